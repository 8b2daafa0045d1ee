#version 460
// The depth pass as compute (§2.1 hidden-stipple removal), for software GPUs: the front faces, pushed
// back by the same polygon offset, written straight into the depth words that the splat and the line
// walk test against (kBindingSceneDepth), with an atomic minimum per pixel.
//
// Why: lavapipe runs a draw's vertex stage, clipping and triangle setup on one thread, about 200 ns a
// triangle, and then the depth had to be copied into words. On the bunny (69k triangles, 1280x1024) the
// fixed-function pass and its copy took 12-18 ms of a 35-50 ms frame, on one of the two cores; here
// every triangle is one invocation spread over both cores (docs/architecture.md, "Depth by compute").
//
// Two variants (kSpecRasterLarge):
//   triangles: one invocation per triangle. A triangle wholly in front of the eye whose box spans at
//     most kRasterSmallSpan pixels each way is rasterised by its invocation; any other one (larger, or
//     crossing the near plane) is listed (RasterTriangles) for
//   large: a workgroup per listed triangle, each lane taking every kDensityWorkgroupSize-th row of its
//     box. A triangle crossing the near plane or the guard band is first clipped to them in clip
//     space, so that its window coordinates stay exact in 64-bit integers.
// Each row's covered pixels are found from the edge functions (three divisions), so a triangle costs
// its rows and pixels, not its box.
//
// Coverage follows the rules of Vulkan's rasterisers: corners snapped to 1/256 pixel, pixel centres
// sampled, edge functions evaluated exactly in integers, a centre on an edge covered only by a top or
// left edge. So a pixel on an edge shared by two triangles is covered once, whichever pass draws each.
// Depth: the plane through the snapped corners at the centre; centres whose depth lies outside [0, 1]
// are clipped away; the polygon offset is Vulkan's, m * kDepthBiasSlopeFactor + r * constant, with m
// the larger depth slope and r the format's resolution; the result is clamped to [0, 1].
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "shared_types.h"
#include "dispatch.h"
#include "stipple_position.h"
#include "uniform_branch.h"

layout(local_size_x = kDensityWorkgroupSize) in;

layout(constant_id = kSpecDepthUnorm24) const bool kDepthUnorm24 = true;
layout(constant_id = kSpecRasterLarge) const bool kLargePass = false;

layout(set = 0, binding = kBindingFrame) uniform FrameBlock { FrameUniforms frame; };
layout(set = 0, binding = kBindingObject) uniform ObjectBlock { ObjectUniforms object; };
layout(set = 0, binding = kBindingDepthTriangles, std430) buffer LargeTriangles {
    RasterTriangles header;
    uint large_triangles[];
};
layout(set = 1, binding = kBindingSceneDepth, std430) buffer SceneDepth { uint scene_depth[]; };

const float kSubpixels = 256.0f;  // corners snap to 1/256 pixel (subPixelPrecisionBits 8)
// Window coordinates within this many pixels of the origin keep the edge functions' products in 64-bit
// integers (2^14 * 256 = 2^22 per coordinate); triangles reaching beyond are clipped to it.
const float kGuardPixels = 16384.0f;

vec2 window_xy(vec4 clip) {  // y down, as the depth pass's viewport maps it (StippleRenderer::begin_rendering)
    vec2 ndc = clip.xy / clip.w;
    return vec2((ndc.x * 0.5f + 0.5f) * frame.viewport.x, (0.5f - ndc.y * 0.5f) * frame.viewport.y);
}

// A triangle ready to rasterise: snapped corners (1/256 pixel), its edges normalised so that the
// inside is positive, and its depth plane with the polygon offset.
struct Setup {
    i64vec2 corner[3];
    i64vec3 edge_x;   // each edge function's change per 1/256 pixel along x
    i64vec3 edge_y;   // and along y
    i64vec3 edge_at;  // the edge functions at the first pixel centre of the box, less the top-left bias
    vec3 depth;       // window depth at pixel (x, y) centre: depth.x * x + depth.y * y + depth.z
    float offset;     // the polygon offset
    ivec2 first;      // the box's pixels within the frame, inclusive
    ivec2 last;
};

