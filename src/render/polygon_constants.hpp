#pragma once
// The per-polygon constants of §2.1-2.3 (what the density pass reads for each polygon: centroid, unit
// normal, area, the fixed selection value), packed into 16 bytes (shared_types.h: TriangleInfo).
#include <vector>

#include "mesh/mesh.hpp"
#include "render/object_gpu.hpp"
#include "stipple/stipple_set.hpp"

namespace stipple {

// The constants of `mesh` in its current shape: the CPU copy, its bounds and quantisation box (the GPU
// buffers are left for create_object_gpu). Selection values come from `stipples` when it carries them,
// else are ranked here (seeded). `box`: the quantisation box when it must hold more than this shape
// (every pose of an animation). CPU only: safe on any thread.
PolygonConstants compute_polygon_constants(const Mesh& mesh, const StippleSet& stipples, uint64_t seed,
                                           const Bounds* box = nullptr);

// Packs the polygons of `mesh` with centroids in the box [box_min, box_min + box_size].
std::vector<gpu::TriangleInfo> pack_polygon_constants(const Mesh& mesh, const std::vector<float>& selection,
                                                      glm::vec3 box_min, glm::vec3 box_size);

}  // namespace stipple
