#include "core/error.hpp"

#include <algorithm>

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

std::string excerpt(const std::string& text, size_t most) {
    // Cut before a UTF-8 continuation byte's sequence rather than through it (a name's last letter halved).
    size_t cut = std::min(most, text.size());
    if (cut < text.size())
        while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
    std::string out = one_line(text.substr(0, cut));
    if (text.size() > most) out += "...";
    return out;
}

// Appended in place: GCC 12 warns (-Wrestrict, a known false positive) on "'" + std::string&&.
std::string quoted_excerpt(const std::string& text, size_t most) {
    std::string out = "'";
    out += excerpt(text, most);
    out += "'";
    return out;
}

void fail_file(const std::string& path, const std::string& problem) { throw Error(one_line(path + ": " + problem)); }

void fail(const std::string& message) { throw Error(one_line(message)); }

}  // namespace stipple
