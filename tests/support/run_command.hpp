#pragma once
// Runs the stipple executable as a user would, capturing exit status, stdout and stderr.
#include <sys/resource.h>

#include <csignal>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

namespace stipple::test {

struct CommandResult {
    int exit_code = -1;
    std::string out;
    std::string err;
};

// Arguments are quoted for the shell; runs `<build>/stipple args...`. `shell_prefix`, when given, is
// shell text put before the command as it stands: "timeout 60" (a command that would hang fails the test
// instead, with status 124), "ulimit -v 2000000;" (memory a command may map).
CommandResult run_stipple(const std::vector<std::string>& args, const std::string& shell_prefix = "");

// An environment variable set for the guard's life (the commands run meanwhile see it), then restored to what
// it was before, or unset if it was not set.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const std::string& value) : name_(name) {
        if (const char* before = std::getenv(name)) before_ = before;
        ::setenv(name, value.c_str(), 1);
    }
    ~ScopedEnv() {
        if (before_) ::setenv(name_.c_str(), before_->c_str(), 1);
        else ::unsetenv(name_.c_str());
    }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

private:
    std::string name_;
    std::optional<std::string> before_;
};

// The process's file-size limit (ulimit -f) at `bytes` for the guard's life, with SIGXFSZ ignored (as stipple's
// main does), so that a write beyond it fails with EFBIG: a full disk in miniature, for the writers' tests.
class ScopedFileSizeLimit {
public:
    explicit ScopedFileSizeLimit(rlim_t bytes) {
        ::getrlimit(RLIMIT_FSIZE, &before_);
        signal_before_ = std::signal(SIGXFSZ, SIG_IGN);
        struct rlimit limited = before_;
        limited.rlim_cur = bytes;
        ::setrlimit(RLIMIT_FSIZE, &limited);
    }
    ~ScopedFileSizeLimit() {
        ::setrlimit(RLIMIT_FSIZE, &before_);
        std::signal(SIGXFSZ, signal_before_);
    }
    ScopedFileSizeLimit(const ScopedFileSizeLimit&) = delete;
    ScopedFileSizeLimit& operator=(const ScopedFileSizeLimit&) = delete;

private:
    struct rlimit before_ {};
    void (*signal_before_)(int) = SIG_DFL;
};

// The names in `folder` (files a failed write could have left behind), sorted.
std::vector<std::string> folder_entries(const std::string& folder);

}  // namespace stipple::test
