#version 460
// §3.1 Raskar-Cohen silhouette lines when the depth pass ran as compute (render/depth_raster.hpp): the
// lines' depth test against the front faces made here, against the depth words, with the comparison
// of the fixed-function test it replaces (LESS_OR_EQUAL on the depth as stored), so that the depth
// image need not be filled for the lines alone (a copy of 2-4 ms at 1280x1024 on a software GPU).
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"

layout(constant_id = kSpecDepthUnorm24) const bool kDepthUnorm24 = true;

layout(constant_id = kSpecLineCaps) const bool kLineCaps = false;

layout(location = 0) out vec4 out_color;

layout(set = 0, binding = kBindingFrame) uniform FrameBlock { FrameUniforms frame; };
layout(set = 0, binding = kBindingObject) uniform ObjectBlock { ObjectUniforms object; };
// The depth words as texels (kBindingSceneDepthTexels): a software GPU gathers them, where it loads a
// storage buffer lane by lane.
layout(set = 1, binding = kBindingSceneDepthTexels) uniform usamplerBuffer scene_depth_texels;

void main() {
    if (kLineCaps && length(gl_PointCoord - 0.5) > 0.5) discard;  // a round cap
    // Row-major from the top row, as gl_FragCoord counts with the depth pass's flipped viewport.
    uint word = texelFetch(scene_depth_texels, int(uint(gl_FragCoord.y) * uint(frame.viewport.x) + uint(gl_FragCoord.x))).x;
    bool behind = kDepthUnorm24 ? uint(gl_FragCoord.z * 16777215.0 + 0.5) > (word & 0xFFFFFFu)
                                : gl_FragCoord.z > uintBitsToFloat(word);
    if (behind) discard;
    out_color = vec4(object.ink_color.rgb, 1.0);
}
