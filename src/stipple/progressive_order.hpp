#pragma once
// Progressive order of each triangle's stipples (paper §2.1: at run time "only the number of
// stipples per polygon varies"; a triangle drawn at density fraction f keeps its first stipples).
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace stipple {

// Reorders the stipples of every triangle t, positions[first[t] .. first[t+1]), so that for every
// fraction f the stipples kept at f (index k with k + 0.5 < f * N_t, in every triangle) are well
// spread over the whole surface, neighbouring triangles included.
//
// Slot k of triangle t appears at time tau = (k + 0.5) / N_t. Slots are filled in increasing tau
// (ties by triangle index); each takes, among the triangle's stipples not placed yet, the one
// farthest from every stipple already placed anywhere (greedy farthest point, searched within
// about 1.5 spacings of the placed set at that time). See progressive_order.cpp for how the
// surface is split into slabs, and time into windows, so that two threads can do this
// deterministically, and for the triangles too large for a slab, which are ordered in pieces (each
// piece a unit with its own (k + 0.5) / N times) and merged.
// `spacing` is the hexagonal spacing of the full set. Deterministic for any thread count.
// With `coarse_classes`, each triangle's first coarse_count(N) stipples as given are its coarse class
// (stipple_classes.hpp): its first coarse_count(N) slots are filled from them and the later slots from the
// others.
void progressive_order(std::vector<glm::vec3>& positions, std::span<const uint32_t> first, double spacing,
                       uint64_t seed, const std::function<void(double)>& progress = {}, bool coarse_classes = false);

}  // namespace stipple
