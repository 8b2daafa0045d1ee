#pragma once
// The fixed per-polygon values of the probabilistic polygon selection (paper §2.3).
#include <cstdint>
#include <vector>

#include "mesh/mesh.hpp"
#include "stipple/stipple_set.hpp"

namespace stipple {

// One value in [0, 1) per triangle, from its rank in a progressive blue-noise order of one site per
// triangle (its centroid here; the stipple it draws when selected in the overload below). A polygon is
// drawn when its value is below its selection probability p, so the selected polygons are an early
// part of that order: spread evenly over the surface, like the paper's "every Nth polygon" of a strip,
// in any mesh. (An independent random value per polygon, the paper's
// fallback, clumps: clumped stipples overlap and read lighter.) The order comes from dart throwing at
// halving areas: at each level the centroids farther than the level's Poisson-disc radius from every
// centroid already ranked get the next ranks. The values are then made exactly uniform among triangles
// of about the same area (and, in the overload below, the same small candidate count), keeping that
// order, so that P(value < p) = p for a triangle of any size and count on a mesh of any mix of sizes
// (see the .cpp); a triangle of no weight (no candidate, or no area where counts are not known) never draws,
// and holds the last value without being ranked. Values are multiples of 2^-24, so C++ and GLSL compare
// them exactly. Deterministic for a seed.
std::vector<float> polygon_selection_values(const Mesh& mesh, uint64_t seed = 1);

// The same, ranking each triangle by the stipple it draws when selected (its first candidate; its
// centroid when it has none) instead of its centroid: the dots drawn by the selected polygons are
// then the evenly spread ones, not the polygons' centres, which a dot may lie a polygon's width from
// (see the .cpp).
std::vector<float> polygon_selection_values(const Mesh& mesh, const StippleSet& stipples, uint64_t seed);

}  // namespace stipple
