#pragma once
// The benchmark's plot-order row (issue 15): how fast the plotter order is and how close to its lower
// bound its pen-up travel comes, on 150k blue-noise dots and on the visible stipples of the bunny's
// default view. The figures are measured by the caller (src/cli/cmd_bench_plot.cpp, which may reach the
// export and the frame capture) and written here with the rest of the results.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace stipple::bench {

struct PlotOrderFigures {
    size_t dots = 0;
    double order_seconds = 0.0;    // blue noise: plot_order; the bunny: make_plot_plan (order, lines, page)
    double travel_ratio = 0.0;     // pen-up travel between dots / the sum of nearest-neighbour distances
    double random_ratio = 0.0;     // the same for a random order (blue noise only, else 0)
    double capture_seconds = 0.0;  // the bunny: the frame that records its visible stipples (else 0)
};

struct PlotOrderRow {
    std::optional<PlotOrderFigures> blue_noise;
    std::optional<PlotOrderFigures> bunny_view;
    std::string bunny_note;  // why there is no bunny figure, when there is none
    uint32_t validation_messages = 0;  // during the bunny's capture (its own Vulkan context)
};

// The row as a Markdown section (printed and in results.md).
std::string plot_order_markdown(const PlotOrderRow& row);

}  // namespace stipple::bench
