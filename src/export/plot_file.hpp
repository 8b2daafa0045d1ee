#pragma once
// Writing a plot by the output's extension: .svg, .pdf or .csv (any case). The entry point for
// `stipple render -o drawing.svg` and the viewer's export button.
#include <string>

#include "export/plot_plan.hpp"

namespace stipple::plot {

// Whether `path` names a vector or dot output (rather than an image).
bool is_plot_path(const std::string& path);
bool is_svg_path(const std::string& path);
bool is_png_path(const std::string& path);

// Writes the plan in the format the extension names; a path with another extension throws
// stipple::Error naming it.
void write_plot_file(const PlotPlan& plan, const std::string& path);

}  // namespace stipple::plot
