// Large C++ allocations in transparent huge pages.
//
// Generation allocates and frees arrays of tens to hundreds of MiB (positions, grids, slots, the
// relaxation's spatial copies), and glibc hands each one back to the system when it is freed, so every
// new one is faulted in again, 4 KiB at a time: the 8M-stipple dragon (`STIPPLE_NO_CACHE=1 stipple info
// dragon.ply --dmax 4`) took 292,000-301,000 page faults, at about 4 us each on a virtual machine (`perf`:
// a ninth of its samples in the kernel's fault path and in memset); it now takes 67,000-70,000, and
// generates 15% faster (docs/performance.md). The system's transparent huge pages are usually granted
// only where a program asks (`/sys/kernel/mm/transparent_hugepage/enabled` = madvise, Debian's default),
// so the blocks this program allocates through `operator new` at kHugeAdviceBytes or more are marked
// MADV_HUGEPAGE before anything touches them: one fault then maps 2 MiB. Only the 2-MiB-aligned interior
// of a block is marked, so no page outside it changes. Smaller blocks, and what C libraries (the Vulkan
// driver) allocate with malloc, are left as they were. Blocks are still malloc's: operator delete frees
// them as before. Left out under a sanitizer (huge_pages.hpp).
#include "core/huge_pages.hpp"

#if !defined(STIPPLE_SANITIZER_ALLOCATOR)
#include <cstdint>
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace {

constexpr std::size_t kHugePageBytes = std::size_t(2) << 20;
// A smaller block holds at most one whole huge page.
constexpr std::size_t kHugeAdviceBytes = std::size_t(4) << 20;

void advise_huge_pages(void* block, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(block);
    const std::uintptr_t first = (begin + kHugePageBytes - 1) & ~(kHugePageBytes - 1);
    const std::uintptr_t last = (begin + bytes) & ~(kHugePageBytes - 1);
    // Advice only: where the kernel has no huge pages (or they are off), the block is used as it is.
    if (last > first) (void)madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#else
    (void)block, (void)bytes;
#endif
}

void* allocate(std::size_t bytes) {
    void* block = std::malloc(bytes ? bytes : 1);
    if (!block) throw std::bad_alloc();
    if (bytes >= kHugeAdviceBytes) advise_huge_pages(block, bytes);
    return block;
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
void operator delete(void* block) noexcept { std::free(block); }
void operator delete[](void* block) noexcept { std::free(block); }
void operator delete(void* block, std::size_t) noexcept { std::free(block); }
void operator delete[](void* block, std::size_t) noexcept { std::free(block); }
void operator delete(void* block, const std::nothrow_t&) noexcept { std::free(block); }
void operator delete[](void* block, const std::nothrow_t&) noexcept { std::free(block); }

#endif  // !STIPPLE_SANITIZER_ALLOCATOR
