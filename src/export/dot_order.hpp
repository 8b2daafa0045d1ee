#pragma once
// The order a plotter draws dots in: a nearest-neighbour tour improved by 2-opt and Or-opt.
//
// Dots in generation order send the pen back and forth across the page (tens of times the travel
// it needs); a nearest-neighbour tour from the pen's position is about 25% over the best path, and
// the local moves of tour_improve.hpp take most of that back. Neighbour lists come from a
// nanoflann k-d tree; the tour's "nearest unvisited dot" from the dot's own list while one of its
// neighbours is unvisited, else from a NearestAliveGrid.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

#include "export/neighbours.hpp"

namespace stipple::plot {

struct OrderOptions {
    uint32_t neighbours = 8;  // candidate list length for the tour and the moves
    bool improve = true;      // false: the plain nearest-neighbour tour
};

// Visiting order (indices into points) of a path starting near `pen`: its first dot is nearer to
// the pen than its last.
std::vector<uint32_t> plot_order(std::span<const glm::dvec2> points, glm::dvec2 pen, const OrderOptions& options = {});

// The plain tour: from the dot nearest the pen, always on to the nearest unvisited dot.
std::vector<uint32_t> nearest_neighbour_tour(std::span<const glm::dvec2> points, const NeighbourLists& neighbours, glm::dvec2 pen);

// Pen-up travel of a path: from `pen` to the first dot, then dot to dot.
double travel_length(std::span<const glm::dvec2> points, std::span<const uint32_t> order, glm::dvec2 pen);

}  // namespace stipple::plot
