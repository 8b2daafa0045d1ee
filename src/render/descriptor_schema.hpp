#pragma once
// The renderer's descriptor sets, described once. Set 0 is the object's (every stipple pipeline binds
// it); set 1 is the compute splat's frame buffers. Each table names, per binding of shaders/shared_types.h,
// its type and which buffer it reads, and the set layout, the pool and the writes are all made from it.
#include <span>

#include <vulkan/vulkan.h>

#include "gpu/descriptors.hpp"

namespace stipple {

namespace gpu {
class Context;
}
struct ObjectGpu;

// One binding of the object set: its number and type, and the object's buffer behind it (and for a
// texel buffer, the view of it that the binding holds).
struct ObjectBinding {
    gpu::DescriptorBinding binding;
    VkBuffer (*buffer)(const ObjectGpu& object);
    VkBufferView (*view)(const ObjectGpu& object) = nullptr;
};
std::span<const ObjectBinding> object_bindings();

// The splat's frame set: background, scene depth, colour (shared_types.h, set 1).
std::span<const gpu::DescriptorBinding> splat_frame_bindings();

// Push constants: the splat's (blue-first colour order, paper-only background); 16 bytes for all.
inline constexpr uint32_t kPushConstantBytes = 16;

struct RenderLayouts {
    VkDescriptorSetLayout object_set = VK_NULL_HANDLE;
    VkDescriptorSetLayout splat_frame_set = VK_NULL_HANDLE;
    VkPipelineLayout pipeline = VK_NULL_HANDLE;        // set 0: every graphics and compute pipeline but the splat
    VkPipelineLayout splat_pipeline = VK_NULL_HANDLE;  // sets 0 and 1: the splat
};
RenderLayouts create_render_layouts(const gpu::Context& context);
void destroy_render_layouts(const gpu::Context& context, RenderLayouts& layouts);

// The object's pool and set (one set per object), written from the table.
void create_object_descriptors(const gpu::Context& context, VkDescriptorSetLayout layout, ObjectGpu& object);
// Rewrites the object's set after a buffer was replaced (a path's buffers grew, the edge table was built).
void write_object_descriptors(const ObjectGpu& object);

}  // namespace stipple
