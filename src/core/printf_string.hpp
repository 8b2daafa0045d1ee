#pragma once
// printf-style formatting into a std::string (any length), for the reports and tables the benchmark prints.
#include <cstdio>
#include <string>

namespace stipple {

template <typename... Args>
std::string printf_string(const char* fmt, Args... args) {
    const int length = std::snprintf(nullptr, 0, fmt, args...);
    if (length <= 0) return {};
    std::string text(size_t(length), '\0');
    std::snprintf(text.data(), text.size() + 1, fmt, args...);
    return text;
}

}  // namespace stipple
