#pragma once
// Polygons into triangles. A PLY face may have any number of corners, and CAD and modelling exports write
// concave ones (an L- or U-shaped face of a part). A fan around the first corner covers a concave polygon
// wrongly: its triangles reach outside it and overlap each other (a U-shaped face of area 5 loaded as
// area 7), so the model gets stipples where it has no surface and twice the tone where it is covered
// twice. The OBJ and PLY loaders both cut their polygons here.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace stipple {

// How many corner tests ear clipping may make for one polygon before it gives up (a polygon that crosses
// itself can leave no ear to find): a few seconds. A comb of 50,000 teeth (200k corners, half of them reflex)
// needed a fifth of it and one of 100,000 teeth more than there is (2026-12-03, when the clipping went back
// after each ear); a star of 500,000 points needs more than there is.
inline constexpr uint64_t kEarTestBudget = uint64_t(1) << 31;

// The n - 2 triangles of the polygon `corners` (indices into `positions`, n >= 3), written to `triangles`
// (3 * (n - 2) indices), each wound as the polygon is. A convex polygon is fanned around its first corner
// (what loaders did before, so convex faces load exactly as they did); a concave one is cut by ear
// clipping in the plane it spans (Newell's normal). Where no ear is left (a polygon that crosses itself),
// the convex corner of the smallest turn is cut off instead and the clipping goes on, for a few turns of the
// ring at most; then, or where no corner turns left, or where the clipping has spent `budget` corner tests,
// the rest is fanned.
enum class Triangulated {
    fanned,        // convex (or without area): fanned around its first corner
    clipped,       // cut by ear clipping
    budget_spent,  // the clipping spent its budget with concave corners left: what is left was fanned, which
                   // covers it wrongly, so the loaders refuse the polygon
};
Triangulated triangulate_polygon(std::span<const glm::vec3> positions, std::span<const uint32_t> corners,
                                 std::span<uint32_t> triangles, uint64_t budget = kEarTestBudget);

}  // namespace stipple
