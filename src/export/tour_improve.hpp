#pragma once
// Local improvement of a pen path through dots: 2-opt and Or-opt moves over neighbour lists.
//
// The path's two ends are free: it is improved as a closed tour through the dots plus one virtual
// point at distance 0 from all (cutting the tour there gives back a path), so a move may also
// change where the path starts and ends. Moves are first-improvement, driven by a queue of points
// whose surroundings changed ("don't-look bits"); a 2-opt move reverses the shorter side of the
// tour, an Or-opt move shifts the shorter arc, so each costs what the shorter side has.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

#include "export/neighbours.hpp"

namespace stipple::plot {

struct ImproveCounts {
    size_t two_opt_moves = 0, or_opt_moves = 0;
};

// order: a permutation of the point indices (the path), improved in place.
ImproveCounts improve_path(std::span<const glm::dvec2> points, const NeighbourLists& neighbours, std::vector<uint32_t>& order);

}  // namespace stipple::plot
