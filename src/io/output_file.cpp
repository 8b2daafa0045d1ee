#include "io/output_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "core/error.hpp"

namespace stipple {

void check_output_writable(const std::string& option, const std::string& path) {
    namespace fs = std::filesystem;
    const fs::path file(path);
    const std::string named = option + " " + path;
    std::error_code ec;
    if (fs::is_directory(file, ec)) fail(named + ": is a folder, not a file");
    if (file.has_parent_path()) {
        fs::create_directories(file.parent_path(), ec);
        if (ec) fail(named + ": cannot make its folder " + file.parent_path().string() + ": " + ec.message());
    }
    // Made to try (exclusively: only a file this made is removed again), or opened if it exists (appending,
    // never truncated): the only test that holds for every reason a file cannot be made, root's included, to
    // which access() answers yes.
    errno = 0;
    if (std::FILE* made = std::fopen(path.c_str(), "wbx")) {
        std::fclose(made);
        fs::remove(file, ec);
        return;
    }
    if (errno == EEXIST) {
        errno = 0;
        if (std::FILE* existing = std::fopen(path.c_str(), "ab")) {
            std::fclose(existing);
            return;
        }
    }
    fail(named + ": cannot write there: " + std::string(std::strerror(errno ? errno : EIO)));
}

}  // namespace stipple
