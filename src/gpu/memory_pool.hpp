#pragma once
// Device memory for buffers and images: small buffers share blocks, the rest get an allocation each.
//
// Why: a device may allow as few as 4096 live allocations (maxMemoryAllocationCount, the least Vulkan
// requires; Windows drivers report it), and every object of a scene holds about twenty buffers, most of them
// a few bytes to a few dozen KiB (placeholders, counters, uniforms, a copy's lists on a small model). With
// an allocation a buffer, a crowd of 100 copies of a small model held 2,021 allocations, and about 200
// copies would have passed that limit (a validation error and undefined behaviour, where lavapipe and
// Linux drivers allow 2^32). Shared blocks hold the small ones; the count is checked before every
// allocation, so a scene that still needs more is refused in one line.
#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace stipple::gpu {

// Where a buffer's or image's memory lies: its own allocation (block == kOwn) or a range of a shared block.
struct MemoryRange {
    static constexpr uint32_t kOwn = ~0u;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize offset = 0;
    VkDeviceSize size = 0;   // what is reserved: the allocation's size, or the range (aligned for flushes)
    void* mapped = nullptr;  // the host address of `offset`, where mapped
    uint32_t block = kOwn;
    bool coherent = true;
};

class MemoryPool {
public:
    // Blocks of 2 MiB hold buffers of up to 128 KiB: the tally (and so the memory plans that read it) moves by
    // at most 2 MiB per memory type over what the buffers need, a sixteenth of a block is the most a freed
    // buffer can strand between others, and every small buffer of a copy on the shared models fits.
    static constexpr VkDeviceSize kBlockBytes = VkDeviceSize(2) << 20;
    static constexpr VkDeviceSize kLargestShared = kBlockBytes / 16;

    // `tally` counts the bytes allocated (blocks whole); `max_allocations` the device's limit, lowered by
    // STIPPLE_GPU_ALLOCATION_LIMIT (how a device that allows few would refuse, tried on another).
    MemoryPool(VkDevice device, const VkPhysicalDeviceMemoryProperties& properties, VkDeviceSize non_coherent_atom,
               uint32_t max_allocations, std::atomic<uint64_t>& tally);
    ~MemoryPool();
    MemoryPool(const MemoryPool&) = delete;
    MemoryPool& operator=(const MemoryPool&) = delete;

    // Memory of memory type `type` for `requirements`, host-mapped where `map`; `shareable` lets a small one
    // share a block (buffers; an image gets its own). On failure `range` holds no memory, its size the bytes
    // asked of the driver (a whole block for a small buffer), and the result says why:
    // VK_ERROR_TOO_MANY_OBJECTS where the device's allocations are all taken (failure_message words it).
    VkResult allocate(const VkMemoryRequirements& requirements, uint32_t type, bool map, bool shareable,
                      MemoryRange& range);
    void free(MemoryRange& range);

    // The device's allocations held now (own and blocks), and the most there may be.
    uint32_t allocation_count() const;
    uint32_t max_allocations() const { return max_allocations_; }

    // One line for a failed allocate of `bytes` (the range's size after it: "cannot allocate 2 MiB of GPU memory
    // (VK_ERROR_...)", "cannot map ...", or the allocation limit), `what` naming the thing for which it was.
    std::string failure_message(VkResult result, VkDeviceSize bytes, const std::string& what = "") const;

private:
    struct Block {
        VkDeviceMemory memory = VK_NULL_HANDLE;
        uint32_t type = 0;
        bool mapped = false;
        bool coherent = true;
        void* host = nullptr;
        std::map<VkDeviceSize, VkDeviceSize> free;  // offset -> length, no two touching
        std::multimap<VkDeviceSize, VkDeviceSize> by_length;  // the same ranges, length -> offset
        VkDeviceSize free_bytes = 0;
        void add_range(VkDeviceSize offset, VkDeviceSize length);
        void remove_range(std::map<VkDeviceSize, VkDeviceSize>::iterator range);
    };
    VkResult allocate_memory(VkDeviceSize size, uint32_t type, bool map, VkDeviceMemory& memory, void*& host);
    bool take(Block& block, VkDeviceSize size, VkDeviceSize alignment, VkDeviceSize& offset);

    VkDevice device_;
    VkPhysicalDeviceMemoryProperties properties_;
    VkDeviceSize atom_;
    uint32_t max_allocations_;
    std::atomic<uint64_t>& tally_;
    mutable std::mutex mutex_;  // the viewer stages new stipples on a thread of its own
    std::vector<std::unique_ptr<Block>> blocks_;  // a freed block's slot is empty until reused
    uint32_t allocations_ = 0;
};

}  // namespace stipple::gpu
