#pragma once
// Polygons into triangles. A PLY face may have any number of corners, and CAD and modelling exports write
// concave ones (an L- or U-shaped face of a part). A fan around the first corner covers a concave polygon
// wrongly: its triangles reach outside it and overlap each other (a U-shaped face of area 5 loaded as
// area 7), so the model gets stipples where it has no surface and twice the tone where it is covered
// twice. (OBJ faces are triangulated by tinyobjloader, which clips ears itself.)
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace stipple {

// Polygons with more corners than this are fanned whatever their shape: ear clipping costs up to the cube
// of the corners, and faces that large are caps of round parts, which are convex.
inline constexpr size_t kMaxEarClippedCorners = 256;

// The n - 2 triangles of the polygon `corners` (indices into `positions`, n >= 3), written to `triangles`
// (3 * (n - 2) indices), each wound as the polygon is. A convex polygon, or one of more than
// kMaxEarClippedCorners corners, is fanned around its first corner (what loaders did before, so convex
// faces load exactly as they did); a concave one is cut by ear clipping in the plane it spans (Newell's
// normal). Where no ear is left (a polygon that crosses itself, or is degenerate), the rest is fanned.
// Returns true when it clipped ears.
bool triangulate_polygon(std::span<const glm::vec3> positions, std::span<const uint32_t> corners,
                         std::span<uint32_t> triangles);

}  // namespace stipple
