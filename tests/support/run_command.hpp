#pragma once
// Runs the stipple executable as a user would, capturing exit status, stdout and stderr.
#include <string>
#include <vector>

namespace stipple::test {

struct CommandResult {
    int exit_code = -1;
    std::string out;
    std::string err;
};

// Arguments are quoted for the shell; runs `<build>/stipple args...`.
CommandResult run_stipple(const std::vector<std::string>& args);

}  // namespace stipple::test
