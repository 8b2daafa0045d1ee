#version 460
// Object-space lines: the pixels whose centre lies within half the line width of the piece (a capsule).
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"

layout(location = 0) flat in vec4 in_piece;  // a.xy, b.xy in pixels, top row first
layout(location = 1) flat in float in_width;  // the piece's line width in pixels
layout(location = 0) out vec4 out_color;

layout(set = 0, binding = kBindingFrame) uniform FrameBlock { FrameUniforms frame; };
layout(set = 0, binding = kBindingObject) uniform ObjectBlock { ObjectUniforms object; };

void main() {
    vec2 p = gl_FragCoord.xy;  // the pixel centre, framebuffer coordinates (top row first)
    vec2 a = in_piece.xy, ab = in_piece.zw - in_piece.xy;
    float t = clamp(dot(p - a, ab) / max(dot(ab, ab), 1e-12), 0.0, 1.0);
    if (distance(p, a + t * ab) > 0.5 * in_width) discard;
    out_color = vec4(object.ink_color.rgb, 1.0);
}
