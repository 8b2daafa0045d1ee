#pragma once
// k nearest neighbours of every point of a fixed 2D set (a nanoflann k-d tree), for the plotter
// order's candidate lists and for the travel's lower bound.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

namespace stipple::plot {

// For each point, its (up to) k nearest other points, nearest first: row i is
// indices[i*k .. i*k+k), with count[i] valid entries (fewer only when the set has <= k points).
struct NeighbourLists {
    uint32_t k = 0;
    std::vector<uint32_t> indices;
    std::vector<uint8_t> count;

    std::span<const uint32_t> of(size_t i) const { return {indices.data() + i * k, count[i]}; }
};

NeighbourLists nearest_neighbours(std::span<const glm::dvec2> points, uint32_t k);

// Sum over the points of the distance to each one's nearest other point: no pen path that visits
// all of them and arrives at each from another of them can be shorter. 0 for fewer than 2 points.
double nearest_neighbour_bound(std::span<const glm::dvec2> points);

}  // namespace stipple::plot
