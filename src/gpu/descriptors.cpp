#include "gpu/descriptors.hpp"

#include <vector>

#include "core/error.hpp"
#include "gpu/context.hpp"
#include "gpu/vk_check.hpp"

namespace stipple::gpu {

VkDescriptorSetLayout create_set_layout(const Context& context, std::span<const DescriptorBinding> bindings,
                                        VkShaderStageFlags stages) {
    std::vector<VkDescriptorSetLayoutBinding> entries;
    for (const DescriptorBinding& b : bindings) entries.push_back({b.binding, b.type, 1, stages, nullptr});
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    info.bindingCount = uint32_t(entries.size());
    info.pBindings = entries.data();
    VkDescriptorSetLayout layout = VK_NULL_HANDLE;
    VK_CHECK(vkCreateDescriptorSetLayout(context.device, &info, nullptr, &layout));
    return layout;
}

VkPipelineLayout create_pipeline_layout(const Context& context, std::span<const VkDescriptorSetLayout> sets,
                                        uint32_t push_bytes) {
    const VkPushConstantRange push{kPushConstantStages, 0, push_bytes};
    VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    info.setLayoutCount = uint32_t(sets.size());
    info.pSetLayouts = sets.data();
    info.pushConstantRangeCount = push_bytes > 0 ? 1 : 0;
    info.pPushConstantRanges = &push;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VK_CHECK(vkCreatePipelineLayout(context.device, &info, nullptr, &layout));
    return layout;
}

VkBufferView create_texel_view(const Context& context, VkBuffer buffer, VkFormat format) {
    VkBufferViewCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
    info.buffer = buffer;
    info.format = format;
    info.range = VK_WHOLE_SIZE;
    VkBufferView view = VK_NULL_HANDLE;
    VK_CHECK(vkCreateBufferView(context.device, &info, nullptr, &view));
    return view;
}

VkDescriptorPool create_pool(const Context& context, std::span<const DescriptorBinding> bindings, uint32_t sets) {
    std::vector<VkDescriptorPoolSize> sizes;
    for (const DescriptorBinding& b : bindings) {
        bool merged = false;
        for (VkDescriptorPoolSize& size : sizes)
            if (size.type == b.type) size.descriptorCount += sets, merged = true;
        if (!merged) sizes.push_back({b.type, sets});
    }
    VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    info.maxSets = sets;
    info.poolSizeCount = uint32_t(sizes.size());
    info.pPoolSizes = sizes.data();
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VK_CHECK(vkCreateDescriptorPool(context.device, &info, nullptr, &pool));
    return pool;
}

VkDescriptorSet allocate_set(const Context& context, VkDescriptorPool pool, VkDescriptorSetLayout layout) {
    VkDescriptorSetAllocateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    info.descriptorPool = pool;
    info.descriptorSetCount = 1;
    info.pSetLayouts = &layout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    VK_CHECK(vkAllocateDescriptorSets(context.device, &info, &set));
    return set;
}

void write_buffer_set(VkDevice device, VkDescriptorSet set, std::span<const DescriptorBinding> bindings,
                      std::span<const VkBuffer> buffers, std::span<const VkBufferView> views) {
    STIPPLE_CHECK(bindings.size() == buffers.size(), "write_buffer_set: one buffer per binding");
    STIPPLE_CHECK(views.empty() || views.size() == bindings.size(), "write_buffer_set: one view per binding");
    std::vector<VkDescriptorBufferInfo> infos(bindings.size());
    std::vector<VkWriteDescriptorSet> writes(bindings.size());
    for (size_t i = 0; i < bindings.size(); ++i) {
        infos[i] = {buffers[i], 0, VK_WHOLE_SIZE};
        writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[i].dstSet = set;
        writes[i].dstBinding = bindings[i].binding;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = bindings[i].type;
        const bool texels = bindings[i].type == VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER ||
                            bindings[i].type == VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER;
        STIPPLE_CHECK(!texels || (!views.empty() && views[i] != VK_NULL_HANDLE),
                      "write_buffer_set: a texel-buffer binding needs its view");
        if (texels)
            writes[i].pTexelBufferView = &views[i];
        else
            writes[i].pBufferInfo = &infos[i];
    }
    vkUpdateDescriptorSets(device, uint32_t(writes.size()), writes.data(), 0, nullptr);
}

}  // namespace stipple::gpu
