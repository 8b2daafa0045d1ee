#pragma once
// Whole-surface relaxation of random stipples toward a Poisson-disc distribution (paper §2.1:
// "generated randomly within the polygon and then redistributed to approximate a Poisson-disc
// distribution").
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "mesh/mesh.hpp"

namespace stipple {

// Moves every stipple away from its neighbours within its own triangle's plane, `iterations`
// times. Stipple i belongs to triangle triangle_of[i] of `mesh` and stays inside it. `spacing` is
// the hexagonal-packing spacing at the stipple density (neighbours within 2 * spacing repel).
// Deterministic for any thread count (Gauss-Seidel iterations within fixed chunks, Jacobi between them).
// `progress`, if set, is called with the fraction done after each iteration.
// It works on copies in spatial order and frees `positions` meanwhile (a stipple costs 34-36 bytes at
// the peak instead of 64: its position and triangle, 16, and the grid's copy of the position, input
// index and bucket starts, 18-20); they hold the relaxed stipples when it returns. It takes `triangle_of`
// (derivable from the triangles' counts, which is how the caller gets it back). `input_again`
// returns `positions` as they were given (the caller's generation is deterministic and cheap): the
// input's spatial order is sorted again at the end to put the stipples back in their order, instead
// of keeping an index of 4 bytes a stipple through the iterations.
//
// Multi-class relaxation (Wei, "Multi-class blue noise sampling", 2010): a stipple whose triangle_of entry
// carries kCoarseClass belongs to the coarse class, the stipples a triangle keeps at a quarter of its
// density (stipple_classes.hpp), which the caller has relaxed as a set of its own already. With
// `coarse_fixed`, it stays where it is while the others are relaxed around it for `iterations`, then all
// are relaxed kFreeIterations more (the class at a smaller step): a view that draws a quarter of the
// stipples then sees a set nearly as even as the whole. (Relaxed together, each class stipple also pushed
// by the others at their own spacing, the classes fought: docs/paper-reading.md, §2.1.)
// `start`, when set, moves the stipples to where the iterations begin, once they are in the relaxation's
// spatial order: pos[slot] is stipple original[slot], of triangle triangle[slot] & ~kCoarseClass.
// `positions`, as given, only set that order (input_again must return them, not the moved ones).
using RelaxStart = std::function<void(std::span<glm::vec3> pos, std::span<const uint32_t> original,
                                      std::span<const uint32_t> triangle)>;
void relax_stipples(const Mesh& mesh, std::vector<uint32_t>&& triangle_of, std::vector<glm::vec3>& positions,
                    double spacing, int iterations, const std::function<std::vector<glm::vec3>()>& input_again,
                    const std::function<void(double)>& progress = {}, bool coarse_fixed = false,
                    const RelaxStart& start = {});

// The flag on a triangle index that puts a stipple in the coarse class (triangle indices stay below it).
inline constexpr uint32_t kCoarseClass = 0x80000000u;
// The iterations after `iterations` with the coarse class fixed (see relax.cpp for the figures).
inline constexpr int kFreeIterations = 2;

// The point of triangle (a, b, c) closest to p, moved inside by a hair (barycentric coordinates
// at least 1e-5), so that a clamped stipple never lies on an edge shared with another triangle.
glm::vec3 clamp_into_triangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

}  // namespace stipple
