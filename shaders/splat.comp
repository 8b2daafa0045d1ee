#version 460
// Compute splat (beyond the paper): stipples are opaque dots that never occlude each other, so a
// compute pass can draw them without the rasteriser. One invocation per item of the work list
// (runs of at most kSplatChunk stipples of the polygons that draw this frame, listed by the density
// pass or the CPU) takes the polygon's density (the density pass's, §2.1-2.3, or the CPU's), walks
// its run of the drawn stipples (index < ceil(density) and its candidates, the last at the fractional
// intensity, §2.1, or solid or absent by its polygon's threshold with solid dots, solid_dot_intensity, or as a
// smaller dot where dots are round, fractional_round_dot; larger dots where the
// candidates cannot carry the density, stipple_scale), projects each, tests it against the
// depth pass (hidden-stipple removal, §2.1; no surface = no ink) on every pixel the rasteriser's point
// would cover (same square or disc), and inks it.
//
// Three dispatches per object (kSpecSplatList): the work list; with GPU densities, the work items of the
// polygons whose density varies across them (the only variant, with the CPU's list, that has that code:
// kVaryingDensity); and the ring pass over the items with a dot astride the outline, which inks only the
// pixels such a dot gives to the visible pixels nearest it (see splat). lavapipe runs the code of a branch
// for every lane, taken or not: kept out of the first dispatch, that code no longer costs most dots.
//
// One pass, in any order, with the same result. A pixel's word is its colour with 255 * (1 - coverage)
// in the alpha byte, the top byte of the word; its colour is the background (read from a separate,
// unchanging copy) mixed with the ink by that coverage. A full stipple stores alpha 0 and the ink:
// nothing changes it. Fractional stipples (§2.1's last one of each polygon) that overlap:
// - large dots (the round-points variants) compose as the points pipeline blends them,
//   1 - coverage = (1 - a)(1 - b)...: each adds its optical depth -log2(1 - intensity) to the pixel's
//   sum (an integer atomicAdd, so the total is the same in any order) and offers the word of the sum it
//   sees, whose alpha byte falls as the sum grows and whose colour follows from that byte alone;
//   atomicMin therefore keeps the word of the whole sum. Keeping only the strongest, 6-px dots at
//   D_max 0.02 on the blobby surface, where they overlap more often than not, read a third lighter
//   than the points pipeline (mean ink 0.131 against 0.196; DensityPaths.TheSplatsLargeDotsCompose...).
// - small dots keep the strongest (atomicMin of the word alone): they rarely overlap (106 of 1.3M
//   pixels of the default scene change), and the cover buffer's clearing and atomics would cost every
//   frame. The alpha of the finished image is 1 - ink coverage; read-backs make it opaque.
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"
#include "dispatch.h"
#include "scene_depth.h"
#include "stipple_formulas.h"
#include "stipple_position.h"
#include "triangle_draws.h"

layout(local_size_x = kDensityWorkgroupSize) in;
layout(constant_id = kSpecCountDrawn) const bool kCountDrawn = false;
layout(constant_id = kSpecRecordVisible) const bool kRecordVisible = false;
layout(constant_id = kSpecRoundPoints) const bool kRoundPoints = false;  // discs, not squares
layout(constant_id = kSpecWholeDot) const bool kWholeDot = false;  // print detail (see splat)
// The list this dispatch walks (kSplatList*, shared_types.h) and whether it has the density across a polygon.
layout(constant_id = kSpecSplatList) const uint kList = kSplatListDrawn;
layout(constant_id = kSpecVaryingDensity) const bool kVaryingDensity = true;
// The ring pass inks only the lost pixels of the dots astride the outline (see splat).
const bool kRingPass = kList == kSplatListRing;

