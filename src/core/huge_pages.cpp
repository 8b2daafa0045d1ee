// Large C++ allocations in transparent huge pages.
//
// Generation allocates and frees arrays of tens to hundreds of MiB (positions, grids, slots, the
// relaxation's spatial copies), and glibc hands each one back to the system when it is freed, so every
// new one is faulted in again, 4 KiB at a time: the 8M-stipple dragon (`STIPPLE_NO_CACHE=1 stipple info
// dragon.ply --dmax 4`) took 292,000-301,000 page faults, at 4-10 us each on a virtual machine (`perf`:
// a ninth of its samples in the kernel's fault path and in memset); it now takes 67,000-70,000, and
// generates 15% faster (docs/performance.md). The system's transparent huge pages are usually granted
// only where a program asks (`/sys/kernel/mm/transparent_hugepage/enabled` = madvise, Debian's default),
// so the blocks this program allocates through `operator new` at kOwnMappingBytes or more are marked
// MADV_HUGEPAGE before anything touches them: one fault then maps 2 MiB.
//
// Such a block is a mapping of its own, starting on a 2-MiB boundary, so that all of it is advised but a
// last partial huge page (rounded up to a whole one when that adds at most a sixteenth to the block),
// and it goes back to the system when it is freed. Until 2026-12-03 blocks of 4 MiB and more were
// malloc's and only their aligned interior was advised: a small model's arrays (spot's 549,582 stipples
// make blocks of 2.1 and 6.3 MiB) held one huge page or none and were faulted in 4 KiB at a time, at
// about 10 us a fault on this virtual machine (a huge page that the system has just had back costs about
// 0.1 ms: 50 times less for 2 MiB). Spot's generation then spent a sixth of its time in faults.
//
// glibc's heap serves the blocks under its mmap threshold, and reuses their pages without a fault; the
// threshold used to rise to the size of each mapped block freed (to 32 MiB), and those blocks are ours
// now, so it is set here: blocks of 2 MiB and more are mapped (ours, or the C libraries' malloc's), the
// smaller ones come from the heap, which is handed back once 16 MiB lie free at its top (glibc's 64 MiB
// after the rise kept 13 MB more resident at the 8M-stipple dragon's peak; 4 or 8 MiB made the bunny's
// generation 8% slower, its grids of 1.9 MiB faulted in again each time). Measured in
// docs/performance.md, "Large blocks of their own".
//
// Smaller blocks, and what C libraries (the Vulkan driver) allocate with malloc, are malloc's as before.
// Left out under a sanitizer (huge_pages.hpp).
#include "core/huge_pages.hpp"

#if !defined(STIPPLE_SANITIZER_ALLOCATOR)
#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#define STIPPLE_OWN_MAPPINGS 1
#endif
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace {

constexpr std::uintptr_t kHugePageBytes = std::uintptr_t(2) << 20;
// A smaller block holds no whole huge page; glibc maps its own blocks from this size on too.
constexpr std::size_t kOwnMappingBytes = std::size_t(2) << 20;
constexpr std::uintptr_t kPageBytes = 4096;
// The free memory at the top of glibc's heap that it keeps before handing it back (see the top).
constexpr std::size_t kHeapTrimBytes = std::size_t(16) << 20;

#if defined(STIPPLE_OWN_MAPPINGS)

// The blocks mapped here, by address, with their lengths: operator delete is not always told a block's
// size, and a block must be unmapped whole. Open addressing in a fixed table (no allocation inside the
// allocator); a block that finds it full is malloc's instead. Only addresses on a 2-MiB boundary are
// looked up, so the frees of malloc's blocks almost never take the lock.
class OwnMappings {
public:
    bool add(std::uintptr_t address, std::size_t length) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (count_ + 1 > kSlots / 2) return false;
        std::size_t slot = home(address);
        while (address_[slot] != 0) slot = (slot + 1) & (kSlots - 1);
        address_[slot] = address, length_[slot] = length, ++count_;
        return true;
    }
    // The length of the block at `address`, taken out of the table; 0 when the block is not one of ours.
    std::size_t remove(std::uintptr_t address) {
        std::lock_guard<std::mutex> lock(mutex_);
        std::size_t slot = home(address);
        while (address_[slot] != address) {
            if (address_[slot] == 0) return 0;
            slot = (slot + 1) & (kSlots - 1);
        }
        const std::size_t length = length_[slot];
        // Backward-shift deletion: later entries of the probe run move up, so no run has a gap.
        std::size_t hole = slot;
        for (std::size_t next = (slot + 1) & (kSlots - 1); address_[next] != 0; next = (next + 1) & (kSlots - 1)) {
            const std::size_t wanted = home(address_[next]);
            // Move `next` into the hole unless its home lies cyclically in (hole, next].
            const bool stays = hole <= next ? (wanted > hole && wanted <= next) : (wanted > hole || wanted <= next);
            if (!stays) address_[hole] = address_[next], length_[hole] = length_[next], hole = next;
        }
        address_[hole] = 0, --count_;
        return length;
    }

private:
    static constexpr std::size_t kSlots = 8192;
    static std::size_t home(std::uintptr_t address) {
        return std::size_t(((address >> 21) * 0x9E3779B97F4A7C15ull) >> 51) & (kSlots - 1);
    }
    std::mutex mutex_;
    std::size_t count_ = 0;
    std::uintptr_t address_[kSlots] = {};
    std::size_t length_[kSlots] = {};
};

