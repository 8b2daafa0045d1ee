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

// Six-fold bond-orientational order (psi_6) of points lying in a plane with unit normal `normal`:
// psi_6(p) is the mean of exp(6 i theta) over p's 6 nearest neighbours, theta each bond's angle in
// the plane. Neighbourhoods are centred only on points at least `margin` (a fraction of the points'
// bounding square) inside its edges, where a border would bias them.
//   local: the mean of |psi_6(p)|: how hexagonal each neighbourhood is (1 on a hexagonal lattice,
//     about 0.36 for uniform random points, 0.41 for dart throwing).
//   windowed: the bounding square cut into windows x windows; the mean over windows of |mean of
//     psi_6 in the window|: orientational order that persists across a window, the hexagonal domains
//     of a crystallised set (1 on a lattice; near 0, falling as 1/sqrt(points per window), for
//     isotropic sets: 0.05 for dart throwing with ~400 points per window).
struct HexagonalOrder {
    double local = 0.0;
    double windowed = 0.0;
};
HexagonalOrder hexagonal_order(const std::vector<glm::vec3>& points, const glm::vec3& normal, int windows = 8,
                               double margin = 0.1);

// The stipples a triangle keeps at density fraction f (paper §2.1: only the number of stipples per
// polygon varies at run time): those with index k such that k + 0.5 < f * N_t, in every triangle.
std::vector<glm::vec3> prefix_at_fraction(const StippleSet& stipples, double fraction);

}  // namespace stipple
