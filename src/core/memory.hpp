#pragma once
// Returning freed memory to the system in the middle of a long computation; what the machine has, for
// refusing in one line what could never fit instead of running out half way.
#include <cstdint>
#include <cstdio>
#include <string>
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

// The memory this process may use, in bytes: the machine's physical memory, or less where a control group
// (cgroup v2 memory.max, v1 memory.limit_in_bytes) limits it (a container on a large host reported the host's,
// and a model it could never load was read until the kernel killed it), or STIPPLE_HOST_MEMORY_LIMIT (e.g.
// 2G: how a smaller machine refuses a model, tried on a big one; a value that is not a size fails). 0 where
// the system says nothing.
uint64_t physical_memory_bytes();

// A size for a message: "3.0 GiB", "12.5 MiB", "830 bytes".
inline std::string byte_size(uint64_t bytes) {
    char text[40];
    if (bytes >= (uint64_t(1) << 30)) std::snprintf(text, sizeof text, "%.1f GiB", double(bytes) / double(uint64_t(1) << 30));
    else if (bytes >= (uint64_t(1) << 20)) std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / double(uint64_t(1) << 20));
    else std::snprintf(text, sizeof text, "%llu bytes", (unsigned long long)bytes);
    return text;
}

}  // namespace stipple
