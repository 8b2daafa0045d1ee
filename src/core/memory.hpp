#pragma once
// Returning freed memory to the system in the middle of a long computation; what the machine has, for
// refusing in one line what could never fit instead of running out half way.
#include <cstdint>
#include <cstdio>
#include <optional>
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

// The process's address-space limit (RLIMIT_AS, ulimit -v), where it has one.
std::optional<uint64_t> address_space_limit();

// The smallest memory limit of a process's control groups and their ancestors, as `proc_self_cgroup` (the format
// of /proc/self/cgroup) lists them under `cgroup_root` (/sys/fs/cgroup): a cgroup v2 line "0::/path" names
// root/path (or root/unified/path on a hybrid host) and its memory.max; a v1 line whose controllers include memory
// names root/memory/path and its memory.limit_in_bytes. Each level up to the root counts: without a cgroup
// namespace (systemd units, batch schedulers, some containers) the root's files are the host's, not the process's,
// and were all that was read (a review). "max", and v1's "no limit" (about 2^63), are none. Nothing: no limit.
std::optional<uint64_t> control_group_memory_limit(const std::string& proc_self_cgroup, const std::string& cgroup_root);

// A size for a message: "3.0 GiB", "12.5 MiB", "830 bytes".
inline std::string byte_size(uint64_t bytes) {
    char text[40];
    if (bytes >= (uint64_t(1) << 30)) std::snprintf(text, sizeof text, "%.1f GiB", double(bytes) / double(uint64_t(1) << 30));
    else if (bytes >= (uint64_t(1) << 20)) std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / double(uint64_t(1) << 20));
    else std::snprintf(text, sizeof text, "%llu bytes", (unsigned long long)bytes);
    return text;
}

}  // namespace stipple