bool two_sided_object() {  // object.flags.x, read where lavapipe cannot fold it (uniform_branch.h)
    return (object.flags[unfoldable_zero()] & kFlagTwoSided) != 0u;
}

// False when the triangle covers no pixel centre of the frame, faces away from a one-sided depth pass
// or has no area. `w` are the corners' clip w (all positive here), `z` their window depth.
bool setup_triangle(vec2 window[3], vec3 z, bool one_sided, out Setup s) {
    for (int i = 0; i < 3; ++i) s.corner[i] = i64vec2(round(window[i] * kSubpixels));
    i64vec2 e1 = s.corner[1] - s.corner[0], e2 = s.corner[2] - s.corner[0];
    int64_t doubled_area = e1.x * e2.y - e1.y * e2.x;
    // Front faces wind counter-clockwise with y up: clockwise here, a negative doubled area.
    if (doubled_area == 0 || (one_sided && doubled_area > 0)) return false;
    int64_t orientation = doubled_area > 0 ? 1 : -1;
    i64vec2 lo = min(s.corner[0], min(s.corner[1], s.corner[2]));
    i64vec2 hi = max(s.corner[0], max(s.corner[1], s.corner[2]));
    // Pixel x's centre is at x * 256 + 128: the first centre at or after lo, the last at or before hi.
    s.first = max(ivec2((lo + 127) >> 8), ivec2(0));
    s.last = min(ivec2((hi - 128) >> 8), ivec2(frame.viewport.xy) - 1);
    if (any(lessThan(s.last, s.first))) return false;
    i64vec2 origin = i64vec2(s.first) * 256 + 128;
    for (int i = 0; i < 3; ++i) {
        i64vec2 a = s.corner[i], b = s.corner[(i + 1) % 3];
        int64_t ex = -(b.y - a.y) * orientation, ey = (b.x - a.x) * orientation;
        bool top_left = ex > 0 || (ex == 0 && ey > 0);  // inside lies to its right, or below a horizontal edge
        s.edge_x[i] = ex;
        s.edge_y[i] = ey;
        s.edge_at[i] = ex * (origin.x - a.x) + ey * (origin.y - a.y) - (top_left ? 0 : 1);
    }
    // The depth plane through the snapped corners, in pixels.
    vec2 p0 = vec2(s.corner[0]) / kSubpixels;
    vec2 f1 = vec2(e1) / kSubpixels, f2 = vec2(e2) / kSubpixels;
    float det = f1.x * f2.y - f1.y * f2.x;
    float dz1 = z.y - z.x, dz2 = z.z - z.x;
    vec2 slope = vec2(dz1 * f2.y - dz2 * f1.y, dz2 * f1.x - dz1 * f2.x) / det;
    s.depth = vec3(slope, z.x - dot(slope, p0 - 0.5f));  // at (x, y) the centre is (x + 0.5, y + 0.5)
    float resolution = kDepthUnorm24 ? 1.0f / 16777216.0f
                                     : exp2(float(int(floor(log2(max(max(z.x, max(z.y, z.z)), 1e-30f)))) - 23));
    s.offset = max(abs(slope.x), abs(slope.y)) * kDepthBiasSlopeFactor + resolution * kDepthBiasConstant;
    // A face facing away of an open one-sided object only hides: pushed further back, as the fixed-function
    // pass draws it (kBackFaceBiasScale).
    if (doubled_area > 0 && !two_sided_object()) s.offset *= kBackFaceBiasScale;
    return true;
}

void write_depth(ivec2 pixel, float z, float offset) {
    if (z < 0.0f || z > 1.0f) return;  // clipped by the near or the far plane
    float biased = clamp(z + offset, 0.0f, 1.0f);
    uint word = kDepthUnorm24 ? uint(biased * 16777215.0f + 0.5f) : floatBitsToUint(biased);
    atomicMin(scene_depth[uint(pixel.y) * uint(frame.viewport.x) + uint(pixel.x)], word);
}

