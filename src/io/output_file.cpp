#include "io/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <vector>

#include "core/error.hpp"

namespace stipple {

void check_output_writable(const std::string& option, const std::string& path) {
    namespace fs = std::filesystem;
    const fs::path file(path);
    const std::string named = option + " " + path;
    struct stat seen {};
    if (lstat(path.c_str(), &seen) == 0) {
        if (S_ISDIR(seen.st_mode)) fail(named + ": is a folder, not a file");
        // A pipe, a device or a link is the user's to name: opening one to try could block or make a file where
        // the link points. Only a regular file is tried (for writing, without opening it).
        if (S_ISREG(seen.st_mode) && access(path.c_str(), W_OK) != 0)
            fail(named + ": cannot write there: " + std::string(std::strerror(errno)));
        return;
    }
    const fs::path folder = file.has_parent_path() ? file.parent_path() : fs::path(".");
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (ec) fail(named + ": cannot make its folder " + folder.string() + ": " + ec.message());
    // A file of a name of its own made and removed in the folder: the one test that holds for every reason a
    // file cannot be made there (root's included, to which access() answers yes on /proc), and that touches no
    // file another program may be writing at the output's own name.
    std::string probe = (folder / ".stipple-write-test-XXXXXX").string();
    std::vector<char> name(probe.begin(), probe.end());
    name.push_back('\0');
    const int fd = mkstemp(name.data());
    if (fd < 0) fail(named + ": cannot write there: " + std::string(std::strerror(errno)));
    close(fd);
    unlink(name.data());
}

}  // namespace stipple
