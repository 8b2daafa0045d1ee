#version 460
// Compute splat (beyond the paper): stipples are opaque dots that never occlude each other, so a
// compute pass can draw them without the rasteriser. One invocation per polygon walks only its drawn
// stipples (index < ceil(density), the last at the fractional intensity, §2.1), projects each, tests
// it against the depth pass (hidden-stipple removal, §2.1; no surface = no ink) on every pixel the
// rasteriser's point would cover (same square or disc), and inks it:
//   kPass 0: full stipples store the ink directly (ink over anything is ink, in any order); the one
//            fractional stipple of a polygon adds its optical depth to the accumulation image;
//   kPass 1: the fractional stipples again: each pixel's summed optical depth is taken (and reset to
//            zero for the next frame) and composited: colour = ink + (colour - ink) exp(-sum).
// So only pixels under stipples are touched, never the whole frame. The colour lives in a buffer for
// the two passes (copied from and back to the colour image by the renderer).
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"
#include "stipple_formulas.h"

layout(local_size_x = kDensityWorkgroupSize) in;
layout(constant_id = 0) const bool kCountDrawn = false;
layout(constant_id = 1) const uint kPass = 0;
// The depth pass's format: 24-bit unorm (X8_D24 words) or 32-bit float (the words are float bits).
layout(constant_id = 2) const bool kDepthUnorm24 = true;

layout(set = 0, binding = kBindingFrame) uniform FrameBlock { FrameUniforms frame; };
layout(set = 0, binding = kBindingObject) uniform ObjectBlock { ObjectUniforms object; };
layout(set = 0, binding = kBindingTriangleDraw, std430) readonly buffer TriangleDraws { TriangleDraw draws[]; };
layout(set = 0, binding = kBindingStipples, std430) readonly buffer Stipples { StippleVertex stipples[]; };
layout(set = 0, binding = kBindingDebug, std430) buffer DebugCounters {
    uint drawn_count;
    uint debug_pad0, debug_pad1, debug_pad2;
    uint drawn_mask[];
};
layout(set = 1, binding = kBindingInkAccumulation, std430) coherent buffer InkAccumulation { uint ink[]; };
layout(set = 1, binding = kBindingSceneDepth, std430) readonly buffer SceneDepth { uint scene_depth[]; };
layout(set = 1, binding = kBindingColorBuffer, std430) coherent buffer ColorBuffer { uint color[]; };
layout(push_constant) uniform Push { uint blue_first; };  // the colour format stores B, G, R, A

uint pack_color(vec3 rgb) {
    return packUnorm4x8(blue_first != 0u ? vec4(rgb.bgr, 1.0) : vec4(rgb, 1.0));
}

vec3 unpack_color(uint packed) {
    vec4 c = unpackUnorm4x8(packed);
    return blue_first != 0u ? c.bgr : c.rgb;
}

// Whether a stipple at window depth z is hidden at a pixel whose depth-pass word is given, or no
// surface covers the pixel; compared as the rasteriser's LESS_OR_EQUAL test sees it (quantised).
bool hidden_or_uncovered(float z, uint word) {
    if (kDepthUnorm24) {
        uint surface = word & 0xFFFFFFu;
        return surface == 0xFFFFFFu || uint(z * 16777215.0 + 0.5) > surface;
    }
    float surface = uintBitsToFloat(word);
    return surface >= 1.0 || z > surface;
}

void splat(uint index, float intensity, mat4 model_view_proj) {
    if (kCountDrawn && kPass == 0u) {  // drawn = survived the density cut, as the vertex path counts it
        atomicAdd(drawn_count, 1u);
        atomicOr(drawn_mask[index >> 5u], 1u << (index & 31u));
    }
    vec4 clip = model_view_proj * vec4(stipples[index].position, 1.0);
    if (clip.w <= 0.0) return;
    vec3 ndc = clip.xyz / clip.w;
    if (ndc.z < 0.0 || ndc.z > 1.0) return;  // the rasteriser clips these too
    // Window coordinates with the renderer's negative-height viewport (y up in NDC, top row first).
    vec2 size = frame.viewport.xy;
    vec2 window = vec2(0.5 * (ndc.x + 1.0) * size.x, 0.5 * (1.0 - ndc.y) * size.y);
    float side = object.shading.y;
    ivec2 lo = max(ivec2(ceil(window - 0.5 * side - 0.5)), ivec2(0));  // pixel centres inside the square
    ivec2 hi = min(ivec2(floor(window + 0.5 * side - 0.5)), ivec2(size) - 1);
    bool round_points = (object.flags.x & kFlagRoundPoints) != 0u;
    bool full = intensity >= 1.0f;
    uint amount = uint(ink_optical_depth(intensity) * kInkFixedPoint + 0.5);
    uint ink_packed = pack_color(frame.ink_color.rgb);
    for (int y = lo.y; y <= hi.y; ++y)
        for (int x = lo.x; x <= hi.x; ++x) {
            ivec2 pixel = ivec2(x, y);
            uint at = uint(y) * uint(size.x) + uint(x);
            if (round_points) {
                vec2 d = (vec2(pixel) + 0.5 - window) / side;
                if (dot(d, d) > 0.25) continue;
            }
            if (kPass == 1u) {  // composite this pixel's fractional ink once, then leave it zero
                uint sum = atomicExchange(ink[at], 0u);
                if (sum == 0u) continue;
                vec3 c = unpack_color(color[at]);
                float transmittance = exp(-float(sum) / kInkFixedPoint);
                color[at] = pack_color(frame.ink_color.rgb + (c - frame.ink_color.rgb) * transmittance);
                continue;
            }
            if (hidden_or_uncovered(ndc.z, scene_depth[at])) continue;
            if (full)
                color[at] = ink_packed;
            else
                atomicAdd(ink[at], amount);
        }
}

void main() {
    uint t = gl_GlobalInvocationID.x;
    if (t >= object.flags.y) return;
    TriangleDraw draw = draws[t];
    if (draw.density <= 0.0f) return;
    mat4 model_view_proj = frame.view_proj * object.model;
    uint count = uint(ceil(draw.density));
    uint first = kPass == 1u ? count - 1u : 0u;  // the resolve revisits only the last, fractional one
    if (kPass == 1u && fract(draw.density) == 0.0f) return;
    for (uint k = first; k < count; ++k)
        splat(draw.first_stipple + k, stipple_intensity(draw.density, float(k)), model_view_proj);
}
