#include "gpu/memory_pool.hpp"

#include <algorithm>

#include "gpu/vk_check.hpp"

namespace stipple::gpu {

namespace {

VkDeviceSize align_up(VkDeviceSize value, VkDeviceSize alignment) {
    return alignment > 1 ? (value + alignment - 1) / alignment * alignment : value;
}

}  // namespace

MemoryPool::MemoryPool(VkDevice device, const VkPhysicalDeviceMemoryProperties& properties,
                       VkDeviceSize non_coherent_atom, uint32_t max_allocations, std::atomic<uint64_t>& tally)
    : device_(device), properties_(properties), atom_(std::max<VkDeviceSize>(non_coherent_atom, 1)),
      max_allocations_(std::max(max_allocations, 1u)), tally_(tally) {}

MemoryPool::~MemoryPool() {
    // Every buffer is gone by now, and with it every block (freed when its last range is); what is left
    // would be a leak, which the validation layer names at the device's end: freed here all the same.
    for (const std::unique_ptr<Block>& block : blocks_)
        if (block) vkFreeMemory(device_, block->memory, nullptr);
}

VkResult MemoryPool::allocate_memory(VkDeviceSize size, uint32_t type, bool map, VkDeviceMemory& memory, void*& host) {
    if (allocations_ >= max_allocations_) return VK_ERROR_TOO_MANY_OBJECTS;
    VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    info.allocationSize = size;
    info.memoryTypeIndex = type;
    VkDeviceMemory made = VK_NULL_HANDLE;
    if (const VkResult result = vkAllocateMemory(device_, &info, nullptr, &made); result != VK_SUCCESS) return result;
    void* address = nullptr;
    if (map) {
        if (const VkResult result = vkMapMemory(device_, made, 0, VK_WHOLE_SIZE, 0, &address); result != VK_SUCCESS) {
            vkFreeMemory(device_, made, nullptr);
            return result;
        }
    }
    ++allocations_;
    tally_ += size;
    memory = made;
    host = address;
    return VK_SUCCESS;
}

void MemoryPool::Block::add_range(VkDeviceSize offset, VkDeviceSize length) {
    free.emplace(offset, length);
    by_length.emplace(length, offset);
}

void MemoryPool::Block::remove_range(std::map<VkDeviceSize, VkDeviceSize>::iterator range) {
    auto [first, last] = by_length.equal_range(range->second);
    for (auto it = first; it != last; ++it)
        if (it->second == range->first) {
            by_length.erase(it);
            break;
        }
    free.erase(range);
}

// Best fit: the shortest free range of the block that holds `size` bytes from an aligned offset, found by
// length (a scan of every range in offset order took 81% of a 2,000-object scene's run: its blocks hold
// thousands of ranges).
bool MemoryPool::take(Block& block, VkDeviceSize size, VkDeviceSize alignment, VkDeviceSize& offset) {
    if (block.free_bytes < size || block.by_length.empty() || block.by_length.rbegin()->first < size) return false;
    for (auto it = block.by_length.lower_bound(size); it != block.by_length.end(); ++it) {
        const VkDeviceSize begin = it->second, end = it->second + it->first;
        const VkDeviceSize at = align_up(begin, alignment);
        if (at + size > end) continue;  // the alignment's gap leaves too little: a longer range will do
        block.remove_range(block.free.find(begin));
        if (at > begin) block.add_range(begin, at - begin);
        if (at + size < end) block.add_range(at + size, end - (at + size));
        block.free_bytes -= size;
        offset = at;
        return true;
    }
    return false;
}

VkResult MemoryPool::allocate(const VkMemoryRequirements& requirements, uint32_t type, bool map, bool shareable,
                              MemoryRange& range) {
    const VkMemoryPropertyFlags flags = properties_.memoryTypes[type].propertyFlags;
    const bool coherent = !(flags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) || (flags & VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    std::lock_guard lock(mutex_);
    if (!shareable || requirements.size > kLargestShared) {
        MemoryRange own;
        own.size = requirements.size;
        own.coherent = coherent;
        if (const VkResult result = allocate_memory(requirements.size, type, map, own.memory, own.mapped); result != VK_SUCCESS) {
            range.size = requirements.size;
            return result;
        }
        range = own;
        return VK_SUCCESS;
    }
    // A flush or invalidate of non-coherent memory covers whole atoms: each range starts and ends on one, so
    // that a buffer's never reaches into its neighbour's.
    const VkDeviceSize alignment = coherent ? requirements.alignment : std::max(requirements.alignment, atom_);
    // Sizes rounded up to the alignment too, so that ranges of one alignment follow each other without gaps.
    const VkDeviceSize size = align_up(std::max<VkDeviceSize>(requirements.size, 1), alignment);
    MemoryRange shared;
    shared.size = size;
    shared.coherent = coherent;
    auto place = [&](uint32_t index) {
        Block& block = *blocks_[index];
        if (block.type != type || block.mapped != map || !take(block, size, alignment, shared.offset)) return false;
        shared.memory = block.memory;
        shared.block = index;
        shared.mapped = block.host ? static_cast<char*>(block.host) + shared.offset : nullptr;
        return true;
    };
    for (uint32_t index = 0; index < blocks_.size(); ++index)
        if (blocks_[index] && place(index)) return range = shared, VK_SUCCESS;
    auto block = std::make_unique<Block>();
    block->type = type;
    block->mapped = map;
    block->coherent = coherent;
    if (const VkResult result = allocate_memory(kBlockBytes, type, map, block->memory, block->host); result != VK_SUCCESS) {
        range.size = kBlockBytes;  // what was asked of the driver, for the message
        return result;
    }
    block->add_range(0, kBlockBytes);
    block->free_bytes = kBlockBytes;
    const auto empty = std::find(blocks_.begin(), blocks_.end(), nullptr);
    const uint32_t index = uint32_t(empty - blocks_.begin());
    if (empty == blocks_.end())
        blocks_.push_back(std::move(block));
    else
        *empty = std::move(block);
    if (!place(index)) {  // an alignment near the block's size: the range on its own after all
        vkFreeMemory(device_, blocks_[index]->memory, nullptr);
        tally_ -= kBlockBytes;
        --allocations_;
        blocks_[index].reset();
        MemoryRange own;
        own.size = requirements.size;
        own.coherent = coherent;
        if (const VkResult result = allocate_memory(requirements.size, type, map, own.memory, own.mapped); result != VK_SUCCESS)
            return result;
        range = own;
        return VK_SUCCESS;
    }
    range = shared;
    return VK_SUCCESS;
}

void MemoryPool::free(MemoryRange& range) {
    if (!range.memory) return;
    std::lock_guard lock(mutex_);
    if (range.block == MemoryRange::kOwn) {
        vkFreeMemory(device_, range.memory, nullptr);  // unmaps implicitly
        tally_ -= range.size;
        --allocations_;
    } else {
        Block& block = *blocks_[range.block];
        VkDeviceSize begin = range.offset, length = range.size;
        // Joined to the free ranges it touches, so that the block's free space stays in as few ranges as it can.
        auto after = block.free.lower_bound(begin);
        if (after != block.free.end() && begin + length == after->first) {
            length += after->second;
            auto next = std::next(after);
            block.remove_range(after);
            after = next;
        }
        if (after != block.free.begin()) {
            auto before = std::prev(after);
            if (before->first + before->second == begin) {
                begin = before->first;
                length += before->second;
                block.remove_range(before);
            }
        }
        block.add_range(begin, length);
        block.free_bytes += range.size;
        if (block.free_bytes == kBlockBytes) {  // empty: given back, so a scene that shrinks holds less
            vkFreeMemory(device_, block.memory, nullptr);
            tally_ -= kBlockBytes;
            --allocations_;
            blocks_[range.block].reset();
        }
    }
    range = MemoryRange();
}

uint32_t MemoryPool::allocation_count() const {
    std::lock_guard lock(mutex_);
    return allocations_;
}

std::string MemoryPool::failure_message(VkResult result, VkDeviceSize bytes, const std::string& what) const {
    if (result == VK_ERROR_TOO_MANY_OBJECTS)
        return "this device allows " + std::to_string(max_allocations_) +
               " GPU memory allocations at once (maxMemoryAllocationCount), and the drawing holds them all: "
               "draw fewer objects";
    const std::string size = bytes >= (VkDeviceSize(1) << 20) ? std::to_string(bytes >> 20) + " MiB" : std::to_string(bytes >> 10) + " KiB";
    return std::string(result == VK_ERROR_MEMORY_MAP_FAILED ? "cannot map " : "cannot allocate ") + size + " of GPU memory" +
           (what.empty() ? "" : " for " + what) + " (" + vk_result_name(result) + ")";
}

}  // namespace stipple::gpu
