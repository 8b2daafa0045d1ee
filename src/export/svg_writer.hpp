#pragma once
// The plot as SVG, written directly (cairo's SVG has no layers).
//
// The page is width/height in mm with a viewBox in mm, so one user unit is one millimetre.
// Each layer is an Inkscape layer (<g inkscape:groupmode="layer" inkscape:label="1 bunny stipples">)
// carrying the styles (fill, stroke, pen width), so a dot is only its geometry: a <circle> with
// centre to 0.01 mm and radius to 0.001 mm (about 42 bytes), or for tick dots one "M x y h L"
// subpath of a shared <path>. Elements follow the plot order; the plotter draws them as listed.
#include <string>

#include "export/plot_plan.hpp"

namespace stipple::plot {

// with_travel adds the pen-up moves as thin light-red lines in a plain group (not a layer), to
// look at the plot order; leave it off for a file that goes to a plotter.
std::string svg_document(const PlotPlan& plan, bool with_travel = false);
// Writes svg_document(plan, plan.show_travel).
void write_svg(const PlotPlan& plan, const std::string& path);

}  // namespace stipple::plot
