#pragma once
// Descriptor sets described once: a list of bindings (number and type) from which the set layout, the
// pool sizes and the writes are all made, so the three can never disagree. What each binding means
// belongs to the caller (the renderer's schema, src/render/descriptor_schema.hpp).
#include <span>

#include <vulkan/vulkan.h>

namespace stipple::gpu {

class Context;

struct DescriptorBinding {
    uint32_t binding;
    VkDescriptorType type;
};

// A set layout with every binding visible to `stages`.
VkDescriptorSetLayout create_set_layout(const Context& context, std::span<const DescriptorBinding> bindings,
                                        VkShaderStageFlags stages);

// The stages of every push-constant block create_pipeline_layout makes (vkCmdPushConstants names them all).
inline constexpr VkShaderStageFlags kPushConstantStages =
    VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT;

// A pipeline layout of these sets and one push-constant block of `push_bytes` for every stage.
VkPipelineLayout create_pipeline_layout(const Context& context, std::span<const VkDescriptorSetLayout> sets,
                                        uint32_t push_bytes);

// A pool sized for `sets` sets of these bindings, and one set from it.
VkDescriptorPool create_pool(const Context& context, std::span<const DescriptorBinding> bindings, uint32_t sets);
VkDescriptorSet allocate_set(const Context& context, VkDescriptorPool pool, VkDescriptorSetLayout layout);

// A view of the whole of `buffer` as texels of `format`, for a texel-buffer binding (the caller destroys it).
VkBufferView create_texel_view(const Context& context, VkBuffer buffer, VkFormat format);

// Points every binding at the whole of its buffer (`buffers[i]` for `bindings[i]`), or a texel-buffer
// binding at its view (`views[i]`; `views` may be empty when no binding is a texel buffer).
void write_buffer_set(VkDevice device, VkDescriptorSet set, std::span<const DescriptorBinding> bindings,
                      std::span<const VkBuffer> buffers, std::span<const VkBufferView> views = {});

}  // namespace stipple::gpu
