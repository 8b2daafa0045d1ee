// Large C++ allocations are mappings of their own, advised into transparent huge pages
// (src/core/huge_pages.cpp), and nothing around them is.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <random>
#include <thread>
#include <utility>
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

constexpr std::uintptr_t kHugePage = std::uintptr_t(2) << 20;

bool advised(const Mapping& mapping) { return mapping.flags.find(" hg ") != std::string::npos; }

TEST(HugePages, ALargeBlockIsAMappingOfItsOwnAdvisedFromItsFirstByte) {
    if (!stipple::kHugePageNew) GTEST_SKIP() << "a sanitizer's operator new is in charge in this build";
    if (!kernel_has_huge_pages()) GTEST_SKIP() << "this kernel has no transparent huge pages";
    constexpr std::size_t kBytes = std::size_t(64) << 20;
    std::vector<char> block(kBytes);  // operator new, as every std::vector
    const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(block.data());
    EXPECT_EQ(begin % kHugePage, 0u) << "the block does not start on a huge page";
    for (const char* inside : {block.data(), block.data() + kBytes / 2, block.data() + kBytes - 1}) {
        Mapping mapping;
        ASSERT_TRUE(mapping_at(inside, mapping)) << "no mapping in /proc/self/smaps holds the block";
        EXPECT_TRUE(advised(mapping)) << "byte " << (inside - block.data()) << " of the 64-MiB block is not advised: "
                                      << mapping.flags;
    }
}

// A block of 3 MiB holds one whole huge page only when it starts on one (glibc's blocks did not, and were
// not advised under 4 MiB); its last MiB would add a third to it as a huge page, so it stays in 4-KiB pages.
TEST(HugePages, ABlockOfAFewMiBStartsOnAHugePage) {
    if (!stipple::kHugePageNew) GTEST_SKIP() << "a sanitizer's operator new is in charge in this build";
    if (!kernel_has_huge_pages()) GTEST_SKIP() << "this kernel has no transparent huge pages";
    constexpr std::size_t kBytes = std::size_t(3) << 20;
    std::vector<char> block(kBytes);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(block.data()) % kHugePage, 0u);
    Mapping first, last;
    ASSERT_TRUE(mapping_at(block.data(), first));
    ASSERT_TRUE(mapping_at(block.data() + kBytes - 1, last));
    EXPECT_TRUE(advised(first)) << first.flags;
    EXPECT_FALSE(advised(last)) << "the last, partial huge page is advised: " << last.flags;
    EXPECT_LE(last.end, reinterpret_cast<std::uintptr_t>(block.data()) + kBytes) << "the mapping reaches past the block";
}

// A block a little under a whole number of huge pages has its last one whole: at most a sixteenth more.
TEST(HugePages, ANearlyWholeLastHugePageIsRoundedUp) {
    if (!stipple::kHugePageNew) GTEST_SKIP() << "a sanitizer's operator new is in charge in this build";
    if (!kernel_has_huge_pages()) GTEST_SKIP() << "this kernel has no transparent huge pages";
    constexpr std::size_t kBytes = (std::size_t(20) << 20) - (std::size_t(256) << 10);
    std::vector<char> block(kBytes);
    Mapping last;
    ASSERT_TRUE(mapping_at(block.data() + kBytes - 1, last));
    EXPECT_TRUE(advised(last)) << last.flags;
}

// The blocks are found again when freed, sized or not, from any thread, with thousands alive at once (the
// table is open addressing: a block lost from it would be handed to free(), which aborts on a pointer
// malloc never gave). Not touched: address space only.
TEST(HugePages, ManyLargeBlocksComeAndGoFromTwoThreads) {
    if (!stipple::kHugePageNew) GTEST_SKIP() << "a sanitizer's operator new is in charge in this build";
    std::atomic<int> aligned{0};
    auto churn = [&aligned](unsigned seed) {
        std::mt19937 random(seed);
        for (int round = 0; round < 4; ++round) {
            std::vector<std::pair<void*, std::size_t>> blocks;
            for (int i = 0; i < 1500; ++i) {
                const std::size_t bytes = (std::size_t(2) << 20) + random() % (std::size_t(6) << 20);
                blocks.emplace_back(::operator new(bytes), bytes);
                if (reinterpret_cast<std::uintptr_t>(blocks.back().first) % kHugePage == 0) ++aligned;
            }
            std::shuffle(blocks.begin(), blocks.end(), random);
            for (size_t i = 0; i < blocks.size(); ++i) {
#if defined(__cpp_sized_deallocation)  // GCC's default from C++14 on; clang 15 leaves it out
                if (i % 2) {
                    ::operator delete(blocks[i].first, blocks[i].second);
                    continue;
                }
#endif
                ::operator delete(blocks[i].first);
            }
        }
    };
    std::thread other(churn, 1u);
    churn(2u);
    other.join();
    EXPECT_EQ(aligned.load(), 2 * 4 * 1500) << "some blocks were malloc's: the table was full";
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
