#pragma once
// §3.1 Raskar-Cohen silhouettes drawn from the mesh's edges: each edge once, with the polygons on
// either side, so that a compute pass can keep the edges of back-facing polygons each frame and one
// indexed line draw inks them (the paper draws every back face's outline, which draws most edges twice
// and, on a software rasteriser, costs a polygon-to-line conversion per face).
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "shared_types.h"

namespace stipple {

// Each vertex's representative: the first vertex at exactly the same position. A mesh whose corners are
// split (a triangle soup, a glTF primitive without indices, per-face normals or texture seams) would
// otherwise make every split edge a border; the edge table is built on the representatives, which
// lie where the split corners do.
std::vector<uint32_t> weld_by_position(std::span<const glm::vec3> positions);

// The edges of a triangle list (3 indices per triangle), each undirected vertex pair once with the
// polygons that share it; a boundary edge has second_polygon == kNoPolygon. An edge shared by more than
// two polygons (non-manifold) appears once per pair of them, so each of its polygons is on a record.
// Sorted by (vertex, vertex), so the same mesh always gives the same table.
std::vector<gpu::SilhouetteEdge> build_silhouette_edges(std::span<const uint32_t> indices);

}  // namespace stipple
