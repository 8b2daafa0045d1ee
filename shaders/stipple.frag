#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"

layout(location = 0) in float in_intensity;  // negative: a square dot enlarged into a disc (stipple.vert)
layout(location = 0) out vec4 out_color;

layout(set = 0, binding = kBindingFrame) uniform FrameBlock { FrameUniforms frame; };
layout(set = 0, binding = kBindingObject) uniform ObjectBlock { ObjectUniforms object; };

void main() {
    // Large stipples are round dots, like a pen's; small ones stay square pixels (a disc of 1-2 px
    // would lose most of its area), unless enlarged beyond kRoundPointsAbovePx (enlarged_square_extent).
    if ((object.flags.x & kFlagRoundPoints) != 0u || in_intensity < 0.0) {
        vec2 d = gl_PointCoord - vec2(0.5);
        if (dot(d, d) > 0.25) discard;
    }
    // Blended "over" the paper: the fractional last stipple fades in instead of popping (§2.1).
    out_color = vec4(object.ink_color.rgb, abs(in_intensity));
}