layout(set = 0, binding = kBindingFrame) uniform FrameBlock { FrameUniforms frame; };
layout(set = 0, binding = kBindingObject) uniform ObjectBlock { ObjectUniforms object; };
layout(set = 0, binding = kBindingDrawnPolygons, std430) readonly buffer DrawnList {
    DrawnPolygons drawn;
    uint drawn_polygons[];
};
layout(set = 0, binding = kBindingDrawnStipples, std430) readonly buffer VaryingList {
    DrawnPolygons varied;  // the gradient pass's list of the polygons whose density varies (GPU densities)
    uint varied_items[];
};
layout(set = 0, binding = kBindingSplatRing, std430) buffer RingList {
    DrawnPolygons ring;  // work items with a dot astride the outline, for the ring pass
    uint ring_items[];
};
layout(set = 0, binding = kBindingDebug, std430) buffer Debug {
    DebugCounters counters;
    uint drawn_mask[];
};
layout(set = 0, binding = kBindingVisibleStipples, std430) buffer Visible {
    VisibleStipplesHeader visible;
    VisibleStipple visible_stipples[];
};
layout(set = 1, binding = kBindingSplatBackground, std430) readonly buffer Background { uint background[]; };
layout(set = 1, binding = kBindingColorBuffer, std430) buffer ColorBuffer { uint color[]; };
layout(set = 1, binding = kBindingSplatCover, std430) buffer SplatCover { uint optical_depth[]; };
layout(push_constant) uniform Push {
    uint blue_first;        // the colour format stores B, G, R, A
    uint paper_background;  // nothing but paper under the splat: the background buffer is not filled
};

// Colour and the remaining paper share (1 - coverage) as one word, alpha in the top byte.
uint pack_color(vec3 rgb, float uncovered) {
    return packUnorm4x8(blue_first != 0u ? vec4(rgb.bgr, uncovered) : vec4(rgb, uncovered));
}

vec3 unpack_color(uint packed) {
    vec4 c = unpackUnorm4x8(packed);
    return blue_first != 0u ? c.bgr : c.rgb;
}

// What every stipple of a run reads from the uniforms, read once per run: loads from a uniform block
// inside the loop are not hoisted past its stores to the colour buffer (they might alias), and each
// costs the loop over the lanes that any load does on a software GPU.
struct SplatConstants {
    vec2 size;          // the viewport
    uint ink_word;      // a whole stipple's word
    vec3 ink, paper;    // the object's ink, the frame's paper
};

// Inks one pixel with a stipple of the given intensity (see the top of this file). `full` is
// intensity >= 1, known where the call is made (see main); `depth_units` is the stipple's optical depth
// (large dots only, see optical_depth_units).
void ink_pixel(uint at, float intensity, uint depth_units, SplatConstants c, bool full) {
    if (full) {
        color[at] = c.ink_word;  // the least word there is: no other stipple replaces it
        return;
    }
    vec3 paper = paper_background != 0u ? c.paper : unpack_color(background[at]);
    if (!kRoundPoints) {
        atomicMin(color[at], pack_color(mix(paper, c.ink, intensity), 1.0 - intensity));
        return;
    }
    uint sum = atomicAdd(optical_depth[at], depth_units) + depth_units;  // a few thousand dots cannot overflow it
    float uncovered = round(255.0 * exp2(-float(sum) * (1.0 / kSplatOpticalDepthScale))) * (1.0 / 255.0);
    atomicMin(color[at], pack_color(mix(paper, c.ink, 1.0 - uncovered), uncovered));
}

// A fractional stipple's optical depth, -log2(1 - intensity), in units of 1 / kSplatOpticalDepthScale.
uint optical_depth_units(float intensity) {
    return uint(min(-log2(1.0 - intensity), kSplatMaxOpticalDepth) * kSplatOpticalDepthScale + 0.5);
}

