// The memory a process may use (src/core/memory.hpp): its control groups' limits, read from the groups that
// /proc/self/cgroup names and their ancestors, in fake trees of both cgroup versions.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/memory.hpp"
#include "support/test_paths.hpp"

namespace {

using stipple::control_group_memory_limit;

void write(const std::filesystem::path& path, const std::string& text) {
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path) << text;
}

// v1 without a namespace: the process's group lies below the root, whose file says "no limit" (about 2^63); its
// own group's limit was missed when only the root was read. The smallest of the path's levels counts.
TEST(MemoryLimits, ControlGroupV1ReadsTheProcesssOwnGroupAndItsAncestors) {
    const auto root = stipple::test::temp_dir("memory-limits-v1");
    write(root / "memory/memory.limit_in_bytes", "9223372036854771712\n");
    write(root / "memory/jobs/memory.limit_in_bytes", "8589934592\n");
    write(root / "memory/jobs/job7/memory.limit_in_bytes", "3221225472\n");
    write(root / "self_cgroup", "9:name=systemd:/\n4:cpu,memory:/jobs/job7\n1:cpu:/\n0::/\n");
    EXPECT_EQ(control_group_memory_limit((root / "self_cgroup").string(), root.string()), uint64_t(3221225472));
    write(root / "memory/jobs/memory.limit_in_bytes", "1073741824\n");  // a parent tighter than the group
    EXPECT_EQ(control_group_memory_limit((root / "self_cgroup").string(), root.string()), uint64_t(1073741824));
    write(root / "self_cgroup", "4:cpu:/jobs/job7\n");  // no memory controller named: no limit
    EXPECT_EQ(control_group_memory_limit((root / "self_cgroup").string(), root.string()), std::nullopt);
}

// v2: "max" is no limit; a namespaced process (path "/") reads the root's file; a missing file is no limit.
TEST(MemoryLimits, ControlGroupV2ReadsMemoryMaxAlongThePath) {
    const auto root = stipple::test::temp_dir("memory-limits-v2");
    write(root / "memory.max", "max\n");
    write(root / "user.slice/memory.max", "max\n");
    write(root / "user.slice/run-1.scope/memory.max", "2147483648\n");
    write(root / "self_cgroup", "0::/user.slice/run-1.scope\n");
    EXPECT_EQ(control_group_memory_limit((root / "self_cgroup").string(), root.string()), uint64_t(2147483648));
    write(root / "self_cgroup", "0::/\n");
    EXPECT_EQ(control_group_memory_limit((root / "self_cgroup").string(), root.string()), std::nullopt);
    write(root / "memory.max", "4294967296\n");
    EXPECT_EQ(control_group_memory_limit((root / "self_cgroup").string(), root.string()), uint64_t(4294967296));
    EXPECT_EQ(control_group_memory_limit((root / "absent").string(), root.string()), std::nullopt);
}

}  // namespace
