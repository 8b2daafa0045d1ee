#include "export/dot_order.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "export/nearest_alive_grid.hpp"
#include "export/tour_improve.hpp"

namespace stipple::plot {

std::vector<uint32_t> nearest_neighbour_tour(std::span<const glm::dvec2> points, const NeighbourLists& neighbours, glm::dvec2 pen) {
    std::vector<uint32_t> order;
    order.reserve(points.size());
    if (points.empty()) return order;
    NearestAliveGrid unvisited(points);
    uint32_t current = unvisited.nearest(pen);
    while (current != NearestAliveGrid::kNone) {
        order.push_back(current);
        unvisited.remove(current);
        // The list is sorted by distance, so its first unvisited entry is the nearest unvisited dot.
        uint32_t next = NearestAliveGrid::kNone;
        for (const uint32_t candidate : neighbours.of(current))
            if (unvisited.alive(candidate)) {
                next = candidate;
                break;
            }
        current = next != NearestAliveGrid::kNone ? next : unvisited.nearest(points[current]);
    }
    return order;
}

std::vector<uint32_t> plot_order(std::span<const glm::dvec2> points, glm::dvec2 pen, const OrderOptions& options) {
    const NeighbourLists neighbours = nearest_neighbours(points, options.neighbours);
    std::vector<uint32_t> order = nearest_neighbour_tour(points, neighbours, pen);
    if (options.improve) improve_path(points, neighbours, order);
    if (order.size() > 1 && glm::length(points[order.back()] - pen) < glm::length(points[order.front()] - pen))
        std::reverse(order.begin(), order.end());
    return order;
}

double travel_length(std::span<const glm::dvec2> points, std::span<const uint32_t> order, glm::dvec2 pen) {
    double length = 0.0;
    for (const uint32_t i : order) {
        length += glm::length(points[i] - pen);
        pen = points[i];
    }
    return length;
}

}  // namespace stipple::plot
