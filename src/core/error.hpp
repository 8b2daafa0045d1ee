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

// `text` as one printable line: line breaks become "; ", other control characters '?'. Library messages
// may span lines and quote file bytes.
std::string one_line(const std::string& text);

// The start of `text` for a message: one printable line of its first `most` characters, "..." where cut
// (a quoted file name, script line or data: URI can be megabytes long). quoted_excerpt puts it in quotes.
std::string excerpt(const std::string& text, size_t most);
std::string quoted_excerpt(const std::string& text, size_t most);

// "<path>: <problem>", the shape of every input error, made one printable line (a name read from the
// file may hold a line break: a Draco or instancing attribute's did, found by fuzzing on 2026-12-04).
[[noreturn]] void fail_file(const std::string& path, const std::string& problem);
[[noreturn]] void fail(const std::string& message);

// Checks that hold in release builds too (unlike assert): internal invariants.
#define STIPPLE_CHECK(cond, msg)                                                        \
    do {                                                                                \
        if (!(cond)) ::stipple::fail(std::string("internal check failed: ") + (msg) + \
                                     " (" #cond ") at " __FILE__);                      \
    } while (0)

}  // namespace stipple
