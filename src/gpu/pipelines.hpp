#pragma once
// Shader modules loaded by name and pipelines described by plain structs (dynamic rendering).
#include <functional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace stipple::gpu {

class Context;

// Reads <shader dir>/<name>.spv, e.g. load_shader(ctx, "stipple.vert"). The shader dir is the build's
// (compiled in) unless STIPPLE_SHADER_DIR is set in the environment.
VkShaderModule load_shader(const Context& context, const std::string& name);
// The checks load_shader makes, without a device: a broken install is told where a pipeline is defined.
void check_shader(const std::string& name);
std::string shader_path(const std::string& name);

// Specialisation constants: (constant_id, 32-bit value) pairs; variants without copied files.
struct Specialization {
    std::vector<std::pair<uint32_t, uint32_t>> constants;
};

// The stencil marks the pixels a surface covers: the depth pass writes it, the stipple pass tests it,
// so that no stipple (a point wider than a pixel) ever inks the paper beside the object.
enum class CoverageStencil { None, Write, Test };

bool format_has_stencil(VkFormat format);

struct GraphicsPipelineDesc {
    std::string vertex_shader;    // shader name, e.g. "stipple.vert"
    std::string fragment_shader;  // empty: depth-only
    Specialization specialization;
    VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    std::vector<VkVertexInputBindingDescription> vertex_bindings;
    std::vector<VkVertexInputAttributeDescription> vertex_attributes;
    VkPolygonMode polygon_mode = VK_POLYGON_MODE_FILL;
    VkCullModeFlags cull_mode = VK_CULL_MODE_NONE;
    bool depth_test = true;
    bool depth_write = true;
    VkCompareOp depth_compare = VK_COMPARE_OP_LESS;
    bool depth_bias = false;  // values set dynamically (vkCmdSetDepthBias)
    CoverageStencil stencil = CoverageStencil::None;
    bool blend = false;       // premultiplied-free "over": src alpha, one minus src alpha
    bool color_write = true;
    bool dynamic_line_width = false;
    VkFormat color_format = VK_FORMAT_UNDEFINED;
    VkFormat depth_format = VK_FORMAT_UNDEFINED;
};

VkPipeline create_graphics_pipeline(const Context& context, const GraphicsPipelineDesc& desc, VkPipelineLayout layout);
// Every compute pipeline also gets kSpecMaxGroupsX (shaders/dispatch.h) from the context.
VkPipeline create_compute_pipeline(const Context& context, const std::string& shader, VkPipelineLayout layout,
                                   const Specialization& specialization = {});

// A pipeline made when a frame first binds it. A renderer holds every variant of every density path, line
// kind and depth pass, and a run binds a few of them: made up front, the default render made 39 pipelines
// and bound 7, and their compilation was 0.8 s of its 1.15 s on lavapipe (SVG output: 75 made, 1.9 s).
// Its shaders are checked when it is defined (check_shader), so a missing or broken one is still reported
// before any frame, not in the middle of a sequence or a viewer session.
class LazyPipeline {
public:
    LazyPipeline() = default;
    ~LazyPipeline() { reset(); }
    LazyPipeline(const LazyPipeline&) = delete;
    LazyPipeline& operator=(const LazyPipeline&) = delete;

    void define_graphics(const Context& context, GraphicsPipelineDesc desc, VkPipelineLayout layout);
    void define_compute(const Context& context, std::string shader, VkPipelineLayout layout,
                        Specialization specialization = {});
    // The pipeline, made on the first call (a cache of the definition: const as reading it is).
    VkPipeline get() const;
    void reset();  // destroys it if made; the definition stays

private:
    const Context* context_ = nullptr;
    std::function<VkPipeline()> make_;
    mutable VkPipeline pipeline_ = VK_NULL_HANDLE;
};

// A dispatch of `groups` workgroups, in rows of at most context.max_groups_x() along y (the shaders number
// their invocations with dispatch.h's linear_invocation and return past their work).
struct GroupGrid {
    uint32_t x = 0, y = 1;
};
GroupGrid split_groups(uint64_t groups, uint32_t max_x);
void dispatch_groups(VkCommandBuffer cb, const Context& context, uint64_t groups);
// The groups of group_size invocations that cover `items`, dispatched as above.
inline void dispatch_items(VkCommandBuffer cb, const Context& context, uint64_t items, uint32_t group_size) {
    dispatch_groups(cb, context, (items + group_size - 1) / group_size);
}

}  // namespace stipple::gpu
