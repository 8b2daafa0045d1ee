#include "export/order_speed.hpp"

#include <algorithm>
#include <chrono>
#include <numeric>
#include <random>

#include "export/blue_noise.hpp"
#include "export/dot_order.hpp"
#include "export/neighbours.hpp"

namespace stipple::plot {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

}  // namespace

OrderSpeed measure_order_speed(size_t count) {
    const double width = 190.0, height = 277.0;  // an A4 page inside its margins
    const glm::dvec2 pen(0.0);
    OrderSpeed s;
    s.spacing_mm = poisson_disc_spacing(width, height, count);
    auto start = Clock::now();
    s.points = poisson_disc_points(width, height, s.spacing_mm, 1);
    s.generate_s = seconds_since(start);

    // The steps one by one, then plot_order as the export calls it (which repeats them).
    start = Clock::now();
    const NeighbourLists lists = nearest_neighbours(s.points, 8);
    s.lists_s = seconds_since(start);
    start = Clock::now();
    std::vector<uint32_t> order = nearest_neighbour_tour(s.points, lists, pen);
    s.tour_s = seconds_since(start);
    s.tour_mm = travel_length(s.points, order, pen);
    start = Clock::now();
    s.moves = improve_path(s.points, lists, order);
    s.improve_s = seconds_since(start);
    s.improved_mm = travel_length(s.points, order, pen);

    start = Clock::now();
    const std::vector<uint32_t> full = plot_order(s.points, pen);
    s.plot_order_s = seconds_since(start);
    s.plot_order_mm = travel_length(s.points, full, pen);
    s.bound_mm = nearest_neighbour_bound(s.points);

    std::vector<uint32_t> shuffled(s.points.size());
    std::iota(shuffled.begin(), shuffled.end(), 0u);
    std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(7));
    s.random_mm = travel_length(s.points, shuffled, pen);
    return s;
}

}  // namespace stipple::plot
