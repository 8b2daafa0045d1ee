#pragma once
// Returning freed memory to the system in the middle of a long computation.
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace stipple {

// Gives the system back the free memory the allocator keeps. glibc serves blocks under 2 MiB from its
// heap (the threshold set in huge_pages.cpp; larger C++ blocks are mappings of their own, unmapped when
// freed) and keeps the pages of blocks freed in the middle of the heap resident: the progressive order
// frees blocks of a few hundred KiB to 2 MiB a slab between the slabs' grids it keeps, and those holes
// counted in generation's peak (the 8M-stipple dragon peaked at 401,000 KiB resident with them, 355,000
// without, before other changes). A low mmap threshold for the whole program instead (mallopt) made the
// renderer's per-frame allocations fault their pages every frame (the vertex path's frame 25% slower), so
// generation calls this where it has just freed such blocks. A no-op without glibc.
inline void release_free_memory() {
#if defined(__GLIBC__)
    malloc_trim(0);
#endif
}

}  // namespace stipple
