// Large C++ allocations are advised into transparent huge pages (src/core/huge_pages.cpp), and nothing
// around them is.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/huge_pages.hpp"

namespace {

struct Mapping {
    std::uintptr_t begin = 0, end = 0;
    std::string flags;  // the VmFlags line of /proc/self/smaps
};

// The mapping of this process that holds `address`, from /proc/self/smaps.
bool mapping_at(const void* address, Mapping& found) {
    std::ifstream smaps("/proc/self/smaps");
    const std::uintptr_t at = reinterpret_cast<std::uintptr_t>(address);
    std::string line;
    bool inside = false;
    while (std::getline(smaps, line)) {
        std::uintptr_t begin = 0, end = 0;
        char dash = 0;
        std::istringstream range(line);
        if (range >> std::hex >> begin >> dash >> end && dash == '-' && line.find(':') > line.find(' ')) {
            inside = at >= begin && at < end;
            if (inside) found.begin = begin, found.end = end;
        } else if (inside && line.rfind("VmFlags:", 0) == 0) {
            found.flags = line + " ";
            return true;
        }
    }
    return false;
}

// Whether the kernel has transparent huge pages at all (madvise fails without them). Whatever the system's
// mode, `never` included, MADV_HUGEPAGE marks the mapping, so the tests need no more than this.
bool kernel_has_huge_pages() {
    std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
    return mode.good();
}

TEST(HugePages, ALargeBlockIsAdvisedAndOnlyItsAlignedInterior) {
    if (!stipple::kHugePageNew) GTEST_SKIP() << "a sanitizer's operator new is in charge in this build";
    if (!kernel_has_huge_pages()) GTEST_SKIP() << "this kernel has no transparent huge pages";
    constexpr std::size_t kBytes = std::size_t(64) << 20;
    std::vector<char> block(kBytes);  // operator new, as every std::vector
    const char* middle = block.data() + kBytes / 2;
    Mapping mapping;
    ASSERT_TRUE(mapping_at(middle, mapping)) << "no mapping in /proc/self/smaps holds the block";
    EXPECT_NE(mapping.flags.find(" hg "), std::string::npos)
        << "the 64-MiB block's pages are not advised into huge pages: " << mapping.flags;
    // The advice covers whole 2-MiB pages inside the block, never memory beyond it.
    const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(block.data());
    EXPECT_GE(mapping.begin, begin);
    EXPECT_LE(mapping.end, begin + kBytes);
    EXPECT_EQ(mapping.begin % (std::uintptr_t(2) << 20), 0u);
    EXPECT_GE(mapping.end - mapping.begin, kBytes - (std::size_t(4) << 20));
}

TEST(HugePages, ASmallBlockIsLeftAsItWas) {
    if (!stipple::kHugePageNew) GTEST_SKIP() << "a sanitizer's operator new is in charge in this build";
    if (!kernel_has_huge_pages()) GTEST_SKIP() << "this kernel has no transparent huge pages";
    std::vector<char> block(std::size_t(512) << 10);
    Mapping mapping;
    ASSERT_TRUE(mapping_at(block.data() + block.size() / 2, mapping));
    EXPECT_EQ(mapping.flags.find(" hg "), std::string::npos) << mapping.flags;
}

}  // namespace
