#pragma once
// The dots as CSV for people who post-process them: a header line
// "x_mm,y_mm,radius_mm,object,polygon", then one line per dot in plot order, coordinates and
// radius (the ink radius, see plot_plan.hpp) in page millimetres to 0.001 mm, the object's index
// in the drawing and the polygon the stipple lies on.
#include <string>

#include "export/plot_plan.hpp"

namespace stipple::plot {

std::string csv_document(const PlotPlan& plan);
void write_csv(const PlotPlan& plan, const std::string& path);

}  // namespace stipple::plot
