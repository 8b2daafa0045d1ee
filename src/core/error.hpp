#pragma once
// Errors that reach the user: one line, naming the file (where there is one) and the problem.
// Everything a user can cause (bad model, bad scene, bad parameter) throws stipple::Error;
// main() prints what() on one line and exits non-zero. Never a bare assert for these.
#include <stdexcept>
#include <string>

namespace stipple {

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

// "<path>: <problem>", the shape of every input error.
[[noreturn]] void fail_file(const std::string& path, const std::string& problem);
[[noreturn]] void fail(const std::string& message);

// Checks that hold in release builds too (unlike assert): internal invariants.
#define STIPPLE_CHECK(cond, msg)                                                        \
    do {                                                                                \
        if (!(cond)) ::stipple::fail(std::string("internal check failed: ") + (msg) + \
                                     " (" #cond ") at " __FILE__);                      \
    } while (0)

}  // namespace stipple