// `fraction`: the stipple's intensity (stipple_intensity, or drawn_intensity with solid dots), which the visible list
// records for vector output; `intensity` and `side`: the dot drawn (a round fractional one is smaller and
// of full ink, fractional_round_dot), a disc of diameter `side` where `round_dot` (round points, and square
// ones enlarged into discs: enlarged_square_extent). Returns whether the dot lies astride the outline (some of its pixels
// have no surface): outside the ring pass its lost pixels are left to that pass, which inks only them.
bool splat(uint index, float fraction, float intensity, bool full, float side, bool round_dot, float scale, mat4 model_view_proj,
           PolygonFrame polygon, SplatConstants c, float depth_pull) {
    if (kCountDrawn && !kRingPass) {  // drawn = survived the density cut, as the vertex path counts it
        atomicAdd(counters.drawn, 1u);
        atomicOr(drawn_mask[index >> 5u], 1u << (index & 31u));
    }
    vec4 clip = model_view_proj * vec4(stipple_position(polygon, unpackUnorm2x16(stipple_vertex(index).barycentric)), 1.0);
    if (clip.w <= 0.0) return false;
    vec3 ndc = clip.xyz / clip.w;
    if (ndc.z < 0.0 || ndc.z > 1.0) return false;  // the rasteriser clips these too
    // Window coordinates with the renderer's negative-height viewport (y up in NDC, top row first).
    vec2 size = c.size;
    vec2 window = vec2(0.5 * (ndc.x + 1.0) * size.x, 0.5 * (1.0 - ndc.y) * size.y);
    ivec2 lo = max(ivec2(ceil(window - 0.5 * side - 0.5)), ivec2(0));  // pixel centres inside the square
    ivec2 hi = min(ivec2(floor(window + 0.5 * side - 0.5)), ivec2(size) - 1);
    const bool round_points = kRoundPoints || round_dot;
    // Print detail (kWholeDot: FrameView::detail_scale > 1): a stipple is a disc many pixels wide while the depth pass's
    // polygon offset is set for one-pixel points, so on a sloped surface half the disc would fall behind
    // its own surface. The disc is one dot on the page: hidden or not as a whole, by its centre's pixel;
    // its pixels only need a surface under them (it stops at the outline, as the screen's points do).
    const bool whole_dot = kWholeDot;
    if (whole_dot) {
        ivec2 centre = clamp(ivec2(floor(window)), ivec2(0), ivec2(size) - 1);
        if (hidden_or_uncovered(ndc.z, scene_depth_at(uint(centre.y) * uint(size.x) + uint(centre.x)))) return false;
    }
    uint depth_units = kRoundPoints && !full ? optical_depth_units(intensity) : 0u;
    uint lost = 0u;  // pixels of the dot beyond the outline
    bool inked = false;
    for (int y = lo.y; y <= hi.y; ++y)
        for (int x = lo.x; x <= hi.x; ++x) {
            if (round_points) {
                vec2 d = (vec2(x, y) + 0.5 - window) / side;
                if (dot(d, d) > 0.25) continue;
            }
            uint at = uint(y) * uint(size.x) + uint(x);
            uint word = scene_depth_at(at);
            if (hidden_or_uncovered(whole_dot ? 0.0 : ndc.z - depth_pull, word)) {
                if (uncovered(word)) ++lost;
                continue;
            }
            inked = true;
            if (!kRingPass) ink_pixel(at, intensity, depth_units, c, full);
        }
    if (kRecordVisible && inked && !kRingPass) {
        uint slot = atomicAdd(visible.count, 1u);
        visible_stipples[slot] = VisibleStipple(window.x, window.y, fraction, index, scale);
    }
    // At print detail the dot is enlarged as a whole and its outline band is the screen's, enlarged.
    if (lost == 0u || whole_dot) return false;
    if (!kRingPass) return true;
    // Astride the outline: the pixels beyond it have no surface to ink, and no stipple lies beyond the
    // outline to ink the pixels just inside it, so the outline band would read lighter, and its share of
    // the footprint grows as the object shrinks. The lost pixels are inked on the visible pixels nearest
    // the dot instead (in order of distance, then index: the same in any run). Pixels hidden behind a
    // nearer part are not moved: that ink belongs to no visible surface.
    ivec2 isize = ivec2(size);
    ivec2 ring_lo = max(lo - 1, ivec2(0)), ring_hi = min(hi + 1, isize - 1);
    float last_distance = -1.0;
    uint last_at = 0u;
    // At most what the ring search may cost (splat_ring_budget): large dots move a few of their pixels.
    uint ring_iterations = uint(ring_hi.x - ring_lo.x + 1) * uint(ring_hi.y - ring_lo.y + 1);
    uint moved = min(lost, splat_ring_budget(side) / max(ring_iterations, 1u));
    for (uint k = 0u; k < moved; ++k) {
        float best_distance = 3.0e38;
        uint best_at = 0xFFFFFFFFu;
        for (int y = ring_lo.y; y <= ring_hi.y; ++y)
            for (int x = ring_lo.x; x <= ring_hi.x; ++x) {
                vec2 offset = vec2(x, y) + 0.5 - window;
                vec2 d = offset / side;
                bool own = x >= lo.x && x <= hi.x && y >= lo.y && y <= hi.y && (!round_points || dot(d, d) <= 0.25);
                if (own) continue;
                float distance = dot(offset, offset);
                uint at = uint(y) * uint(isize.x) + uint(x);
                if (distance < last_distance || (distance == last_distance && at <= last_at)) continue;
                if (distance > best_distance || (distance == best_distance && at >= best_at)) continue;
                if (hidden_or_uncovered(ndc.z - depth_pull, scene_depth_at(at))) continue;
                best_distance = distance;
                best_at = at;
            }
        if (best_at == 0xFFFFFFFFu) return true;
        ink_pixel(best_at, intensity, depth_units, c, full);
        last_distance = best_distance;
        last_at = best_at;
    }
    return true;
}

