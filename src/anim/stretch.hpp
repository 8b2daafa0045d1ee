#pragma once
// How far an animation stretches each polygon, so that stipple generation can give polygons headroom:
// a polygon drawn at twice its rest area needs up to twice its rest count of candidates.
#include <cstdint>
#include <vector>

#include "anim/animated_model.hpp"
#include "mesh/mesh.hpp"

namespace stipple::anim {

struct StretchReport {
    std::vector<double> times;            // the sampled times (seconds, not wrapped)
    std::vector<float> max_area_ratio;    // per triangle: its largest area over its rest area
    std::vector<float> min_area_ratio;    // per triangle: its smallest
    float max_ratio = 1.0f;               // over the mesh
    float min_ratio = 1.0f;
    Bounds bounds;                        // every vertex of every sampled pose
    // Per triangle, 1 where it has (next to) no area at rest (1e-9 of the mean, so no candidates) and a
    // pose opens it to over 1e-3 of the mean rest area: drawn without stipples there. And their count.
    std::vector<uint8_t> opened;
    size_t opened_triangles = 0;
};

// `uniform` evenly spaced times from 0 to the duration (both included) plus every keyframe time of
// the animation's channels (evenly thinned to at most `max_key_times` when there are more), sorted.
std::vector<double> stretch_sample_times(const Animation& animation, uint32_t uniform = 64, size_t max_key_times = 1024);

// Deforms the rest mesh at each of those times (the animation clamped, not looped, so the last key's
// pose is seen) and compares every triangle's area with its rest area (AnimatedModel::rest's; a
// triangle of zero rest area reports 1: it has no stipples to scale).
StretchReport measure_stretch(const AnimatedModel& model, int animation, uint32_t uniform = 64);

}  // namespace stipple::anim
