#pragma once
// Point-set quality: how evenly stipples are spread over a surface.
#include <vector>

#include <glm/glm.hpp>

#include "stipple/stipple_set.hpp"

namespace stipple {

// delta-bar: the mean nearest-neighbour distance divided by the hexagonal-packing spacing
// sqrt(2 / (sqrt(3) * N / surface_area)) of N points on that area. About 0.46 for uniform random
// points in 2D, 0.80 for dart throwing (Poisson disc), 1 for a perfect hexagonal lattice.
// Distances are 3D Euclidean, which matches the surface distance when spacing << curvature radius.
// Returns 0 for fewer than 2 points or a non-positive area.
double normalized_nn_distance(const std::vector<glm::vec3>& points, double surface_area);

// The stipples a triangle keeps at density fraction f (paper §2.1: only the number of stipples per
// polygon varies at run time): those with index k such that k + 0.5 < f * N_t, in every triangle.
std::vector<glm::vec3> prefix_at_fraction(const StippleSet& stipples, double fraction);

}  // namespace stipple
