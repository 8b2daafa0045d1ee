#include "export/plot_stats.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "export/neighbours.hpp"
#include "export/text_format.hpp"

namespace stipple::plot {

namespace {

double dot_pen_down(const PlotDot& dot, DotStyle style, double pen_mm) {
    switch (style) {
        case DotStyle::Filled: return 2.0 * std::numbers::pi * dot.radius_mm;
        case DotStyle::Circle: return 2.0 * std::numbers::pi * circle_stroke_radius(dot.radius_mm, pen_mm);
        case DotStyle::Tick: return tick_length(dot.radius_mm, pen_mm);
    }
    return 0.0;
}

// Sum over the layer's dots but its first of the distance to their nearest neighbour.
double dot_travel_bound(const std::vector<PlotDot>& dots) {
    if (dots.size() < 2) return 0.0;
    std::vector<glm::dvec2> points;
    points.reserve(dots.size());
    for (const PlotDot& dot : dots) points.push_back(dot.mm);
    const NeighbourLists nearest = nearest_neighbours(points, 1);
    double bound = 0.0;
    for (size_t i = 1; i < points.size(); ++i) bound += glm::length(points[nearest.indices[i]] - points[i]);
    return bound;
}

}  // namespace

PlotStats plot_stats(const PlotPlan& plan) {
    PlotStats stats;
    stats.page = plan.layout.page;
    stats.fit = plan.fit;
    stats.small_dots = plan.small_dots;
    glm::dvec2 pen = plan.home;
    double dots_ink = 0.0, ink_short = 0.0;
    for (const PlotLayer& layer : plan.layers) {
        for (size_t i = 0; i < layer.dots.size(); ++i) {
            const std::array<glm::dvec2, 2> ends = dot_stroke_ends(layer.dots[i], plan.dot_style, layer.stroke_mm);
            stats.pen_up_mm += glm::length(ends[0] - pen);
            // The order's own figure: between the dots' centres, as its lower bound is.
            if (i > 0) stats.dot_travel_mm += glm::length(layer.dots[i].mm - layer.dots[i - 1].mm);
            stats.pen_down_mm += dot_pen_down(layer.dots[i], plan.dot_style, layer.stroke_mm);
            pen = ends[1];
            const double r = layer.dots[i].radius_mm;
            dots_ink += std::numbers::pi * r * r;
            if (plan.dot_style == DotStyle::Tick) {
                const double short_by = tick_ink_short(r, layer.stroke_mm);
                ink_short += short_by;
                stats.capped_ticks += short_by > 0.0;
            }
        }
        stats.dots += layer.dots.size();
        stats.dot_travel_bound_mm += dot_travel_bound(layer.dots);
        for (const Polyline& line : layer.lines) {
            if (line.points.empty()) continue;
            stats.pen_up_mm += glm::length(line.points.front() - pen);
            stats.pen_down_mm += polyline_length(line);
            pen = line.closed ? line.points.front() : line.points.back();
            ++stats.polylines;
        }
    }
    stats.pen_lifts = stats.dots + stats.polylines;
    stats.tick_ink_short = dots_ink > 0.0 ? ink_short / dots_ink : 0.0;
    return stats;
}

std::string format_stats(const PlotStats& stats) {
    return "plot: " + std::to_string(stats.dots) + " dots, " + std::to_string(stats.polylines) + " polylines, pen down " +
           format_number(stats.pen_down_mm, 1) + " mm, pen up " + format_number(stats.pen_up_mm, 1) + " mm, " +
           std::to_string(stats.pen_lifts) + " pen lifts, " +
           // With no two dots in a layer there is no travel between dots to rate (it said "1x its lower bound (0 mm)").
           (stats.dot_travel_bound_mm > 0.0 ? "travel between dots " + format_number(stats.travel_ratio(), 2) + "x its lower bound (" +
                                                  format_number(stats.dot_travel_bound_mm, 1) + " mm)"
            : stats.dot_travel_mm > 0.0     ? "travel between dots " + format_number(stats.dot_travel_mm, 1) + " mm (dots on each other)"
                                            : std::string("no travel between dots")) +
           (stats.small_dots ? ", " + std::to_string(stats.small_dots) + " dots under the pen's least mark drawn as it by chance" : "") +
           (stats.capped_ticks ? ", " + std::to_string(stats.capped_ticks) + " ticks at their longest (twice their dot's width), " +
                                     format_number(100.0 * stats.tick_ink_short, 1) +
                                     "% of the dots' ink short: a wider --pen-width or --dot-style filled keeps it"
                               : "");
}

}  // namespace stipple::plot
