#include "io/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
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
    // Missing folders are made when the file is written, not here: a request refused after this check (a bad
    // animation name, a bad model) left an empty folder behind. The nearest folder that exists is tried instead.
    const fs::path wanted = file.has_parent_path() ? file.parent_path() : fs::path(".");
    // Walked up as the system will resolve it: "missing/../.." is "..", not ".".
    fs::path folder = (wanted.is_absolute() ? wanted : fs::current_path() / wanted).lexically_normal();
    for (;;) {
        std::error_code ec;
        const fs::file_status seen = fs::symlink_status(folder, ec);
        // Missing, or under a file (ENOTDIR: said below of that file); anything else is a loop of links, a name
        // too long or no permission.
        if (ec && ec != std::errc::no_such_file_or_directory && ec != std::errc::not_a_directory)
            fail(named + ": cannot make its folder " + wanted.string() + ": " + ec.message());
        if (fs::exists(seen)) {
            const fs::file_status target = fs::is_symlink(seen) ? fs::status(folder, ec) : seen;
            if (!fs::exists(target))
                fail(named + ": cannot make its folder " + wanted.string() + ": " + folder.string() + " is a link to nothing");
            if (!fs::is_directory(target))
                fail(named + ": cannot make its folder " + wanted.string() + ": " + folder.string() + " is not a folder");
            break;
        }
        if (!folder.has_parent_path() || folder.parent_path() == folder) break;
        folder = folder.parent_path();
    }
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

namespace {

// Writes `bytes` to `file`, naming `path` in the message on failure.
void write_bytes(const std::string& file, const std::string& path, const std::string& what, std::string_view bytes) {
    errno = 0;
    std::FILE* out = std::fopen(file.c_str(), "wb");
    if (!out) fail_file(path, what + ": " + std::strerror(errno));
    const size_t written = std::fwrite(bytes.data(), 1, bytes.size(), out);
    const int write_error = written == bytes.size() ? 0 : (errno ? errno : EIO);
    const int close_error = std::fclose(out) == 0 ? 0 : (errno ? errno : EIO);
    if (write_error || close_error) fail_file(path, what + ": " + std::strerror(write_error ? write_error : close_error));
}

}  // namespace

void write_output(const std::string& path, const std::string& what, const std::function<void(const std::string& file)>& write) {
    namespace fs = std::filesystem;
    const fs::path target(path);
    if (target.has_parent_path()) {
        std::error_code ec;
        fs::create_directories(target.parent_path(), ec);
        if (ec) fail_file(path, what + ": cannot create its folder: " + ec.message());
    }
    const std::string temporary = path + ".part-" + std::to_string(getpid());
    // The new file can be made beside the target (tried, as the writer may be a library that names no cause).
    const int probe = open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (probe < 0) {
        // In place, as before: the folder takes no new file, but the target may be writable. Tried first without
        // truncating it, for the cause (a library writer may name none).
        const int in_place = open(path.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0666);
        if (in_place < 0) fail_file(path, what + ": " + std::strerror(errno));
        close(in_place);
        write(path);
        return;
    }
    close(probe);
    try {
        write(temporary);
    } catch (...) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        throw;
    }
    std::error_code ec;
    fs::rename(temporary, target, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        fail_file(path, what + ": cannot move the new file into place: " + ec.message());
    }
}

void write_output(const std::string& path, const std::string& what, std::string_view bytes) {
    write_output(path, what, [&](const std::string& file) { write_bytes(file, path, what, bytes); });
}

}  // namespace stipple