bool one_sided_depth() {  // object.flags.x, read where lavapipe cannot fold it (uniform_branch.h)
    return (object.flags[unfoldable_zero()] & kFlagDepthOneSided) != 0u;
}

// The pixels of a row inside all three edges: offsets [lo, hi] from the box's first column (empty when
// hi < lo), from the row's edge values at that column and their steps per pixel. Each bound comes
// from a float quotient (a software GPU divides integers lane by lane, several times slower, and 64-bit
// ones slower still), clamped to just beyond the row, then made exact by one integer step either way:
// the quotient is off by far less than one.
ivec2 row_span(ivec3 row, ivec3 step, vec3 inverse_step, int width) {
    int lo = 0, hi = width - 1;
    for (int i = 0; i < 3; ++i) {
        if (step[i] == 0) {
            if (row[i] < 0) hi = -1;
            continue;
        }
        float q = clamp(-float(row[i]) * inverse_step[i], -2.0f, float(width) + 1.0f);
        if (step[i] > 0) {  // the first k with row + step * k >= 0
            int k = int(ceil(q));
            if (row[i] + step[i] * k < 0) ++k;
            else if (row[i] + step[i] * (k - 1) >= 0) --k;
            lo = max(lo, k);
        } else {  // the last such k
            int k = int(floor(q));
            if (row[i] + step[i] * k < 0) --k;
            else if (row[i] + step[i] * (k + 1) >= 0) ++k;
            hi = min(hi, k);
        }
    }
    return ivec2(lo, hi);
}

ivec2 row_span64(i64vec3 row, i64vec3 step, vec3 inverse_step, int width) {
    int lo = 0, hi = width - 1;
    for (int i = 0; i < 3; ++i) {
        if (step[i] == 0) {
            if (row[i] < 0) hi = -1;
            continue;
        }
        float q = clamp(-float(row[i]) * inverse_step[i], -2.0f, float(width) + 1.0f);
        if (step[i] > 0) {
            int k = int(ceil(q));
            if (row[i] + step[i] * k < 0) ++k;
            else if (row[i] + step[i] * (k - 1) >= 0) --k;
            lo = max(lo, k);
        } else {
            int k = int(floor(q));
            if (row[i] + step[i] * k < 0) --k;
            else if (row[i] + step[i] * (k + 1) >= 0) ++k;
            hi = min(hi, k);
        }
    }
    return ivec2(lo, hi);
}

float depth_at(Setup s, int x, int y) { return s.depth.x * float(x) + s.depth.y * float(y) + s.depth.z; }

// One invocation, a whole triangle whose box spans at most kRasterSmallSpan pixels each way (its edge
// values then fit 32 bits, and its pixels the iteration limit below).
void rasterise_small(Setup s) {
    ivec3 step_x = ivec3(s.edge_x * 256), step_y = ivec3(s.edge_y * 256);
    ivec3 row = ivec3(s.edge_at);
    vec3 inverse_step = 1.0f / vec3(step_x);  // infinite where a step is 0 (not used there)
    int width = s.last.x - s.first.x + 1;
    for (int y = s.first.y; y <= s.last.y; ++y) {
        ivec2 span = row_span(row, step_x, inverse_step, width);
        for (int k = span.x; k <= span.y; ++k) {
            int x = s.first.x + k;
            write_depth(ivec2(x, y), depth_at(s, x, y), s.offset);
        }
        row += step_y;
    }
}

