#pragma once
// Buffers and images with their memory: small move-only owners, so nothing leaks when an error
// unwinds (a leak would be a validation message at device destruction).
#include <atomic>
#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/memory_pool.hpp"

namespace stipple::gpu {

class Context;

enum class MemoryUse {
    DeviceLocal,  // GPU-only data (stipples, per-frame densities, depth)
    Upload,       // host-visible, written by the CPU (uniforms, staging)
    Readback,     // host-visible and cached, read by the CPU (images, counters)
};

class Buffer {
public:
    Buffer() = default;
    Buffer(const Context& context, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use);
    ~Buffer() { reset(); }
    Buffer(Buffer&& other) noexcept { *this = std::move(other); }
    Buffer& operator=(Buffer&& other) noexcept;
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;

    void reset();
    VkBuffer handle() const { return buffer_; }
    VkDeviceSize size() const { return size_; }
    void* mapped() const { return memory_.mapped; }  // non-null for Upload and Readback
    explicit operator bool() const { return buffer_ != VK_NULL_HANDLE; }

    // Makes host writes visible / device writes readable on non-coherent memory.
    void flush() const;
    void invalidate() const;

private:
    VkDevice device_ = VK_NULL_HANDLE;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    VkDeviceSize size_ = 0;
    MemoryPool* pool_ = nullptr;
    MemoryRange memory_;  // its own allocation, or a range of a block shared with other small buffers
};

class Image {
public:
    Image() = default;
    Image(const Context& context, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
          VkImageAspectFlags aspect);
    ~Image() { reset(); }
    Image(Image&& other) noexcept { *this = std::move(other); }
    Image& operator=(Image&& other) noexcept;
    Image(const Image&) = delete;
    Image& operator=(const Image&) = delete;

    // A colour image in linear tiling whose memory is also a buffer of its pixels' 4-byte words, row after
    // row (words(), with STORAGE and TRANSFER usage): a compute pass then writes the image's pixels with no
    // copy. Where the device cannot (the format is no linear colour attachment, or the rows are padded),
    // an ordinary image without words. Between writes through the words and uses of the image, the image
    // is in the GENERAL layout: a linear image's memory holds its pixels as laid out only there.
    // host_mapped: in host-visible, coherent memory, mapped for the image's life (mapped(), row_pitch()),
    // with words where its rows are not padded; where the device has no such image, an empty Image.
    static Image linear_with_words(const Context& context, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                                   bool host_mapped = false);

    void reset();
    VkImage handle() const { return image_; }
    VkImageView view() const { return view_; }
    VkBuffer words() const { return words_; }
    // Names words() for the image's life, process-wide (RenderTargets::color_words_serial); 0 without words.
    uint64_t words_serial() const { return words_serial_; }
    // linear_with_words(..., host_mapped): the pixels, rows row_pitch() bytes apart.
    const void* mapped() const { return memory_.mapped ? static_cast<const char*>(memory_.mapped) + pixels_offset_ : nullptr; }
    VkDeviceSize row_pitch() const { return row_pitch_; }
    VkFormat format() const { return format_; }
    VkExtent2D extent() const { return extent_; }
    VkImageAspectFlags aspect() const { return aspect_; }

private:
    VkDevice device_ = VK_NULL_HANDLE;
    VkImage image_ = VK_NULL_HANDLE;
    VkImageView view_ = VK_NULL_HANDLE;
    MemoryPool* pool_ = nullptr;
    MemoryRange memory_;  // always its own allocation
    VkBuffer words_ = VK_NULL_HANDLE;
    VkDeviceSize row_pitch_ = 0, pixels_offset_ = 0;
    uint64_t words_serial_ = 0;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    VkExtent2D extent_{};
    VkImageAspectFlags aspect_ = 0;
};

// A device-local buffer filled once from host data through a staging buffer (waits for completion).
Buffer create_device_buffer(const Context& context, std::span<const std::byte> data, VkBufferUsageFlags usage);

// Host data already in a staging buffer, waiting to become a device-local buffer. Staging uses no queue
// and no command pool, so it may run on any thread (the viewer stages new stipples in the background);
// upload_staged then needs the thread that submits.
struct StagedBuffer {
    Buffer staging;
    VkDeviceSize size = 0;
    VkBufferUsageFlags usage = 0;
};
StagedBuffer stage_buffer(const Context& context, std::span<const std::byte> data, VkBufferUsageFlags usage);
template <typename T>
StagedBuffer stage_buffer(const Context& context, std::span<const T> data, VkBufferUsageFlags usage) {
    return stage_buffer(context, std::as_bytes(data), usage);
}
// Device-local buffers of the staged data, all copied in one submission (waits for completion).
std::vector<Buffer> upload_staged(const Context& context, std::span<const StagedBuffer> staged);

template <typename T>
Buffer create_device_buffer(const Context& context, std::span<const T> data, VkBufferUsageFlags usage) {
    return create_device_buffer(context, std::as_bytes(data), usage);
}

// Copies a buffer's contents back to the host (waits), or its first `bytes`. The buffer needs TRANSFER_SRC usage.
std::vector<std::byte> read_buffer(const Context& context, const Buffer& buffer, VkDeviceSize bytes = VK_WHOLE_SIZE);

// Image layout transition with a full pipeline barrier between the two stages (synchronization2).
void image_barrier(VkCommandBuffer cb, VkImage image, VkImageAspectFlags aspect, VkImageLayout from,
                   VkImageLayout to, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                   VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access);
// The same, with a global memory barrier of the same scopes in the same dependency: for an image whose
// memory a buffer also reaches (Image::linear_with_words), since an image barrier's access scopes cover
// accesses to the image alone, and two barriers recorded apart would not order the buffer's accesses
// around the layout change.
void aliased_image_barrier(VkCommandBuffer cb, VkImage image, VkImageAspectFlags aspect, VkImageLayout from,
                           VkImageLayout to, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                           VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access);

// A global memory dependency (cheaper to write than one barrier per buffer).
void memory_barrier(VkCommandBuffer cb, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                    VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access);

void buffer_barrier(VkCommandBuffer cb, VkBuffer buffer, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                    VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access);

}  // namespace stipple::gpu
