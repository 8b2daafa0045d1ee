#include "gpu/pipelines.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <mutex>
#include <set>

#include "core/error.hpp"
#include "gpu/context.hpp"
#include "gpu/vk_check.hpp"
#include "shared_types.h"

namespace stipple::gpu {

namespace {

// Owns the modules of one pipeline creation (destroyed once the pipeline exists).
struct ShaderModules {
    const Context& context;
    std::vector<VkShaderModule> modules;
    ~ShaderModules() {
        for (VkShaderModule m : modules) vkDestroyShaderModule(context.device, m, nullptr);
    }
    VkShaderModule add(const std::string& name) {
        modules.reserve(modules.size() + 1);  // so that keeping the module cannot throw and lose it
        return modules.emplace_back(load_shader(context, name));
    }
};

struct SpecializationData {
    std::vector<VkSpecializationMapEntry> entries;
    std::vector<uint32_t> values;
    VkSpecializationInfo info{};
    explicit SpecializationData(const Specialization& spec) {
        for (auto [id, value] : spec.constants) {
            entries.push_back({id, uint32_t(values.size() * sizeof(uint32_t)), sizeof(uint32_t)});
            values.push_back(value);
        }
        info.mapEntryCount = uint32_t(entries.size());
        info.pMapEntries = entries.data();
        info.dataSize = values.size() * sizeof(uint32_t);
        info.pData = values.data();
    }
    const VkSpecializationInfo* get() const { return entries.empty() ? nullptr : &info; }
};

}  // namespace

bool format_has_stencil(VkFormat format) {
    return format == VK_FORMAT_D32_SFLOAT_S8_UINT || format == VK_FORMAT_D24_UNORM_S8_UINT ||
           format == VK_FORMAT_D16_UNORM_S8_UINT || format == VK_FORMAT_S8_UINT;
}

std::string shader_path(const std::string& name) {
    const char* env = std::getenv("STIPPLE_SHADER_DIR");
    std::string dir = env ? env : STIPPLE_SHADER_DIR;
    return dir + "/" + name + ".spv";
}

// The SPIR-V execution model of a shader named "<name>.<stage>": Vertex 0, Fragment 4, GLCompute 5 (-1: unknown).
static int execution_model_of(const std::string& name) {
    if (name.ends_with(".vert")) return 0;
    if (name.ends_with(".frag")) return 4;
    if (name.ends_with(".comp")) return 5;
    return -1;
}

// Refuses, naming the file, a module the driver should never see.
static void check_spirv_module(const std::string& path, const std::vector<char>& bytes, int execution_model) {
    // Its instructions must tile the file: a truncated or overwritten module reached the driver (and the
    // validation layer) before, which answered "out of memory" or VkResult(unknown).
    std::vector<uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), bytes.size());
    constexpr uint32_t kSpirvMagic = 0x07230203u;
    if (words.size() < 5 || words[0] != kSpirvMagic) fail_file(path, "not a SPIR-V module (rebuild the project)");
    // A module cut at an instruction's end passes that, and lavapipe crashed on one cut in its decorations:
    // the last instruction must close a function (functions come last in a module), and the entry point and
    // every function called must be defined.
    constexpr uint32_t kOpEntryPoint = 15, kOpFunction = 54, kOpFunctionEnd = 56, kOpFunctionCall = 57;
    std::vector<uint32_t> functions, needed;
    uint32_t last_opcode = 0;
    bool sound = true;
    for (size_t at = 5; at < words.size();) {
        const uint32_t count = words[at] >> 16, opcode = words[at] & 0xFFFFu;
        if (count == 0 || count > words.size() - at) {
            sound = false;
            break;
        }
        if (opcode == kOpFunction && count > 2) functions.push_back(words[at + 2]);
        if (opcode == kOpEntryPoint && count > 2) {
            needed.push_back(words[at + 2]);
            // A module of another stage put in its place (a developer's STIPPLE_SHADER_DIR) crashed lavapipe.
            if (execution_model >= 0 && words[at + 1] != uint32_t(execution_model))
                fail_file(path, "a shader of another stage than its name says (SPIR-V execution model " +
                                    std::to_string(words[at + 1]) + ", expected " + std::to_string(execution_model) + ")");
        }
        if (opcode == kOpFunctionCall && count > 3) needed.push_back(words[at + 3]);
        last_opcode = opcode;
        at += count;
    }
    sound = sound && last_opcode == kOpFunctionEnd &&
            std::all_of(needed.begin(), needed.end(), [&](uint32_t id) {
                return std::find(functions.begin(), functions.end(), id) != functions.end();
            });
    if (!sound) fail_file(path, "a truncated or corrupt SPIR-V module (rebuild the project)");
}

