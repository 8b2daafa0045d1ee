#version 460
// The per-frame density of every polygon (§2.1-2.3, §3.2), one invocation per polygon.
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"
#include "stipple_formulas.h"

layout(local_size_x = kDensityWorkgroupSize) in;

layout(set = 0, binding = kBindingFrame) uniform FrameBlock { FrameUniforms frame; };
layout(set = 0, binding = kBindingObject) uniform ObjectBlock { ObjectUniforms object; };
layout(set = 0, binding = kBindingTriangleDraw, std430) writeonly buffer TriangleDraws { TriangleDraw draws[]; };
layout(set = 0, binding = kBindingTriangleInfo, std430) readonly buffer TriangleInfos { TriangleInfo infos[]; };

void main() {
    uint t = gl_GlobalInvocationID.x;
    if (t >= object.flags.y) return;
    float density = polygon_density(polygon_view(infos[t], object), density_params(frame, object));
    draws[t].density = density;  // first_stipple is constant, written once at creation
}
