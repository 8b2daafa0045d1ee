#include "anim/gpu_deform.hpp"

#include <algorithm>
#include <span>

#include <glm/gtc/matrix_access.hpp>

#include "anim/deform_layout.hpp"
#include "core/error.hpp"
#include "gpu/context.hpp"
#include "gpu/descriptors.hpp"
#include "gpu/pipelines.hpp"

namespace stipple::anim {

namespace {
constexpr uint32_t kDeformVertexTexels = sizeof(gpu::DeformVertex) / 16;  // RGBA32UI texels a vertex
static_assert(sizeof(gpu::DeformVertex) == 16 * 5);
// The kernel's set, by binding number; the vertices, the morph deltas and the palette are read as texels.
constexpr gpu::DescriptorBinding kDeformBindings[6] = {
    {gpu::kBindingDeformVertices, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER},
    {gpu::kBindingDeformMorphDeltas, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER},
    {gpu::kBindingDeformPalette, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER},
    {gpu::kBindingDeformMorphWeights, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
    {gpu::kBindingDeformPositions, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
    {gpu::kBindingDeformNormals, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
};
static_assert(gpu::kBindingDeformVertices == 0 && gpu::kBindingDeformMorphDeltas == 1 && gpu::kBindingDeformPalette == 2 &&
              gpu::kBindingDeformMorphWeights == 3 && gpu::kBindingDeformPositions == 4 && gpu::kBindingDeformNormals == 5);
}

uint32_t most_used_influences(const AnimatedModel& model) {
    uint32_t most = 1;  // the kernel always reads the first pair
    for (const Influences& inf : model.influences)
        most = std::max(most, static_cast<uint32_t>(std::count_if(inf.weight.begin(), inf.weight.end(),
                                                                  [](float w) { return w != 0.0f; })));
    return most;
}

std::vector<gpu::DeformVertex> pack_deform_vertices(const AnimatedModel& model) {
    std::vector<gpu::DeformVertex> out(model.vertex_count());
    for (size_t v = 0; v < out.size(); ++v) {
        gpu::DeformVertex& d = out[v];
        d.position = model.bind_positions[v];
        d.normal = model.bind_normals[v];
        const MorphRef& morph = model.morph_refs[v];
        d.morph_first = morph.first_delta;
        d.morph_weights = morph.count == 0 ? 0u : (morph.first_weight | morph.count << 16);
        // The used pairs first, in their order (the kernel reads only as many as the model's busiest vertex uses).
        const Influences& inf = model.influences[v];
        uint32_t packed = 0;
        for (uint32_t i = 0; i < kMaxInfluences; ++i) {
            STIPPLE_CHECK(inf.slot[i] < gpu::kDeformMaxPaletteSlots, "palette slot beyond 16 bits");
            if (inf.weight[i] == 0.0f) continue;
            d.slots[packed / 2] |= inf.slot[i] << (16 * (packed % 2));
            (packed < 4 ? d.weights0[packed] : d.weights1[packed - 4]) = inf.weight[i];
            ++packed;
        }
    }
    return out;
}

std::vector<gpu::MorphDelta> pack_morph_deltas(const AnimatedModel& model) {
    std::vector<gpu::MorphDelta> out(model.morph_deltas.size());
    for (size_t i = 0; i < out.size(); ++i)
        out[i] = gpu::MorphDelta{glm::vec4(model.morph_deltas[i].position, 0.0f), glm::vec4(model.morph_deltas[i].normal, 0.0f)};
    return out;
}

namespace {

constexpr VkBufferUsageFlags kOutputUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
constexpr VkDeviceSize kUpdateChunk = 65536;  // vkCmdUpdateBuffer's limit per call

template <class T>
gpu::Buffer upload(const gpu::Context& context, std::vector<T> data, VkBufferUsageFlags usage) {
    if (data.empty()) data.emplace_back();  // a binding needs a buffer, a copy a non-zero size
    return gpu::create_device_buffer(context, std::span<const T>(data), usage);
}

void update(VkCommandBuffer cb, const gpu::Buffer& buffer, const void* data, VkDeviceSize bytes) {
    for (VkDeviceSize offset = 0; offset < bytes; offset += kUpdateChunk)
        vkCmdUpdateBuffer(cb, buffer.handle(), offset, std::min(kUpdateChunk, bytes - offset),
                          static_cast<const char*>(data) + offset);
}

}  // namespace

GpuDeformer::GpuDeformer(const gpu::Context& context, const AnimatedModel& model)
    : context_(context),
      vertex_count_(static_cast<uint32_t>(model.vertex_count())),
      palette_slots_(static_cast<uint32_t>(model.palette.size())),
      morph_weights_(model.morph_weight_count) {
    try {
        // The vertices, the morph deltas and the palette are texel buffers: a software GPU fetches a texel's
        // four words in one gather, where it loads a storage buffer's members one lane at a time (reading the
        // vertices as texels took the bench cylinder's deformation from 6.2-6.4 to 3.4-5.1 ms on a busy
        // machine; docs/animation.md).
        const uint64_t vertex_texels = uint64_t(kDeformVertexTexels) * std::max(vertex_count_, 1u);
        if (vertex_texels > context.properties.limits.maxTexelBufferElements)
            fail("the model's " + std::to_string(vertex_count_) + " skinned vertices exceed the device's texel buffer limit of " +
                 std::to_string(context.properties.limits.maxTexelBufferElements / kDeformVertexTexels));
        vertices_ = upload(context, pack_deform_vertices(model), VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);
        vertices_view_ = gpu::create_texel_view(context, vertices_.handle(), VK_FORMAT_R32G32B32A32_UINT);
        if (2 * model.morph_deltas.size() > context.properties.limits.maxTexelBufferElements)
            fail("the model's " + std::to_string(model.morph_deltas.size()) +
                 " morph deltas exceed the device's texel buffer limit of " +
                 std::to_string(context.properties.limits.maxTexelBufferElements / 2));
        deltas_ = upload(context, pack_morph_deltas(model), VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);
        deltas_view_ = gpu::create_texel_view(context, deltas_.handle(), VK_FORMAT_R32G32B32A32_SFLOAT);
        const VkBufferUsageFlags per_frame = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
        const uint64_t palette_texels = 3ull * std::max(palette_slots_, 1u);
        if (palette_texels > context.properties.limits.maxTexelBufferElements)
            fail("the model's " + std::to_string(palette_slots_) + " palette matrices exceed the device's texel buffer limit of " +
                 std::to_string(context.properties.limits.maxTexelBufferElements / 3));
        palette_ = gpu::Buffer(context, palette_texels * sizeof(glm::vec4),
                               VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::DeviceLocal);
        palette_view_ = gpu::create_texel_view(context, palette_.handle(), VK_FORMAT_R32G32B32A32_SFLOAT);
        weights_ = gpu::Buffer(context, std::max(morph_weights_, 1u) * sizeof(float), per_frame, gpu::MemoryUse::DeviceLocal);
        const VkDeviceSize output_bytes = std::max(vertex_count_, 1u) * 3 * sizeof(float);
        positions_ = gpu::Buffer(context, output_bytes, kOutputUsage, gpu::MemoryUse::DeviceLocal);
        normals_ = gpu::Buffer(context, output_bytes, kOutputUsage, gpu::MemoryUse::DeviceLocal);

        set_layout_ = gpu::create_set_layout(context, kDeformBindings, VK_SHADER_STAGE_COMPUTE_BIT);
        pipeline_layout_ = gpu::create_pipeline_layout(context, {&set_layout_, 1}, sizeof(gpu::DeformPush));
        gpu::Specialization influences;
        influences.constants.push_back({gpu::kSpecDeformInfluences, most_used_influences(model)});
        pipeline_ = gpu::create_compute_pipeline(context, "deform.comp", pipeline_layout_, influences);

        pool_ = gpu::create_pool(context, kDeformBindings, 1);
        set_ = gpu::allocate_set(context, pool_, set_layout_);
        write_descriptors(positions_.handle(), normals_.handle());
    } catch (...) {
        release();
        throw;
    }
}

GpuDeformer::~GpuDeformer() { release(); }

void GpuDeformer::release() {
    const VkDevice device = context_.device;
    if (pool_) vkDestroyDescriptorPool(device, pool_, nullptr);
    if (palette_view_) vkDestroyBufferView(device, palette_view_, nullptr);
    if (vertices_view_) vkDestroyBufferView(device, vertices_view_, nullptr);
    if (deltas_view_) vkDestroyBufferView(device, deltas_view_, nullptr);
    if (pipeline_) vkDestroyPipeline(device, pipeline_, nullptr);
    if (pipeline_layout_) vkDestroyPipelineLayout(device, pipeline_layout_, nullptr);
    if (set_layout_) vkDestroyDescriptorSetLayout(device, set_layout_, nullptr);
}

void GpuDeformer::set_outputs(VkBuffer positions, VkBuffer normals) { write_descriptors(positions, normals); }

void GpuDeformer::write_descriptors(VkBuffer positions, VkBuffer normals) {
    const VkBuffer buffers[6] = {vertices_.handle(), deltas_.handle(), palette_.handle(), weights_.handle(), positions, normals};
    VkDescriptorBufferInfo infos[6];
    VkWriteDescriptorSet writes[6];
    for (uint32_t b = 0; b < 6; ++b) {
        infos[b] = {buffers[b], 0, VK_WHOLE_SIZE};
        writes[b] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[b].dstSet = set_;
        writes[b].dstBinding = b;
        writes[b].descriptorCount = 1;
        writes[b].descriptorType = kDeformBindings[b].type;
        if (b == gpu::kBindingDeformPalette)
            writes[b].pTexelBufferView = &palette_view_;
        else if (b == gpu::kBindingDeformVertices)
            writes[b].pTexelBufferView = &vertices_view_;
        else if (b == gpu::kBindingDeformMorphDeltas)
            writes[b].pTexelBufferView = &deltas_view_;
        else
            writes[b].pBufferInfo = &infos[b];
    }
    vkUpdateDescriptorSets(context_.device, 6, writes, 0, nullptr);
}

void GpuDeformer::record(VkCommandBuffer cb, const Pose& pose) {
    STIPPLE_CHECK(pose.palette.size() == palette_slots_ && pose.morph_weights.size() == morph_weights_,
                  "the pose is not of the deformer's model");
    // The previous dispatch's reads of the palette (texels) and weights come before this frame's writes.
    gpu::memory_barrier(cb, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_READ_BIT,
                        VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    // Each slot's top three rows (the kernel's layout; the fourth row of an affine matrix is 0 0 0 1).
    palette_rows_.resize(3 * pose.palette.size());
    for (size_t s = 0; s < pose.palette.size(); ++s)
        for (int r = 0; r < 3; ++r) palette_rows_[3 * s + r] = glm::row(pose.palette[s], r);
    update(cb, palette_, palette_rows_.data(), palette_rows_.size() * sizeof(glm::vec4));
    update(cb, weights_, pose.morph_weights.data(), pose.morph_weights.size() * sizeof(float));
    // Shader reads of both kinds: the palette's texels (sampled) and the weights (storage).
    gpu::memory_barrier(cb, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_READ_BIT);
    // Whatever read the outputs last frame (vertex input, shaders) finishes before they are rewritten.
    gpu::memory_barrier(cb, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT,
                        VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout_, 0, 1, &set_, 0, nullptr);
    const gpu::DeformPush push{vertex_count_, 0, 0, 0};
    vkCmdPushConstants(cb, pipeline_layout_, gpu::kPushConstantStages, 0, sizeof push, &push);
    gpu::dispatch_items(cb, context_, vertex_count_, gpu::kDeformWorkgroupSize);
}

}  // namespace stipple::anim
