#pragma once
// The paper's "no vertex program" path: the CPU evaluates the per-polygon density (the same
// formulas as the GPU, shaders/stipple_formulas.h) and submits only the stipples that survive.
#include <span>

#include <glm/glm.hpp>

#include "shared_types.h"

namespace stipple {

// One density per polygon, and the bounds of the density its stipples see (TriangleDraw::least, most), as
// the density pass computes them (polygon_density, polygon_density_bounds). `first_stipple` holds one more entry than `triangles`
// (where the last polygon's candidates end); `first_triangle` is triangles[0]'s index in the mesh whose
// object-space corners `positions` and `indices` (three a polygon) give.
void compute_densities_cpu(std::span<const gpu::TriangleInfo> triangles, std::span<const uint32_t> first_stipple,
                           size_t first_triangle, std::span<const glm::vec3> positions,
                           std::span<const uint32_t> indices, const gpu::FrameUniforms& frame,
                           const gpu::ObjectUniforms& object, std::span<float> densities,
                           std::span<glm::vec2> bounds);

}  // namespace stipple

namespace stipple {

struct ObjectGpu;

// The CPU density path for one object, this frame: densities into draw_staging and after them the
// list the GPU draws from: for cpu, the stipples that draw (DrawCommand, then their indices, in
// polygon order: the list shaders/drawn_stipples.comp writes on the GPU); for cpu-splat, the splat's
// work items (DrawnPolygons). Reads the object's documented CPU
// inputs only: PolygonConstants::cpu, ObjectGeometry::first_stipple and this frame's uniforms.
// The list's header is its dispatch, in rows of at most max_groups_x (gpu::split_groups).
// Returns the sum of the densities.
double run_cpu_density(ObjectGpu& object, const gpu::FrameUniforms& frame, uint32_t max_groups_x);

}  // namespace stipple
