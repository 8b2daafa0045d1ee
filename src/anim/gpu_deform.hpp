#pragma once
// The deformation pass on the GPU (shaders/deform.comp): a model's vertices, influences and morph
// deltas uploaded once; per frame the pose's palette and morph weights go into the command buffer
// itself (vkCmdUpdateBuffer), so a frame in flight never sees the next frame's pose, then one dispatch
// writes deformed positions and normals (3 floats per vertex, the layout of kBindingMeshPositions).
#include <vector>

#include <vulkan/vulkan.h>

#include "anim/animated_model.hpp"
#include "anim/pose.hpp"
#include "deform_types.h"
#include "gpu/resources.hpp"

namespace stipple::gpu {
class Context;
}

namespace stipple::anim {

// The kernel's per-vertex records for a model (what GpuDeformer uploads): each vertex's used influence
// pairs (weight not 0) first.
std::vector<gpu::DeformVertex> pack_deform_vertices(const AnimatedModel& model);
// The most used influence pairs of any vertex (at least 1): the kernel's kSpecDeformInfluences.
uint32_t most_used_influences(const AnimatedModel& model);
std::vector<gpu::MorphDelta> pack_morph_deltas(const AnimatedModel& model);

class GpuDeformer {
public:
    GpuDeformer(const gpu::Context& context, const AnimatedModel& model);
    ~GpuDeformer();
    GpuDeformer(const GpuDeformer&) = delete;
    GpuDeformer& operator=(const GpuDeformer&) = delete;

    // Its own outputs (storage, vertex and transfer-source usage), 12 bytes per vertex each.
    const gpu::Buffer& positions() const { return positions_; }
    const gpu::Buffer& normals() const { return normals_; }
    // Writes into other buffers instead, e.g. the renderer's mesh positions (each needs storage usage
    // and 12 bytes per vertex). Not while a recorded dispatch is pending.
    void set_outputs(VkBuffer positions, VkBuffer normals);

    // Records the pose's upload and the dispatch (outside a render pass). Orders itself after earlier
    // reads of its inputs and outputs; the caller orders later readers after its compute-shader writes.
    void record(VkCommandBuffer cb, const Pose& pose);

    uint32_t vertex_count() const { return vertex_count_; }

private:
    // What the constructor made, destroyed; also when it throws midway (a destructor does not run then).
    void release();
    void write_descriptors(VkBuffer positions, VkBuffer normals);

    const gpu::Context& context_;
    uint32_t vertex_count_ = 0;
    uint32_t palette_slots_ = 0;
    uint32_t morph_weights_ = 0;
    gpu::Buffer vertices_, deltas_, palette_, weights_, positions_, normals_;
    std::vector<glm::vec4> palette_rows_;  // this frame's palette as the kernel reads it (kept: no allocation a frame)
    VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
    VkPipelineLayout pipeline_layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    VkBufferView palette_view_ = VK_NULL_HANDLE;  // the palette's texels (RGBA32F, three per slot)
    VkBufferView vertices_view_ = VK_NULL_HANDLE;  // the DeformVertex[]'s texels (RGBA32UI, five per vertex)
    VkBufferView deltas_view_ = VK_NULL_HANDLE;    // the MorphDelta[]'s texels (RGBA32F, two per delta)
};

}  // namespace stipple::anim
