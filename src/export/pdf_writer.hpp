#pragma once
// The plot as a one-page PDF through cairo: the page in points (the page's mm times 72/25.4),
// the same dots, strokes and colours as the SVG, in plot order. Each layer is painted as a group
// of its own (a form XObject in the file); cairo 1.16 cannot write PDF optional-content layers.
#include <string>

#include "export/plot_plan.hpp"

namespace stipple::plot {

void write_pdf(const PlotPlan& plan, const std::string& path);

}  // namespace stipple::plot