// One lane's share of a large triangle: every kDensityWorkgroupSize-th row of its box, four pixels an
// iteration. (lavapipe ends any loop of an invocation after 65535 iterations in all, silently: four
// pixels an iteration let a triangle cover a 4096-pixel-wide frame's 4096 rows.)
void rasterise_share(Setup s) {
    int width = s.last.x - s.first.x + 1;
    i64vec3 step_x = s.edge_x * 256;
    vec3 inverse_step = 1.0f / vec3(step_x);
    for (int y = s.first.y + int(gl_LocalInvocationID.x); y <= s.last.y; y += int(kDensityWorkgroupSize)) {
        i64vec3 row = s.edge_at + s.edge_y * (int64_t(y - s.first.y) * 256);
        ivec2 span = row_span64(row, step_x, inverse_step, width);
        for (int k = span.x; k <= span.y; k += 4) {
            for (int j = 0; j < 4; ++j) {  // unrolled: not a loop of its own
                if (k + j > span.y) break;
                int x = s.first.x + k + j;
                write_depth(ivec2(x, y), depth_at(s, x, y), s.offset);
            }
        }
    }
}

vec4 corner_clip(uint corner) { return object.model_view_proj * vec4(mesh_vertex(corner), 1.0f); }

// The clip-space plane distances: the near plane (z >= 0) and the guard band (|x|, |y| <= g w).
float plane_distance(vec4 c, int plane, vec2 guard) {
    if (plane == 0) return c.z;
    if (plane == 1) return guard.x * c.w - c.x;
    if (plane == 2) return guard.x * c.w + c.x;
    if (plane == 3) return guard.y * c.w - c.y;
    return guard.y * c.w + c.y;
}

// A listed triangle that crosses the near plane or the guard band: clipped to them in clip space
// (Sutherland-Hodgman, at most 8 corners), then drawn as a fan. Apart from the unclipped ones, whose
// path stays free of its arrays (on a software GPU they cost every workgroup, used or not).
void rasterise_clipped(vec4 c0, vec4 c1, vec4 c2, vec2 guard, bool one_sided) {
    vec4 polygon[8];
    polygon[0] = c0;
    polygon[1] = c1;
    polygon[2] = c2;
    int count = 3;
    for (int plane = 0; plane < 5 && count >= 3; ++plane) {
        vec4 clipped[8];
        int kept = 0;
        for (int i = 0; i < count; ++i) {
            vec4 a = polygon[i], b = polygon[(i + 1) % count];
            float da = plane_distance(a, plane, guard), db = plane_distance(b, plane, guard);
            if (da >= 0.0f && kept < 8) clipped[kept++] = a;
            if ((da >= 0.0f) != (db >= 0.0f) && kept < 8) clipped[kept++] = mix(a, b, da / (da - db));
        }
        for (int i = 0; i < kept; ++i) polygon[i] = clipped[i];
        count = kept;
    }
    for (int i = 1; i + 1 < count; ++i) {  // a fan over the clipped polygon
        vec4 c[3] = vec4[3](polygon[0], polygon[i], polygon[i + 1]);
        if (c[0].w <= 0.0f || c[1].w <= 0.0f || c[2].w <= 0.0f) continue;
        vec2 window[3] = vec2[3](window_xy(c[0]), window_xy(c[1]), window_xy(c[2]));
        Setup s;
        if (setup_triangle(window, vec3(c[0].z / c[0].w, c[1].z / c[1].w, c[2].z / c[2].w), one_sided, s))
            rasterise_share(s);
    }
}

void rasterise_large(uint triangle) {
    uvec3 corners = mesh_triangle(triangle);
    vec4 c0 = corner_clip(corners.x), c1 = corner_clip(corners.y), c2 = corner_clip(corners.z);
    // The guard band in NDC: kGuardPixels from the origin, less a pixel for rounding.
    vec2 guard = (kGuardPixels - 1.0f) / (0.5f * frame.viewport.xy) - 1.0f;
    bool inside = true;
    for (int plane = 0; plane < 5; ++plane)
        inside = inside && plane_distance(c0, plane, guard) >= 0.0f && plane_distance(c1, plane, guard) >= 0.0f &&
                 plane_distance(c2, plane, guard) >= 0.0f;
    bool one_sided = one_sided_depth();
    if (!inside) {
        rasterise_clipped(c0, c1, c2, guard, one_sided);
        return;
    }
    vec2 window[3] = vec2[3](window_xy(c0), window_xy(c1), window_xy(c2));
    Setup s;
    if (setup_triangle(window, vec3(c0.z / c0.w, c1.z / c1.w, c2.z / c2.w), one_sided, s)) rasterise_share(s);
}