void main() {
    uint slot = linear_invocation();
    uint listed = kList == kSplatListDrawn ? drawn.count : kList == kSplatListVarying ? varied.count : ring.count;
    if (slot >= listed) return;
    // The run's first stipple.
    uint item = kList == kSplatListDrawn ? drawn_polygons[slot] : kList == kSplatListVarying ? varied_items[slot] : ring_items[slot];
    uint t = stipple_vertex(item).triangle;
    TriangleDraw draw = triangle_draw(t);
    float density = draw.density;
    if (density <= 0.0f) return;
    uint first = draw.first_stipple;
    mat4 model_view_proj = object.model_view_proj;
    uint begin, end;
    float side;
    uint candidates = polygon_candidates(t, first, object.flags);
    const float point_size = object.shading.y;
    work_item_run(item, t, draw, candidates, point_size, begin, end, side);
    PolygonFrame polygon = polygon_frame(t);  // once for all of its stipples
    // Large dots stay on their own slanted surface (large_dot_depth_pull): round ones, and square ones enlarged
    // where the candidates cannot carry the density (a 6-px square on a steep floor lost a row of its pixels
    // behind its own surface, the PNG reading 0.8 of the SVG's ink).
    float depth_pull = 0.0;
    vec2 depth_slope = vec2(0.0);
    // Square dots enlarged beyond kRoundPointsAbovePx are discs of their area (enlarged_square_extent).
    const bool whole_round = drawn_dot_is_round(kRoundPoints, side);
    const float whole_extent = drawn_dot_extent(kRoundPoints, side);
    if (kRoundPoints || side > point_size) {
        depth_slope = window_depth_slope(polygon, model_view_proj, frame.viewport.xy);
        depth_pull = large_dot_depth_pull(depth_slope, whole_extent);
    }
    SplatConstants c = SplatConstants(frame.viewport.xy, pack_color(object.ink_color.rgb, 0.0), object.ink_color.rgb,
                                      frame.paper_color.rgb);
    // The whole stipples, then the fractional last one (§2.1) if it is in this run: each loop inks
    // in one way only. (On a SIMD software rasteriser a per-pixel choice between a store and an atomic
    // runs both for every lane, and a run of a dense mesh is a stipple or two, half of them fractional.)
    // Below the least density any stipple of the polygon sees, they are whole wherever they lie.
    // Compared as floats first: a large polygon close up may carry a density beyond any uint.
    uint whole_end = draw.least >= float(end) ? end : clamp(uint(floor(max(draw.least, 0.0))), begin, end);
    // Where the density changes across the polygon beyond what its candidates carry, its dots' sizes change
    // with it (stipple_scale): each stipple is then drawn by the second loop, at its own size, up to `side`
    // (the largest, work_item_run).
    bool sizes_vary = kVaryingDensity && draw.least != draw.most && draw.most > float(candidates);
    if (sizes_vary) whole_end = begin;
    bool astride = false;  // a dot of the run lies astride the outline (see splat)
    for (uint k = begin; k < whole_end; ++k)
        if (splat(first + k, 1.0f, 1.0f, true, whole_extent, whole_round, side / point_size, model_view_proj, polygon, c, depth_pull))
            astride = true;
    // A polygon whose density changes across it: its corners and terms once for all of its stipples (only
    // in the variants that draw such polygons: kVaryingDensity).
    bool varies = kVaryingDensity && draw.least != draw.most;
    vec3 corner_a = vec3(0.0), corner_b = vec3(0.0), corner_c = vec3(0.0);
    DensityParams q = density_params(frame, object);
    float threshold = 0.0;  // the polygon's own (solid_dot_intensity)
    if (varies) {
        view_corners(t, object.model_view, corner_a, corner_b, corner_c);
        q.flags = object.flags[t >> 31u];  // object.flags.x, where lavapipe cannot fold it (uniform_branch.h)
        threshold = polygon_selection(triangle_info(t));
    }
    for (uint k = whole_end; k < end; ++k) {
        float here = density;
        if (varies) {  // where it lies (stipple_density_here)
            vec2 uv = unpackUnorm2x16(stipple_vertex(first + k).barycentric);
            here = stipple_density_here(density, corner_a + uv.x * (corner_b - corner_a) + uv.y * (corner_c - corner_a),
                                        corner_a, corner_b, corner_c, q);
        }
        // A flat polygon's density carries its last stipple's intensity already (solid_dots_density); where
        // the density changes across the polygon, each stipple's is decided where it lies, by its threshold.
        float fraction = varies ? drawn_intensity(here, float(k), threshold, q.flags) : stipple_intensity(here, float(k));
        if (fraction <= 0.0f) continue;  // where it lies, the density does not reach it
        float side_here = sizes_vary ? splat_dot_side(point_size, here, float(candidates)) : side;
        bool lost;
        if (kRoundPoints) {  // a smaller dot, of full ink where it is large enough to show its area
            vec2 dot_now = fractional_round_dot(fraction, side_here);
            lost = splat(first + k, fraction, dot_now.y, dot_now.y >= 1.0f, dot_now.x, true, side_here / point_size, model_view_proj,
                         polygon, c, large_dot_depth_pull(depth_slope, dot_now.x));
        } else {
            float extent = enlarged_square_extent(side_here);
            lost = splat(first + k, fraction, fraction, false, extent, enlarged_square_is_round(side_here), side_here / point_size,
                         model_view_proj, polygon, c, sizes_vary ? large_dot_depth_pull(depth_slope, extent) : depth_pull);
        }
        if (lost) astride = true;
    }
    // The run goes to the ring pass, which walks it again and inks only its dots' lost pixels.
    if (!kRingPass && astride) {
        uint at = atomicAdd(ring.count, 1u);
        if (at % kDensityWorkgroupSize == 0u) GROW_DISPATCH(ring, at + 1u)  // a workgroup starts there
        ring_items[at] = item;
    }
}
