#include "export/page.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <utility>

#include "core/error.hpp"
#include "export/text_format.hpp"

namespace stipple::plot {

namespace {

constexpr const char* kAcceptedPages = "expected A3, A4, A5, letter, legal or WxHmm, optionally -portrait or -landscape";

bool ends_with(const std::string& text, const std::string& suffix) {
    return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// A positive finite millimetre figure spanning the whole of `text`, or a negative value.
double parse_length(const std::string& text) {
    double value = -1.0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    // Beyond a double's range (1e400, 1e-400): too large or too small, not "not a number" (strtod: inf, or 0
    // for a positive number too small, taken as the smallest).
    if (ec == std::errc::result_out_of_range && ptr == end) {
        value = std::strtod(text.c_str(), nullptr);
        if (value == 0.0 && text.front() != '-') value = std::numeric_limits<double>::min();
    } else if (ec != std::errc() || ptr != end) return -1.0;
    if (std::isnan(value) || value <= 0.0) return -1.0;
    return value;
}

// Shortest round-trip form ("10", "12.5"), for messages.
std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

[[noreturn]] void bad_page(const std::string& name, const std::string& why) {
    fail("--page '" + name + "': " + why + " (" + kAcceptedPages + ")");
}

}  // namespace

PageSize parse_page(const std::string& name) {
    std::string size = lower_ascii(name);
    if (size.find_first_of(" \t") != std::string::npos) bad_page(name, "no spaces: write it as one word, e.g. 210x297mm");
    enum class Orientation { AsGiven, Portrait, Landscape } orientation = Orientation::AsGiven;
    if (ends_with(size, "-landscape")) {
        orientation = Orientation::Landscape;
        size.resize(size.size() - 10);
    } else if (ends_with(size, "-portrait")) {
        orientation = Orientation::Portrait;
        size.resize(size.size() - 9);
    }

    PageSize page;
    if (size == "a3") page = {297.0, 420.0};
    else if (size == "a4") page = {210.0, 297.0};
    else if (size == "a5") page = {148.0, 210.0};
    else if (size == "letter") page = {215.9, 279.4};
    else if (size == "legal") page = {215.9, 355.6};
    else if (ends_with(size, "mm") && size.find('x') != std::string::npos) {
        const std::string dims = size.substr(0, size.size() - 2);
        const size_t x = dims.find('x');
        page.width_mm = parse_length(dims.substr(0, x));
        page.height_mm = parse_length(dims.substr(x + 1));
        if (page.width_mm <= 0.0 || page.height_mm <= 0.0) bad_page(name, "width and height must be positive numbers");
        // Below a centimetre a dot of the default pen (0.3 mm) is a tenth of the page; 1e-300 mm drew nothing.
        if (page.width_mm < 10.0 || page.height_mm < 10.0) bad_page(name, "smaller than 10 mm a side");
        // Beyond any plotter or printer; mostly a typo (metres instead of millimetres).
        if (page.width_mm > 10000.0 || page.height_mm > 10000.0) bad_page(name, "larger than 10 m");
        page.orientation_given = true;  // the width and height as written
    } else {
        bad_page(name, "unknown page size");
    }

    page.orientation_given = page.orientation_given || orientation != Orientation::AsGiven;
    const bool landscape = page.width_mm > page.height_mm;
    if ((orientation == Orientation::Landscape && !landscape) || (orientation == Orientation::Portrait && landscape))
        std::swap(page.width_mm, page.height_mm);
    return page;
}

PageSize oriented_for(PageSize page, double width, double height) {
    if (page.orientation_given) return page;
    const bool landscape_page = page.width_mm > page.height_mm;
    if (landscape_page != (width > height)) std::swap(page.width_mm, page.height_mm);
    return page;
}

PageLayout fit_to_page(const PageSize& page, double margin_mm, glm::dvec2 min_px, glm::dvec2 max_px) {
    const double width_px = max_px.x - min_px.x, height_px = max_px.y - min_px.y;
    if (!(width_px > 0.0 && std::isfinite(width_px)) || !(height_px > 0.0 && std::isfinite(height_px))) fail("page layout: the drawing has no size (" + number(width_px) + "x" + number(height_px) + " px)");
    if (!std::isfinite(margin_mm) || margin_mm < 0.0) fail("--margin " + number(margin_mm) + ": must be 0 or more millimetres");
    const double inner_w = page.width_mm - 2.0 * margin_mm, inner_h = page.height_mm - 2.0 * margin_mm;
    if (inner_w <= 0.0 || inner_h <= 0.0)
        fail("--margin " + number(margin_mm) + ": leaves no room on a " + number(page.width_mm) + "x" +
             number(page.height_mm) + " mm page");

    PageLayout layout;
    layout.page = page;
    layout.margin_mm = margin_mm;
    layout.mm_per_px = std::min(inner_w / width_px, inner_h / height_px);
    const glm::dvec2 centre_px = 0.5 * (min_px + max_px);
    layout.offset_mm = glm::dvec2(page.width_mm, page.height_mm) / 2.0 - centre_px * layout.mm_per_px;
    return layout;
}

}  // namespace stipple::plot