namespace {

// The module's words, refused in one line naming the file where it is missing, not a file, or not a sound
// SPIR-V module of the stage its name says.
std::vector<char> read_shader(const std::string& name) {
    std::string path = shader_path(name);
    // A folder or a pipe in its place threw from deep in the stream or waited forever for a writer.
    std::error_code error;
    if (std::filesystem::exists(path, error) && !std::filesystem::is_regular_file(path, error))
        fail_file(path, "not a file (a SPIR-V module was expected here)");
    std::ifstream file(path, std::ios::binary);
    if (!file) fail_file(path, "shader not found (was the project built? set STIPPLE_SHADER_DIR to move it)");
    std::vector<char> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    if (bytes.empty() || bytes.size() % 4 != 0) fail_file(path, "not a SPIR-V module");
    check_spirv_module(path, bytes, execution_model_of(name));
    return bytes;
}

}  // namespace

void check_shader(const std::string& name) {
    // Once a file for the process: a renderer defines density.comp's nine variants and splat.comp's 24.
    static std::mutex mutex;
    static std::set<std::string> checked;
    const std::string path = shader_path(name);
    {
        std::lock_guard<std::mutex> lock(mutex);
        if (checked.count(path)) return;
    }
    read_shader(name);
    std::lock_guard<std::mutex> lock(mutex);
    checked.insert(path);
}

VkShaderModule load_shader(const Context& context, const std::string& name) {
    const std::vector<char> bytes = read_shader(name);
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = bytes.size();
    info.pCode = reinterpret_cast<const uint32_t*>(bytes.data());
    VkShaderModule module = VK_NULL_HANDLE;
    VK_CHECK(vkCreateShaderModule(context.device, &info, nullptr, &module));
    return module;
}

