#pragma once
// What a plot costs: the figures `--stats` prints.
//
// Pen-up travel is every move with the pen lifted, from the home corner through all layers in
// order (the way back home is not counted). Its lower bound is taken over the dots only, where
// the travel is: within a layer the pen reaches each dot but the first from another dot, at least
// that dot's distance to its nearest neighbour in the layer; the ratio compares the travel between
// dots with the sum of those distances (1 would be a perfect path; generation order is tens to
// hundreds of times over it). Pen-down length counts strokes and dots as drawn in the plan's dot
// style (a filled dot by its outline, which is what a plotter draws of it).
#include <cstddef>
#include <string>

#include "export/plot_plan.hpp"

namespace stipple::plot {

struct PlotStats {
    PageSize page;          // the page as laid out (a bare named size turned to the drawing)
    Fit fit = Fit::Drawing;  // what was fitted to it
    size_t dots = 0, polylines = 0, pen_lifts = 0;
    size_t small_dots = 0;  // dots under the pen's least mark, drawn as it by chance (plot_plan.hpp); those drawn are in dots
    size_t capped_ticks = 0;   // tick style: ticks at their longest (kMaxTickDiameters), inking less than their dots
    double tick_ink_short = 0.0;  // their ink left out, as a share of all the dots' ink
    double pen_down_mm = 0.0, pen_up_mm = 0.0;
    double dot_travel_mm = 0.0;        // pen-up travel between dots of one layer
    double dot_travel_bound_mm = 0.0;  // its nearest-neighbour lower bound
    double travel_ratio() const { return dot_travel_bound_mm > 0.0 ? dot_travel_mm / dot_travel_bound_mm : 1.0; }
};

PlotStats plot_stats(const PlotPlan& plan);

// One line: "plot: 12345 dots, 67 polylines, pen down 1234.5 mm, pen up 2345.6 mm, 12412 pen lifts,
// travel between dots 1.11x its lower bound".
std::string format_stats(const PlotStats& stats);

}  // namespace stipple::plot