constinit OwnMappings own_mappings;

#if defined(__GLIBC__)
// See the top of this file.
const bool glibc_thresholds_set = [] {
    mallopt(M_MMAP_THRESHOLD, int(kOwnMappingBytes));
    mallopt(M_TRIM_THRESHOLD, int(kHeapTrimBytes));
    return true;
}();
#endif

// A mapping of its own for a large block, starting on a 2-MiB boundary, its whole huge pages advised;
// nullptr when the system refuses (malloc then tries).
void* map_block(std::size_t bytes) {
    if (bytes > (std::size_t(1) << 48)) return nullptr;  // beyond any address space (and the roundings' overflow)
    // A last partial huge page costs up to 512 faults of 4 KiB: rounded up when that adds little.
    const std::uintptr_t whole_pages = (bytes + kHugePageBytes - 1) & ~(kHugePageBytes - 1);
    const std::uintptr_t length =
        whole_pages - bytes <= bytes / 16 ? whole_pages : (bytes + kPageBytes - 1) & ~(kPageBytes - 1);
    void* raw = mmap(nullptr, length + kHugePageBytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (raw == MAP_FAILED) return nullptr;
    const std::uintptr_t raw_begin = reinterpret_cast<std::uintptr_t>(raw);
    const std::uintptr_t begin = (raw_begin + kHugePageBytes - 1) & ~(kHugePageBytes - 1);
    const std::uintptr_t end = begin + length, raw_end = raw_begin + length + kHugePageBytes;
    if (begin > raw_begin) (void)munmap(raw, begin - raw_begin);
    if (raw_end > end) (void)munmap(reinterpret_cast<void*>(end), raw_end - end);
    if (!own_mappings.add(begin, length)) {
        (void)munmap(reinterpret_cast<void*>(begin), length);
        return nullptr;
    }
#if defined(MADV_HUGEPAGE)
    // Advice only: where the kernel has no huge pages (or they are off), the block is used as it is.
    const std::uintptr_t whole = length & ~(kHugePageBytes - 1);
    if (whole > 0) (void)madvise(reinterpret_cast<void*>(begin), whole, MADV_HUGEPAGE);
#endif
    return reinterpret_cast<void*>(begin);
}

// Unmaps `block` if it is one of ours.
bool unmap_block(void* block) {
    const std::uintptr_t address = reinterpret_cast<std::uintptr_t>(block);
    if (address == 0 || (address & (kHugePageBytes - 1)) != 0) return false;
    const std::size_t length = own_mappings.remove(address);
    if (length == 0) return false;
    (void)munmap(block, length);
    return true;
}

#else
void* map_block(std::size_t) { return nullptr; }
bool unmap_block(void*) { return false; }
#endif

void* allocate(std::size_t bytes) {
    if (bytes >= kOwnMappingBytes)
        if (void* block = map_block(bytes)) return block;
    void* block = std::malloc(bytes ? bytes : 1);
    if (!block) throw std::bad_alloc();
    return block;
}

void release(void* block) noexcept {
    if (!unmap_block(block)) std::free(block);
}

}  // namespace

void* operator new(std::size_t bytes) { return allocate(bytes); }
void* operator new[](std::size_t bytes) { return allocate(bytes); }
void* operator new(std::size_t bytes, const std::nothrow_t&) noexcept {
    try {
        return allocate(bytes);
    } catch (...) {
        return nullptr;
    }
}
void* operator new[](std::size_t bytes, const std::nothrow_t&) noexcept {
    try {
        return allocate(bytes);
    } catch (...) {
        return nullptr;
    }
}
void operator delete(void* block) noexcept { release(block); }
void operator delete[](void* block) noexcept { release(block); }
void operator delete(void* block, std::size_t) noexcept { release(block); }
void operator delete[](void* block, std::size_t) noexcept { release(block); }
void operator delete(void* block, const std::nothrow_t&) noexcept { release(block); }
void operator delete[](void* block, const std::nothrow_t&) noexcept { release(block); }

#endif  // !STIPPLE_SANITIZER_ALLOCATOR
