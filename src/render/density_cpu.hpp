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

// Draw commands for the surviving stipples: polygon t draws [first[t], first[t] + drawn_stipple_count).
// Consecutive polygons merge into one command while each one before draws all of its candidates
// (first[t + 1] - first[t]), so a dense region costs one draw, not one per polygon. Returns the number
// of commands written.
uint32_t build_draw_commands(std::span<const float> densities, std::span<const uint32_t> first_stipple,
                             std::span<gpu::DrawCommand> commands);

}  // namespace stipple

namespace stipple {

struct ObjectGpu;

// The CPU density path for one object, this frame: densities into draw_staging and either the
// surviving ranges (runs of fully drawn polygons merged) into cpu_commands, or, for cpu-splat, the
// list of polygons that draw after the densities in draw_staging. Reads the object's documented CPU
// inputs only: PolygonConstants::cpu, ObjectGeometry::first_stipple and this frame's uniforms.
// Returns the sum of the densities.
double run_cpu_density(ObjectGpu& object, const gpu::FrameUniforms& frame);

}  // namespace stipple
