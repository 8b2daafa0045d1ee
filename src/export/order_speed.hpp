#pragma once
// The plotter order's speed and quality on a blue-noise dot set (the projection of a stippled
// surface on an A4-sized field): each step timed, each path's pen-up travel against its lower bound
// (the sum of the nearest-neighbour distances). Shared by tools/plot_order_speed and `stipple bench`
// (its plot-order row), which print the figures; the tests assert the quality, never the time.
#include <cstddef>
#include <vector>

#include <glm/vec2.hpp>

#include "export/tour_improve.hpp"

namespace stipple::plot {

struct OrderSpeed {
    std::vector<glm::dvec2> points;  // the dots (mm)
    double spacing_mm = 0.0;
    double generate_s = 0.0;    // the blue-noise set
    double lists_s = 0.0;       // neighbour lists (k-d tree, k = 8)
    double tour_s = 0.0;        // nearest-neighbour tour
    double improve_s = 0.0;     // 2-opt + Or-opt on it
    double plot_order_s = 0.0;  // plot_order, all steps (what the export runs)
    ImproveCounts moves;
    double tour_mm = 0.0, improved_mm = 0.0, plot_order_mm = 0.0, random_mm = 0.0;  // pen-up travel
    double bound_mm = 0.0;  // its nearest-neighbour lower bound

    double ratio() const { return bound_mm > 0.0 ? plot_order_mm / bound_mm : 0.0; }  // plot_order's
};

// About `count` dots (Poisson-disc, seed 1) on a 190 x 277 mm field, the pen starting at the origin.
OrderSpeed measure_order_speed(size_t count);

}  // namespace stipple::plot
