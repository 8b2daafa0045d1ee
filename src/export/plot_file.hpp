#pragma once
// Writing a plot by the output's extension: .svg, .pdf or .csv (any case). The entry point for
// `stipple render -o drawing.svg` and the viewer's export button.
#include <string>

#include "export/plot_plan.hpp"

namespace stipple::plot {

// Whether `path` names a vector or dot output (rather than an image).
bool is_plot_path(const std::string& path);
bool is_svg_path(const std::string& path);
bool is_csv_path(const std::string& path);
bool is_png_path(const std::string& path);

// The largest page side a PDF can have: ISO 32000 (Annex C) limits a page to 14,400 units of 1/72 in,
// 200 in; readers refuse or clamp larger pages. An SVG has no such limit.
inline constexpr double kPdfMaxPageMm = 5080.0;

// Throws stipple::Error naming `path` when its format cannot hold a page of this size (a PDF beyond
// kPdfMaxPageMm a side).
void check_page_for_format(const std::string& path, double width_mm, double height_mm);

// Writes the plan in the format the extension names; a path with another extension throws
// stipple::Error naming it.
void write_plot_file(const PlotPlan& plan, const std::string& path);

}  // namespace stipple::plot
