#include "gpu/resources.hpp"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <utility>

#include "gpu/context.hpp"
#include "gpu/vk_check.hpp"

namespace stipple::gpu {

namespace {

VkMemoryPropertyFlags required_flags(MemoryUse use) {
    switch (use) {
        case MemoryUse::DeviceLocal: return 0;  // preferred DEVICE_LOCAL, below; CPU drivers have only host memory
        case MemoryUse::Upload:
        case MemoryUse::Readback: return VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT;
    }
    return 0;
}

VkMemoryPropertyFlags preferred_flags(MemoryUse use) {
    switch (use) {
        case MemoryUse::DeviceLocal: return VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
        case MemoryUse::Upload: return VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
        case MemoryUse::Readback: return VK_MEMORY_PROPERTY_HOST_CACHED_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    }
    return 0;
}

VkImage create_image_2d(VkDevice device, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                        VkImageTiling tiling) {
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {extent.width, extent.height, 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = tiling;
    info.usage = usage;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImage image = VK_NULL_HANDLE;
    VK_CHECK(vkCreateImage(device, &info, nullptr, &image));
    return image;
}

VkImageView create_view_2d(VkDevice device, VkImage image, VkFormat format, VkImageAspectFlags aspect) {
    VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    info.image = image;
    info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    info.format = format;
    info.subresourceRange = {aspect, 0, 1, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    VK_CHECK(vkCreateImageView(device, &info, nullptr, &view));
    return view;
}

}  // namespace

Buffer::Buffer(const Context& context, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use)
    : device_(context.device), size_(size) {
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size > 0 ? size : 4;  // zero-sized buffers are invalid; an empty object still binds one
    // Device-local buffers can always be copied from, so tests and tools can read any of them back.
    info.usage = use == MemoryUse::DeviceLocal ? usage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT : usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VK_CHECK(vkCreateBuffer(device_, &info, nullptr, &buffer_));

    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device_, buffer_, &requirements);
    const uint32_t type = context.find_memory_type(requirements.memoryTypeBits, required_flags(use), preferred_flags(use));
    MemoryPool& pool = context.memory_pool();
    pool_ = &pool;
    if (const VkResult result = pool.allocate(requirements, type, use != MemoryUse::DeviceLocal, true, memory_);
        result != VK_SUCCESS) {
        const VkDeviceSize asked = memory_.size;
        memory_ = MemoryRange();
        reset();  // the buffer made above, not leaked
        fail(pool.failure_message(result, asked));
    }
    VK_CHECK(vkBindBufferMemory(device_, buffer_, memory_.memory, memory_.offset));
}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
    if (this != &other) {
        reset();
        device_ = std::exchange(other.device_, VK_NULL_HANDLE);
        buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
        size_ = std::exchange(other.size_, 0);
        pool_ = std::exchange(other.pool_, nullptr);
        memory_ = std::exchange(other.memory_, MemoryRange());
    }
    return *this;
}

void Buffer::reset() {
    if (!device_) return;
    if (buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
    if (pool_) pool_->free(memory_);
    buffer_ = VK_NULL_HANDLE;
    pool_ = nullptr;
    device_ = VK_NULL_HANDLE;
}

// A range of a shared block is flushed alone (its offset and size are whole atoms: MemoryPool::allocate).
void Buffer::flush() const {
    if (memory_.coherent || !memory_.mapped) return;
    const VkDeviceSize size = memory_.block == MemoryRange::kOwn ? VK_WHOLE_SIZE : memory_.size;
    VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE, nullptr, memory_.memory, memory_.offset, size};
    VK_CHECK(vkFlushMappedMemoryRanges(device_, 1, &range));
}

void Buffer::invalidate() const {
    if (memory_.coherent || !memory_.mapped) return;
    const VkDeviceSize size = memory_.block == MemoryRange::kOwn ? VK_WHOLE_SIZE : memory_.size;
    VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE, nullptr, memory_.memory, memory_.offset, size};
    VK_CHECK(vkInvalidateMappedMemoryRanges(device_, 1, &range));
}

