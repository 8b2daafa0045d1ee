#pragma once
// Small helpers the text writers (SVG, CSV, statistics) share: compact numbers, colours, escaping,
// and writing a file with a one-line error on failure.
#include <string>
#include <string_view>

#include <glm/vec3.hpp>

namespace stipple::plot {

// Appends value rounded to `decimals` places, without trailing zeros ("12.5", "3", "-0.25"), the
// shortest form that keeps the precision: file size is per dot.
void append_number(std::string& out, double value, int decimals);
std::string format_number(double value, int decimals);
// The decimals that write lengths to `fraction` of `unit_mm` (an image pixel on the page), at least `least`
// and at most 9: coordinates and radii keep their precision on a page of a few millimetres.
int decimals_for(double unit_mm, double fraction, int least);

// The text with ASCII letters in lower case: option values (--page, --fit, --dot-style) in any case.
std::string lower_ascii(std::string text);

// "#rrggbb" of a colour in [0,1].
std::string hex_colour(glm::vec3 colour);

// Text safe inside an XML attribute value.
std::string xml_escape(std::string_view text);

// Writes `contents` to `path`; throws stipple::Error "<path>: cannot write: <reason>" on failure.
void write_text_file(const std::string& path, std::string_view contents);

}  // namespace stipple::plot
