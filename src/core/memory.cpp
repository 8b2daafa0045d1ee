#include "core/memory.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <optional>

#include "core/decimal.hpp"
#include "core/error.hpp"

namespace stipple {

namespace {

// The first word of a control group's limit file, where it is a number of bytes ("max" and absent files: none).
std::optional<uint64_t> cgroup_limit(const char* path) {
    std::ifstream in(path);
    std::string word;
    if (!(in >> word) || word.empty() || word.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
    return parse_byte_size(word);
}

}  // namespace

uint64_t physical_memory_bytes() {
    const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
    uint64_t memory = pages > 0 && page > 0 ? uint64_t(pages) * uint64_t(page) : 0;
    auto lower_to = [&](uint64_t limit) { memory = memory == 0 ? limit : std::min(memory, limit); };
    // cgroup v1 reports "no limit" as a number near 2^63, which the minimum leaves out.
    for (const char* path : {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"})
        if (const std::optional<uint64_t> limit = cgroup_limit(path); limit && *limit > 0) lower_to(*limit);
    if (const char* text = std::getenv("STIPPLE_HOST_MEMORY_LIMIT"); text && *text) {
        const std::optional<uint64_t> limit = parse_byte_size(text);
        // A test setting: a typo must not silently test nothing.
        if (!limit || *limit < 1)
            fail(std::string("STIPPLE_HOST_MEMORY_LIMIT=") + text + " is not a size such as 2G (bytes, or a number with k, M or G)");
        lower_to(*limit);
    }
    return memory;
}

}  // namespace stipple