Image::Image(const Context& context, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
             VkImageAspectFlags aspect)
    : device_(context.device), format_(format), extent_(extent), aspect_(aspect) {
    image_ = create_image_2d(device_, extent, format, usage, VK_IMAGE_TILING_OPTIMAL);

    VkMemoryRequirements requirements;
    vkGetImageMemoryRequirements(device_, image_, &requirements);
    const uint32_t type = context.find_memory_type(requirements.memoryTypeBits, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    MemoryPool& pool = context.memory_pool();
    pool_ = &pool;
    if (const VkResult result = pool.allocate(requirements, type, false, false, memory_); result != VK_SUCCESS) {
        memory_ = MemoryRange();
        reset();  // the image made above, not leaked
        fail(pool.failure_message(result, requirements.size,
                                    "a " + std::to_string(extent.width) + "x" + std::to_string(extent.height) + " image"));
    }
    VK_CHECK(vkBindImageMemory(device_, image_, memory_.memory, 0));
    view_ = create_view_2d(device_, image_, format, aspect);
}

Image Image::linear_with_words(const Context& context, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                               bool host_mapped) {
    // What the caller gets where this image cannot be: an ordinary one, or none (host_mapped).
    auto instead = [&] { return host_mapped ? Image() : Image(context, extent, format, usage, VK_IMAGE_ASPECT_COLOR_BIT); };
    VkFormatProperties properties;
    vkGetPhysicalDeviceFormatProperties(context.physical_device, format, &properties);
    const VkFormatFeatureFlags needed = VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_TRANSFER_SRC_BIT |
                                        VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
    if ((properties.linearTilingFeatures & needed) != needed) return instead();

    Image image;
    image.device_ = context.device;
    image.format_ = format;
    image.extent_ = extent;
    image.aspect_ = VK_IMAGE_ASPECT_COLOR_BIT;
    image.image_ = create_image_2d(image.device_, extent, format, usage, VK_IMAGE_TILING_LINEAR);
    VkImageSubresource pixels{VK_IMAGE_ASPECT_COLOR_BIT, 0, 0};
    VkSubresourceLayout layout;
    vkGetImageSubresourceLayout(image.device_, image.image_, &pixels, &layout);
    const VkDeviceSize row = VkDeviceSize(extent.width) * 4;
    const bool words = layout.offset == 0 && layout.rowPitch == row;  // rows padded: no words
    if (!words && !host_mapped) return instead();
    image.row_pitch_ = layout.rowPitch;
    image.pixels_offset_ = layout.offset;

    VkMemoryRequirements for_image, for_words{};
    vkGetImageMemoryRequirements(image.device_, image.image_, &for_image);
    for_words.memoryTypeBits = ~0u;
    if (words) {
        VkBufferCreateInfo buffer_info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
        buffer_info.size = row * extent.height;
        buffer_info.usage =
            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
        buffer_info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
        VK_CHECK(vkCreateBuffer(image.device_, &buffer_info, nullptr, &image.words_));
        vkGetBufferMemoryRequirements(image.device_, image.words_, &for_words);
    }
    uint32_t types = for_image.memoryTypeBits & for_words.memoryTypeBits;
    const VkMemoryPropertyFlags host = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    if (host_mapped)
        for (uint32_t i = 0; i < context.memory_properties.memoryTypeCount; ++i)
            if ((context.memory_properties.memoryTypes[i].propertyFlags & host) != host) types &= ~(1u << i);
    if (types == 0) return instead();
    VkMemoryRequirements both = for_image;
    both.size = std::max(for_image.size, for_words.size);
    both.alignment = std::max(for_image.alignment, for_words.alignment);
    const uint32_t type = context.find_memory_type(types, host_mapped ? host : 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    image.pool_ = &context.memory_pool();
    if (const VkResult result = image.pool_->allocate(both, type, host_mapped, false, image.memory_); result != VK_SUCCESS) {
        image.memory_ = MemoryRange();
        fail(image.pool_->failure_message(result, both.size, "a " + std::to_string(extent.width) + "x" +
                                                                 std::to_string(extent.height) + " image"));
    }
    VK_CHECK(vkBindImageMemory(image.device_, image.image_, image.memory_.memory, 0));
    if (words) {
        VK_CHECK(vkBindBufferMemory(image.device_, image.words_, image.memory_.memory, 0));
        static std::atomic<uint64_t> next_serial{1};
        image.words_serial_ = next_serial++;
    }
    image.view_ = create_view_2d(image.device_, image.image_, format, VK_IMAGE_ASPECT_COLOR_BIT);
    return image;
}

Image& Image::operator=(Image&& other) noexcept {
    if (this != &other) {
        reset();
        device_ = std::exchange(other.device_, VK_NULL_HANDLE);
        image_ = std::exchange(other.image_, VK_NULL_HANDLE);
        view_ = std::exchange(other.view_, VK_NULL_HANDLE);
        pool_ = std::exchange(other.pool_, nullptr);
        memory_ = std::exchange(other.memory_, MemoryRange());
        words_ = std::exchange(other.words_, VK_NULL_HANDLE);
        row_pitch_ = other.row_pitch_;
        words_serial_ = std::exchange(other.words_serial_, 0);
        pixels_offset_ = other.pixels_offset_;
        format_ = other.format_;
        extent_ = other.extent_;
        aspect_ = other.aspect_;
    }
    return *this;
}

void Image::reset() {
    if (!device_) return;
    if (view_) vkDestroyImageView(device_, view_, nullptr);
    if (words_) vkDestroyBuffer(device_, words_, nullptr);
    if (image_) vkDestroyImage(device_, image_, nullptr);
    if (pool_) pool_->free(memory_);  // unmaps implicitly
    view_ = VK_NULL_HANDLE;
    words_ = VK_NULL_HANDLE;
    image_ = VK_NULL_HANDLE;
    pool_ = nullptr;
    device_ = VK_NULL_HANDLE;
}

Buffer create_device_buffer(const Context& context, std::span<const std::byte> data, VkBufferUsageFlags usage) {
    const StagedBuffer staged = stage_buffer(context, data, usage);
    return std::move(upload_staged(context, std::span(&staged, 1)).front());
}

StagedBuffer stage_buffer(const Context& context, std::span<const std::byte> data, VkBufferUsageFlags usage) {
    StagedBuffer staged;
    staged.size = data.size();
    staged.usage = usage;
    if (data.empty()) return staged;
    staged.staging = Buffer(context, data.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::Upload);
    if (!data.empty()) std::memcpy(staged.staging.mapped(), data.data(), data.size());
    staged.staging.flush();
    return staged;
}

std::vector<Buffer> upload_staged(const Context& context, std::span<const StagedBuffer> staged) {
    std::vector<Buffer> buffers;
    buffers.reserve(staged.size());
    VkCommandBuffer cb = VK_NULL_HANDLE;
    for (const StagedBuffer& s : staged) {
        buffers.emplace_back(context, s.size, s.usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::DeviceLocal);
        if (s.size == 0) continue;
        if (!cb) cb = context.begin_one_shot();
        const VkBufferCopy region{0, 0, s.size};
        vkCmdCopyBuffer(cb, s.staging.handle(), buffers.back().handle(), 1, &region);
    }
    if (cb) context.submit_and_wait(cb);
    return buffers;
}

std::vector<std::byte> read_buffer(const Context& context, const Buffer& buffer, VkDeviceSize size) {
    std::vector<std::byte> bytes(std::min(size, buffer.size()));
    if (bytes.empty()) return bytes;
    Buffer staging(context, bytes.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Readback);
    VkCommandBuffer cb = context.begin_one_shot();
    VkBufferCopy region{0, 0, bytes.size()};
    vkCmdCopyBuffer(cb, buffer.handle(), staging.handle(), 1, &region);
    buffer_barrier(cb, staging.handle(), VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                   VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    context.submit_and_wait(cb);
    staging.invalidate();
    if (!bytes.empty()) std::memcpy(bytes.data(), staging.mapped(), bytes.size());
    return bytes;
}

namespace {

void record_image_barrier(VkCommandBuffer cb, VkImage image, VkImageAspectFlags aspect, VkImageLayout from,
                          VkImageLayout to, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                          VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access, bool aliased) {
    VkImageMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    barrier.srcStageMask = src_stage;
    barrier.srcAccessMask = src_access;
    barrier.dstStageMask = dst_stage;
    barrier.dstAccessMask = dst_access;
    barrier.oldLayout = from;
    barrier.newLayout = to;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = {aspect, 0, 1, 0, 1};
    VkMemoryBarrier2 memory{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    memory.srcStageMask = src_stage;
    memory.srcAccessMask = src_access;
    memory.dstStageMask = dst_stage;
    memory.dstAccessMask = dst_access;
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.imageMemoryBarrierCount = 1;
    dependency.pImageMemoryBarriers = &barrier;
    dependency.memoryBarrierCount = aliased ? 1 : 0;
    dependency.pMemoryBarriers = aliased ? &memory : nullptr;
    vkCmdPipelineBarrier2(cb, &dependency);
}

}  // namespace

void image_barrier(VkCommandBuffer cb, VkImage image, VkImageAspectFlags aspect, VkImageLayout from,
                   VkImageLayout to, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                   VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access) {
    record_image_barrier(cb, image, aspect, from, to, src_stage, src_access, dst_stage, dst_access, false);
}

void aliased_image_barrier(VkCommandBuffer cb, VkImage image, VkImageAspectFlags aspect, VkImageLayout from,
                           VkImageLayout to, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                           VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access) {
    record_image_barrier(cb, image, aspect, from, to, src_stage, src_access, dst_stage, dst_access, true);
}

void memory_barrier(VkCommandBuffer cb, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                    VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access) {
    VkMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    barrier.srcStageMask = src_stage;
    barrier.srcAccessMask = src_access;
    barrier.dstStageMask = dst_stage;
    barrier.dstAccessMask = dst_access;
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.memoryBarrierCount = 1;
    dependency.pMemoryBarriers = &barrier;
    vkCmdPipelineBarrier2(cb, &dependency);
}

void buffer_barrier(VkCommandBuffer cb, VkBuffer buffer, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                    VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access) {
    VkBufferMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
    barrier.srcStageMask = src_stage;
    barrier.srcAccessMask = src_access;
    barrier.dstStageMask = dst_stage;
    barrier.dstAccessMask = dst_access;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.buffer = buffer;
    barrier.offset = 0;
    barrier.size = VK_WHOLE_SIZE;
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.bufferMemoryBarrierCount = 1;
    dependency.pBufferMemoryBarriers = &barrier;
    vkCmdPipelineBarrier2(cb, &dependency);
}

}  // namespace stipple::gpu
