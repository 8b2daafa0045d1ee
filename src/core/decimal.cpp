#include "core/decimal.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>

namespace stipple {

namespace {

size_t digits(std::string_view text, size_t at) {
    size_t end = at;
    while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end]))) ++end;
    return end - at;
}

// The length of the sign, if there is one.
size_t sign(std::string_view text) { return !text.empty() && (text[0] == '+' || text[0] == '-') ? 1 : 0; }

bool is_decimal(std::string_view text) {
    size_t at = sign(text);
    const size_t whole = digits(text, at);
    at += whole;
    size_t fraction = 0;
    if (at < text.size() && text[at] == '.') {
        fraction = digits(text, at + 1);
        at += 1 + fraction;
    }
    if (whole + fraction == 0) return false;
    if (at < text.size() && (text[at] == 'e' || text[at] == 'E')) {
        at += 1;
        at += sign(text.substr(at));
        const size_t exponent = digits(text, at);
        if (exponent == 0) return false;
        at += exponent;
    }
    return at == text.size();
}

}  // namespace

std::optional<double> parse_decimal(std::string_view text) {
    if (!is_decimal(text)) return std::nullopt;
    const std::string copy(text);  // strtod needs a terminated string
    errno = 0;
    const double value = std::strtod(copy.c_str(), nullptr);
    if (!std::isfinite(value) || (errno == ERANGE && std::abs(value) > 1.0)) return std::nullopt;  // overflow
    return value;
}

std::optional<int64_t> parse_decimal_integer(std::string_view text) {
    const size_t at = sign(text);
    if (at == text.size() || digits(text, at) != text.size() - at) return std::nullopt;
    const std::string copy(text);
    errno = 0;
    const long long value = std::strtoll(copy.c_str(), nullptr, 10);
    if (errno == ERANGE) return std::nullopt;
    return static_cast<int64_t>(value);
}

std::optional<uint64_t> parse_byte_size(std::string_view text) {
    const char last = text.empty() ? '\0' : text.back();
    double unit = 1.0;
    if (last == 'k' || last == 'K') unit = 1024.0;
    else if (last == 'm' || last == 'M') unit = 1024.0 * 1024.0;
    else if (last == 'g' || last == 'G') unit = 1024.0 * 1024.0 * 1024.0;
    const std::optional<double> value = parse_decimal(unit > 1.0 ? text.substr(0, text.size() - 1) : text);
    const double bytes = value ? *value * unit : -1.0;
    if (!std::isfinite(bytes) || bytes < 0.0 || bytes > 1e18) return std::nullopt;
    return uint64_t(bytes);
}

}  // namespace stipple
