#pragma once
// The benchmark's animated row (issue 16): what playing an animation costs a frame. A skinned model of
// at least BenchOptions::animated_triangles triangles (anim::rigs::bending_cylinder: a capped tube
// bending at its elbow, two joints) is drawn from the standard view at the default parameters with the
// splat path, once as a static model and once playing its "Bend" animation at 30 frames per second of
// animation time, so every timed frame deforms the mesh and recomputes its polygons on the GPU.
#include "bench/bench_runner.hpp"
#include "render/offscreen.hpp"

namespace stipple::bench {

// The cylinder's rings and segments for at least `triangles` triangles (2 per quad, plus the caps).
struct CylinderSize {
    uint32_t rings = 0, segments = 0;
};
CylinderSize cylinder_size(uint32_t triangles);

// Writes the cylinder into the cache folder (bench-models/), loads it as an animated model and times both.
AnimatedRow run_animated_row(const gpu::Context& context, OffscreenTarget& target, const BenchOptions& options,
                             const Logger& log);

}  // namespace stipple::bench