void large_pass() {  // at most kRasterMaxGroups workgroups: each takes every that-many-th listed triangle
    for (uint listed = gl_WorkGroupID.x; listed < header.count; listed += gl_NumWorkGroups.x)
        rasterise_large(large_triangles[listed]);
}

// True when the three corners lie beyond one plane of the view volume (-w <= x, y <= w, 0 <= z <= w): the
// triangle covers nothing. Clipping is linear in clip space, so this holds whatever the corners' w, behind
// the eye included.
bool beyond_one_plane(vec4 c0, vec4 c1, vec4 c2) {
    return (c0.x > c0.w && c1.x > c1.w && c2.x > c2.w) || (c0.x < -c0.w && c1.x < -c1.w && c2.x < -c2.w) ||
           (c0.y > c0.w && c1.y > c1.w && c2.y > c2.w) || (c0.y < -c0.w && c1.y < -c1.w && c2.y < -c2.w) ||
           (c0.z < 0.0f && c1.z < 0.0f && c2.z < 0.0f) || (c0.z > c0.w && c1.z > c1.w && c2.z > c2.w);
}

void triangle_pass() {
    uint t = linear_invocation();
    bool large = false;
    if (t < object.flags.y) {
        uvec3 corners = mesh_triangle(t);
        vec4 c0 = corner_clip(corners.x), c1 = corner_clip(corners.y), c2 = corner_clip(corners.z);
        // Wholly beside the frame, behind the eye or beyond the far plane: nothing to draw. Such triangles
        // were listed for the large pass when they reached beyond the guard band, a workgroup each to clip
        // them to nothing: a model far to the side of the view took a second a frame.
        if (beyond_one_plane(c0, c1, c2)) {
            large = false;
        } else if (c0.z < 0.0f || c1.z < 0.0f || c2.z < 0.0f || c0.w <= 0.0f || c1.w <= 0.0f || c2.w <= 0.0f) {
            large = true;
        } else {
            vec2 window[3] = vec2[3](window_xy(c0), window_xy(c1), window_xy(c2));
            vec2 lo = min(window[0], min(window[1], window[2])), hi = max(window[0], max(window[1], window[2]));
            // Beyond the guard band (or not finite, w near 0): clipped by the large pass too.
            bool guarded = all(lessThan(abs(lo), vec2(kGuardPixels))) && all(lessThan(abs(hi), vec2(kGuardPixels)));
            if (!guarded || any(greaterThan(hi - lo, vec2(float(kRasterSmallSpan) - 1.0f)))) {
                // Larger than the small loop takes; one wholly beside the frame needs no pass.
                large = !guarded || (all(lessThan(lo, frame.viewport.xy + 1.0f)) && all(greaterThan(hi, vec2(-1.0f))));
            } else {
                Setup s;
                if (setup_triangle(window, vec3(c0.z / c0.w, c1.z / c1.w, c2.z / c2.w), one_sided_depth(), s))
                    rasterise_small(s);
            }
        }
    }
    // One atomic add per subgroup for its listed triangles, each lane's place from a prefix sum.
    uint listed_here = subgroupAdd(large ? 1u : 0u);
    if (listed_here == 0u) return;
    uint base = 0u;
    if (subgroupElect()) base = atomicAdd(header.count, listed_here);
    base = subgroupBroadcastFirst(base) + subgroupExclusiveAdd(large ? 1u : 0u);
    if (large) {
        large_triangles[base] = t;
        atomicMax(header.groups_x, min(base + 1u, min(kRasterMaxGroups, kMaxGroupsX)));
    }
}

void main() {
    if (kLargePass) large_pass();
    else triangle_pass();
}