VkPipeline create_graphics_pipeline(const Context& context, const GraphicsPipelineDesc& desc, VkPipelineLayout layout) {
    ShaderModules modules{context, {}};
    SpecializationData spec(desc.specialization);
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    VkPipelineShaderStageCreateInfo stage{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    stage.stage = VK_SHADER_STAGE_VERTEX_BIT;
    stage.module = modules.add(desc.vertex_shader);
    stage.pName = "main";
    stage.pSpecializationInfo = spec.get();
    stages.push_back(stage);
    if (!desc.fragment_shader.empty()) {
        stage.stage = VK_SHADER_STAGE_FRAGMENT_BIT;
        stage.module = modules.add(desc.fragment_shader);
        stages.push_back(stage);
    }

    VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vertex_input.vertexBindingDescriptionCount = uint32_t(desc.vertex_bindings.size());
    vertex_input.pVertexBindingDescriptions = desc.vertex_bindings.data();
    vertex_input.vertexAttributeDescriptionCount = uint32_t(desc.vertex_attributes.size());
    vertex_input.pVertexAttributeDescriptions = desc.vertex_attributes.data();

    VkPipelineInputAssemblyStateCreateInfo input_assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    input_assembly.topology = desc.topology;

    VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;

    VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    raster.polygonMode = desc.polygon_mode;
    raster.cullMode = desc.cull_mode;
    raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;  // with the negative-height viewport (GL convention)
    raster.depthBiasEnable = desc.depth_bias;
    raster.lineWidth = 1.0f;

    VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;

    VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    depth.depthTestEnable = desc.depth_test;
    depth.depthWriteEnable = desc.depth_write;
    depth.depthCompareOp = desc.depth_compare;
    if (desc.stencil != CoverageStencil::None) {
        depth.stencilTestEnable = VK_TRUE;
        VkStencilOpState op{};
        op.compareMask = 1;
        op.writeMask = 1;
        op.reference = 1;
        if (desc.stencil == CoverageStencil::Write) {
            op.compareOp = VK_COMPARE_OP_ALWAYS;
            op.passOp = VK_STENCIL_OP_REPLACE;  // where the depth test passes: a surface covers the pixel
        } else {
            op.compareOp = VK_COMPARE_OP_EQUAL;
        }
        depth.front = op;
        depth.back = op;
    }

    VkPipelineColorBlendAttachmentState attachment{};
    attachment.colorWriteMask = desc.color_write ? (VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                                    VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT)
                                                 : 0;
    if (desc.blend) {
        attachment.blendEnable = VK_TRUE;
        attachment.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
        attachment.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
        attachment.colorBlendOp = VK_BLEND_OP_ADD;
        attachment.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
        attachment.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
        attachment.alphaBlendOp = VK_BLEND_OP_ADD;
    }
    VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    bool has_color = desc.color_format != VK_FORMAT_UNDEFINED;
    blend.attachmentCount = has_color ? 1 : 0;
    blend.pAttachments = &attachment;

    std::vector<VkDynamicState> dynamic_states{VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    if (desc.depth_bias) dynamic_states.push_back(VK_DYNAMIC_STATE_DEPTH_BIAS);
    if (desc.dynamic_line_width) dynamic_states.push_back(VK_DYNAMIC_STATE_LINE_WIDTH);
    VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dynamic.dynamicStateCount = uint32_t(dynamic_states.size());
    dynamic.pDynamicStates = dynamic_states.data();

    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rendering.colorAttachmentCount = has_color ? 1 : 0;
    rendering.pColorAttachmentFormats = &desc.color_format;
    rendering.depthAttachmentFormat = desc.depth_format;
    if (format_has_stencil(desc.depth_format)) rendering.stencilAttachmentFormat = desc.depth_format;

    VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    info.pNext = &rendering;
    info.stageCount = uint32_t(stages.size());
    info.pStages = stages.data();
    info.pVertexInputState = &vertex_input;
    info.pInputAssemblyState = &input_assembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depth;
    info.pColorBlendState = &blend;
    info.pDynamicState = &dynamic;
    info.layout = layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    VK_CHECK(vkCreateGraphicsPipelines(context.device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
    return pipeline;
}

VkPipeline create_compute_pipeline(const Context& context, const std::string& shader, VkPipelineLayout layout,
                                   const Specialization& specialization) {
    ShaderModules modules{context, {}};
    Specialization with_rows = specialization;
    with_rows.constants.emplace_back(kSpecMaxGroupsX, context.max_groups_x());
    SpecializationData spec(with_rows);
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = modules.add(shader);
    info.stage.pName = "main";
    info.stage.pSpecializationInfo = spec.get();
    info.layout = layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    VK_CHECK(vkCreateComputePipelines(context.device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
    return pipeline;
}

GroupGrid split_groups(uint64_t groups, uint32_t max_x) {
    STIPPLE_CHECK(max_x > 0, "a dispatch row of no workgroups");
    if (groups == 0) return {0, 1};
    const uint64_t x = std::min<uint64_t>(groups, max_x);
    return {uint32_t(x), uint32_t(std::min<uint64_t>((groups + x - 1) / x, UINT32_MAX))};
}

void dispatch_groups(VkCommandBuffer cb, const Context& context, uint64_t groups) {
    const GroupGrid grid = split_groups(groups, context.max_groups_x());
    if (grid.x == 0) return;
    // 65535 rows of 65535 groups of 64 are 2^38 invocations: no buffer a pass walks is that long.
    STIPPLE_CHECK(grid.y <= context.properties.limits.maxComputeWorkGroupCount[1],
                  "a dispatch of " + std::to_string(groups) + " workgroups exceeds this device's limits (or STIPPLE_MAX_WORKGROUPS)");
    vkCmdDispatch(cb, grid.x, grid.y, 1);
}

void LazyPipeline::define_graphics(const Context& context, GraphicsPipelineDesc desc, VkPipelineLayout layout) {
    check_shader(desc.vertex_shader);
    if (!desc.fragment_shader.empty()) check_shader(desc.fragment_shader);
    reset();
    context_ = &context;
    make_ = [&context, desc = std::move(desc), layout] { return create_graphics_pipeline(context, desc, layout); };
}

void LazyPipeline::define_compute(const Context& context, std::string shader, VkPipelineLayout layout,
                                  Specialization specialization) {
    check_shader(shader);
    reset();
    context_ = &context;
    make_ = [&context, shader = std::move(shader), layout, specialization = std::move(specialization)] {
        return create_compute_pipeline(context, shader, layout, specialization);
    };
}

VkPipeline LazyPipeline::get() const {
    STIPPLE_CHECK(make_, "a pipeline was used that was never defined");
    if (!pipeline_) pipeline_ = make_();
    return pipeline_;
}

void LazyPipeline::reset() {
    if (pipeline_) vkDestroyPipeline(context_->device, pipeline_, nullptr);
    pipeline_ = VK_NULL_HANDLE;
}

}  // namespace stipple::gpu
