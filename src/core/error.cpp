#include "core/error.hpp"

namespace stipple {

std::string one_line(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '\n' || c == '\r') {
            if (!out.empty() && out.back() != ' ') out += "; ";
        } else {
            out += static_cast<unsigned char>(c) < 0x20 ? '?' : c;
        }
    }
    while (!out.empty() && (out.back() == ' ' || out.back() == ';')) out.pop_back();
    return out;
}

void fail_file(const std::string& path, const std::string& problem) { throw Error(one_line(path + ": " + problem)); }

void fail(const std::string& message) { throw Error(one_line(message)); }

}  // namespace stipple
