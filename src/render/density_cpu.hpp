#pragma once
// The paper's "no vertex program" path: the CPU evaluates the per-polygon density (the same
// formulas as the GPU, shaders/stipple_formulas.h) and submits only the stipples that survive.
#include <span>

#include "shared_types.h"

namespace stipple {

// One density per polygon, exactly polygon_density() of the shaders. `first_stipple` holds one more
// entry than `triangles` (where the last polygon's candidates end).
void compute_densities_cpu(std::span<const gpu::TriangleInfo> triangles, std::span<const uint32_t> first_stipple,
                           const gpu::FrameUniforms& frame, const gpu::ObjectUniforms& object,
                           std::span<float> densities);

}  // namespace stipple

namespace stipple {

struct ObjectGpu;

// The CPU density path for one object, this frame: densities into draw_staging and after them the
// list the GPU draws from: for cpu, the stipples that draw (DrawCommand, then their indices, in
// polygon order: the list shaders/drawn_stipples.comp writes on the GPU); for cpu-splat, the splat's
// work items (DrawnPolygons). Reads the object's documented CPU
// inputs only: PolygonConstants::cpu, ObjectGeometry::first_stipple and this frame's uniforms.
// Returns the sum of the densities.
double run_cpu_density(ObjectGpu& object, const gpu::FrameUniforms& frame);

}  // namespace stipple
