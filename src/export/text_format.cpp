#include "export/text_format.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "core/error.hpp"
#include "io/output_file.hpp"
#include "core/utf8.hpp"

namespace stipple::plot {

void append_number(std::string& out, double value, int decimals) {
    if (!std::isfinite(value)) value = 0.0;
    char text[64];
    const auto result = std::to_chars(text, text + sizeof text, value, std::chars_format::fixed, decimals);
    const char* end = result.ptr;
    if (decimals > 0) {
        while (end[-1] == '0') --end;
        if (end[-1] == '.') --end;
    }
    // Rounding can leave "-0", which is just 0.
    if (end - text == 2 && text[0] == '-' && text[1] == '0') {
        out += '0';
        return;
    }
    out.append(text, static_cast<size_t>(end - text));
}

int decimals_for(double unit_mm, double fraction, int least) {
    const double step = unit_mm * fraction;
    if (!(step > 0.0) || !std::isfinite(step)) return least;
    return std::clamp(int(std::ceil(-std::log10(step))), least, 9);
}

std::string format_number(double value, int decimals) {
    std::string out;
    append_number(out, value, decimals);
    return out;
}

std::string lower_ascii(std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

std::string hex_colour(glm::vec3 colour) {
    char text[8];
    const auto byte = [](float c) { return static_cast<unsigned>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f)); };
    std::snprintf(text, sizeof text, "#%02x%02x%02x", byte(colour.r), byte(colour.g), byte(colour.b));
    return text;
}

std::string xml_escape(std::string_view raw) {
    // A file name need not be UTF-8 (a Latin-1 name), and an XML file that is not does not parse.
    const std::string text = valid_utf8(raw);
    std::string out;
    for (const char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&apos;"; break;
            default:
                // Control characters are not allowed in XML 1.0; a name should not have them anyway.
                if (static_cast<unsigned char>(c) < 0x20) out += ' ';
                else out += c;
        }
    }
    return out;
}

void write_text_file(const std::string& path, std::string_view contents) { write_output(path, "cannot write", contents); }

}  // namespace stipple::plot
