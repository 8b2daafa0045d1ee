#include "io/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <mutex>
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

// The temporary file being written (one at a time), removed if the process is interrupted before it is
// renamed into place: an interrupted render left "<name>.part-XXXXXX" beside its images.
char pending_temporary[4096];
std::atomic<bool> pending_set{false};

extern "C" void remove_pending_and_reraise(int sig) {
    if (pending_set.load()) unlink(pending_temporary);  // async-signal-safe
    std::signal(sig, SIG_DFL);
    std::raise(sig);
}

// Installed on first use, and only over the default action (a handler of someone else's, or an ignored
// signal, is left as it is).
void install_interrupt_cleanup() {
    static std::once_flag once;
    std::call_once(once, [] {
        for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
            struct sigaction current {};
            if (sigaction(sig, nullptr, &current) != 0 || current.sa_handler != SIG_DFL) continue;
            struct sigaction action {};
            action.sa_handler = remove_pending_and_reraise;
            sigemptyset(&action.sa_mask);
            sigaction(sig, &action, nullptr);
        }
    });
}

// Marks `temporary` as the file to remove on an interruption, for the guard's life (where no other is marked).
class PendingTemporary {
public:
    explicit PendingTemporary(const std::string& temporary) {
        bool expected = false;
        if (temporary.size() >= sizeof pending_temporary || !pending_set.compare_exchange_strong(expected, true)) return;
        std::memcpy(pending_temporary, temporary.c_str(), temporary.size() + 1);
        owned_ = true;
    }
    ~PendingTemporary() {
        if (owned_) pending_set.store(false);
    }
    PendingTemporary(const PendingTemporary&) = delete;
    PendingTemporary& operator=(const PendingTemporary&) = delete;

private:
    bool owned_ = false;
};

// The mode a new file gets: 0666 less the process's umask (mkstemp makes its files 0600).
mode_t new_file_mode() {
    const mode_t mask = umask(0);
    umask(mask);
    return 0666 & ~mask;
}

// Runs `write` on `out`, then flushes it to the disk (`sync`) and closes it; a failure throws naming `path`.
void write_and_close(std::FILE* out, bool sync, const std::string& path, const std::string& what,
                     const std::function<void(std::FILE*)>& write) {
    try {
        write(out);
    } catch (...) {
        std::fclose(out);
        throw;
    }
    errno = 0;
    int error = std::fflush(out) == 0 && !std::ferror(out) ? 0 : (errno ? errno : EIO);
    if (!error && sync && fsync(fileno(out)) != 0) error = errno;
    if (std::fclose(out) != 0 && !error) error = errno ? errno : EIO;
    if (error) fail_file(path, what + ": " + std::strerror(error));
}

}  // namespace

void write_output(const std::string& path, const std::string& what, const std::function<void(std::FILE* out)>& write) {
    namespace fs = std::filesystem;
    const fs::path target(path);
    if (target.has_parent_path()) {
        std::error_code ec;
        fs::create_directories(target.parent_path(), ec);
        if (ec) fail_file(path, what + ": cannot create its folder: " + ec.message());
    }
    // Beside and renamed into place where the target is missing or a plain file of this user's alone. A link, a
    // pipe or a device is the user's to name and is written through, as before; so is a file with other hard
    // links or of another owner, whose links, owner and mode a new file would not keep.
    struct stat seen {};
    const bool exists = lstat(path.c_str(), &seen) == 0;
    if (!exists || (S_ISREG(seen.st_mode) && seen.st_nlink == 1 && seen.st_uid == geteuid())) {
        std::string temporary = path + ".part-XXXXXX";  // a name of its own, made without following links
        const int fd = mkstemp(temporary.data());
        if (fd >= 0) {
            install_interrupt_cleanup();
            const PendingTemporary pending(temporary);
            fchmod(fd, exists ? (seen.st_mode & 07777) : new_file_mode());
            std::FILE* out = fdopen(fd, "wb");
            if (!out) {
                close(fd);
                unlink(temporary.c_str());
                fail_file(path, what + ": " + std::strerror(errno));
            }
            try {
                write_and_close(out, true, path, what, write);
            } catch (...) {
                unlink(temporary.c_str());
                throw;
            }
            if (std::rename(temporary.c_str(), path.c_str()) == 0) return;
            // Not allowed to replace it (a sticky folder, a file bind-mounted on its own): written in place.
            unlink(temporary.c_str());
        }
        // No new file can be made beside it (a writable file in a folder that is not): written in place.
    }
    errno = 0;
    std::FILE* out = std::fopen(path.c_str(), "wb");
    if (!out) fail_file(path, what + ": " + std::strerror(errno));
    write_and_close(out, false, path, what, write);
}

void write_output(const std::string& path, const std::string& what, std::string_view bytes) {
    write_output(path, what, [&](std::FILE* out) {
        errno = 0;
        if (std::fwrite(bytes.data(), 1, bytes.size(), out) != bytes.size())
            fail_file(path, what + ": " + std::strerror(errno ? errno : EIO));
    });
}

}  // namespace stipple
