#pragma once
// §3.1 Raskar-Cohen silhouettes drawn from the mesh's edges: each edge once, with the polygons on
// either side, so that a compute pass can keep the edges of back-facing polygons each frame and one
// indexed line draw inks them (the paper draws every back face's outline, which draws most edges twice
// and, on a software rasteriser, costs a polygon-to-line conversion per face).
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "mesh/mesh_ops.hpp"  // weld_by_position: the table is built on welded corners
#include "shared_types.h"

namespace stipple {

// The edges of a triangle list (3 indices per triangle), each undirected vertex pair once with the
// polygons that share it; a boundary edge has second_polygon == kNoPolygon. An edge shared by more than
// two polygons (non-manifold) appears once per pair of them, so each of its polygons is on a record.
// Sorted by (vertex, vertex), so the same mesh always gives the same table.
std::vector<gpu::SilhouetteEdge> build_silhouette_edges(std::span<const uint32_t> indices);

}  // namespace stipple
