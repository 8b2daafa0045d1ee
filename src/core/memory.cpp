#include "core/memory.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>

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

std::optional<uint64_t> control_group_memory_limit(const std::string& proc_self_cgroup, const std::string& cgroup_root) {
    std::ifstream in(proc_self_cgroup);
    std::optional<uint64_t> least;
    // The group at `path` in the hierarchy mounted at `hierarchy`, and each of its ancestors up to that root.
    auto consider = [&](const std::string& hierarchy, std::string path, const char* file) {
        while (true) {
            if (const std::optional<uint64_t> limit = cgroup_limit((hierarchy + path + "/" + file).c_str()); limit && *limit > 0)
                least = least ? std::min(*least, *limit) : *limit;
            if (path.empty()) break;
            const size_t slash = path.find_last_of('/');
            path.erase(slash == std::string::npos ? 0 : slash);  // a path not starting at "/" ends at the root too
        }
    };
    std::string line;
    while (std::getline(in, line)) {
        const size_t first = line.find(':'), second = first == std::string::npos ? first : line.find(':', first + 1);
        if (second == std::string::npos) continue;
        const std::string controllers = line.substr(first + 1, second - first - 1);
        std::string path = line.substr(second + 1);
        while (!path.empty() && path.back() == '/') path.pop_back();
        if (path.find("/..") != std::string::npos) continue;
        if (line.compare(0, first, "0") == 0 && controllers.empty()) {
            consider(cgroup_root, path, "memory.max");
            consider(cgroup_root + "/unified", path, "memory.max");
        } else if (("," + controllers + ",").find(",memory,") != std::string::npos) {
            consider(cgroup_root + "/memory", path, "memory.limit_in_bytes");
        }
    }
    return least;
}

std::optional<uint64_t> address_space_limit() {
    struct rlimit limit {};
    if (::getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return std::nullopt;
    return uint64_t(limit.rlim_cur);
}

uint64_t physical_memory_bytes() {
    const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
    uint64_t memory = pages > 0 && page > 0 ? uint64_t(pages) * uint64_t(page) : 0;
    auto lower_to = [&](uint64_t limit) { memory = memory == 0 ? limit : std::min(memory, limit); };
    if (const std::optional<uint64_t> limit = control_group_memory_limit("/proc/self/cgroup", "/sys/fs/cgroup")) lower_to(*limit);
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
