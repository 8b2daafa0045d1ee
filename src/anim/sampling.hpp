#pragma once
// Keyframe sampling (ours, from the glTF 2.0 specification): STEP holds the key at or before the
// time; LINEAR interpolates (rotations by slerp along the short arc); CUBICSPLINE is the Hermite
// spline through the keys with the file's in/out tangents scaled by the key interval. A time before
// the first key holds the first value, after the last the last. Rotations come out normalised.
#include "anim/animated_model.hpp"

namespace stipple::anim {

// Writes sampler.components numbers to out.
void sample(const Sampler& sampler, double time, bool is_rotation, double* out);

// Spherical linear interpolation between unit quaternions along the shorter arc (x, y, z, w order).
void slerp_short_arc(const double* a, const double* b, double s, double* out);

}  // namespace stipple::anim
