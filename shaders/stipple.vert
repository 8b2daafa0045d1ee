#version 460
// Draws candidate stipples; the per-polygon density decides which survive (§3.2): a stipple whose
// index within its polygon is beyond the density is pushed beyond the far plane and clipped.
// The last one gets the fractional part of the density as its intensity (§2.1), or with solid dots (the
// default) is whole or absent by its polygon's threshold (solid_dot_intensity: a flat polygon's density carries
// it already, a polygon whose density changes across it decides each stipple here).
// The kDrawnList variant draws the survivors' list instead (indirect and cpu paths, DrawCommand in
// shared_types.h): vertex i is the candidate the list names, read from the stipple buffer; only those
// that the density where they lie does not reach are culled. The vertex path draws every candidate but
// those of the polygons whose density changes across them (kGradientListed), then those in chunks
// (kGradientChunks, GradientChunks in shared_types.h). The kCountDrawn variant also records every
// surviving stipple (tests and statistics). The kOutlineShift variant moves a dot astride the object's
// outline onto the surface (outline_shift).
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"
#include "stipple_formulas.h"
#include "scene_depth.h"
#include "stipple_position.h"
#include "triangle_draws.h"

layout(constant_id = kSpecCountDrawn) const bool kCountDrawn = false;
layout(constant_id = kSpecDrawnList) const bool kDrawnList = false;
layout(constant_id = kSpecRoundPoints) const bool kRoundPoints = false;  // dots above 2.5 px
layout(constant_id = kSpecGradientListed) const bool kGradientListed = false;
layout(constant_id = kSpecGradientChunks) const bool kGradientChunks = false;
layout(constant_id = kSpecOutlineShift) const bool kOutlineShift = false;

layout(location = 0) in vec2 in_barycentric;  // (u, v) in the polygon, R16G16_UNORM
layout(location = 1) in uint in_triangle;

layout(set = 0, binding = kBindingFrame) uniform FrameBlock { FrameUniforms frame; };
layout(set = 0, binding = kBindingObject) uniform ObjectBlock { ObjectUniforms object; };
layout(set = 0, binding = kBindingDrawnStipples, std430) readonly buffer DrawnStipples {
    DrawCommand draw;
    uint drawn_stipples[];
};
layout(set = 0, binding = kBindingDebug, std430) buffer Debug {
    DebugCounters counters;
    uint drawn_mask[];
};

layout(location = 0) out float out_intensity;  // negative: a square dot enlarged into a disc (stipple.frag)

// The density at this stipple: its polygon's, but on a polygon large on screen whose density changes
// across it, where the stipple lies (stipple_density_here), for the stipples whose index that decides and,
// where its candidates cannot carry that density, for every stipple (its dot's size, stipple_scale).
float density_where_it_lies(TriangleDraw draw, uint triangle, float index, vec2 barycentric, uint candidates) {
    bool decides = index + 1.0f > draw.least && index < draw.most;  // whole below the least, culled above the most
    if (draw.least == draw.most || !(decides || draw.most > float(candidates))) return draw.density;
    vec3 a, b, c;
    view_corners(triangle, object.model_view, a, b, c);
    DensityParams q = density_params(frame, object);
    q.flags = object.flags[triangle >> 31u];  // object.flags.x, read where lavapipe cannot fold it (uniform_branch.h)
    return stipple_density_here(draw.density, a + barycentric.x * (b - a) + barycentric.y * (c - a), a, b, c, q);
}

// The outline (beyond the paper; the points' counterpart of the splat's ring pass, splat.comp). A dot astride
// the object's outline loses its pixels that have no surface under them (the coverage stencil), and no dot
// lies beyond the outline to ink the pixels just inside it, so the outline band reads lighter, and its share
// of the footprint grows as the object shrinks: on these paths the horse at 1/16 of the frame height read 6%
// lighter than framed (docs/paper-reading.md, "The outline"). The splat inks such a dot's lost pixels on the
// visible pixels nearest it; a point is drawn where it is, so it is moved instead, by a whole pixel (the
// same pixel centres under it, so the same ink) along an axis or a diagonal, along its own plane (its depth
// follows), to where the fewest of its pixels are uncovered or hidden (the first such move in a fixed order;
// none if none loses fewer). A dot only hidden in part, by a nearer part, is not moved: that ink belongs to
// no visible surface. Dots whose box is wider than kOutlineBoxMax pixels keep their loss (close-up dots,
// whose outline band is a small share of the drawing). Returns the move in pixels (x right, y down).
const int kOutlineBoxMax = 6;

ivec2 outline_shift(vec4 clip, float side, bool round_dot, vec2 slope) {
    if (clip.w <= 0.0) return ivec2(0);
    vec3 ndc = clip.xyz / clip.w;
    if (ndc.z < 0.0 || ndc.z > 1.0) return ivec2(0);
    ivec2 size = ivec2(frame.viewport.xy);
    // Window coordinates with the renderer's negative-height viewport (y up in NDC, top row first), and the
    // pixel centres inside the dot's square, as splat.comp finds them.
    vec2 window = vec2(0.5 * (ndc.x + 1.0) * frame.viewport.x, 0.5 * (1.0 - ndc.y) * frame.viewport.y);
    ivec2 lo = ivec2(ceil(window - 0.5 * side - 0.5)), hi = ivec2(floor(window + 0.5 * side - 0.5));
    if (any(greaterThan(hi - lo, ivec2(kOutlineBoxMax - 1))) || any(lessThan(hi, lo))) return ivec2(0);
    // Does any pixel of the dot within the frame lack a surface? (Nearly every dot stops here.) A box of up to
    // 2x2 pixels (dots of up to 2 px, the default 1.5 among them) reads its four without a loop.
    bool astride = false;
    if (all(lessThanEqual(hi - lo, ivec2(1)))) {
        for (int k = 0; k < 4; ++k) {
            ivec2 p = lo + ivec2(k & 1, k >> 1), inside = clamp(p, ivec2(0), size - 1);
            vec2 d = (vec2(p) + 0.5 - window) / side;
            bool mine = p == inside && all(lessThanEqual(p, hi)) && (!round_dot || dot(d, d) <= 0.25);
            astride = astride || (mine && uncovered(scene_depth_at(uint(inside.y) * uint(size.x) + uint(inside.x))));
        }
    } else {
        for (int y = max(lo.y, 0); y <= min(hi.y, size.y - 1); ++y)
            for (int x = max(lo.x, 0); x <= min(hi.x, size.x - 1); ++x) {
                vec2 d = (vec2(x, y) + 0.5 - window) / side;
                if ((!round_dot || dot(d, d) <= 0.25) && uncovered(scene_depth_at(uint(y) * uint(size.x) + uint(x))))
                    astride = true;
            }
    }
    // Each move in turn, the dot at its own plane's depth there (`slope`, window depth per pixel): the pixels it
    // would lose (no surface, a nearer one, or beyond the frame). A software GPU runs a branch's code for every
    // lane under a mask, taken or not, but leaves a loop once no lane goes on: these loops run for no dot that
    // is not astride (their count is 0 then). The moves in order of length, then a fixed order: none, (1, 0),
    // (-1, 0), (0, 1), (0, -1), (1, 1), (-1, 1), (1, -1), (-1, -1) (worked out, not read from an array a
    // software GPU would fill for every lane).
    ivec2 best = ivec2(0);
    int best_lost = 1 << 30;
    for (int m = 0; m < (astride ? 9 : 0); ++m) {
        ivec2 move = m == 0 ? ivec2(0) : m < 5 ? ivec2(m == 1 ? 1 : m == 2 ? -1 : 0, m == 3 ? 1 : m == 4 ? -1 : 0)
                                               : ivec2((m & 1) != 0 ? 1 : -1, m < 7 ? 1 : -1);
        float z = ndc.z + dot(slope, vec2(move));
        int count = z < 0.0 ? 1 << 29 : 0;  // not in front of the near plane
        for (int y = lo.y; y <= hi.y; ++y)
            for (int x = lo.x; x <= hi.x; ++x) {
                vec2 d = (vec2(x, y) + 0.5 - window) / side;
                if (round_dot && dot(d, d) > 0.25) continue;
                ivec2 p = ivec2(x, y) + move, inside = clamp(p, ivec2(0), size - 1);  // read within the frame
                if (p != inside || hidden_or_uncovered(z, scene_depth_at(uint(inside.y) * uint(size.x) + uint(inside.x))))
                    ++count;
            }
        if (count < best_lost) best_lost = count, best = move;
    }
    return best;
}

void main() {
    // The vertex inputs are the candidate gl_VertexIndex names; the list variant draws another one.
    uint stipple = uint(gl_VertexIndex);
    uint triangle = in_triangle;
    vec2 barycentric = in_barycentric;
    bool in_chunk = true;
    if (kGradientChunks) {  // candidate gl_VertexIndex of chunk gl_InstanceIndex, if still its polygon's
        uint first = drawn_stipples[gl_InstanceIndex];
        stipple = first + uint(gl_VertexIndex);
        StippleVertex chunk = stipple_vertex(first), here = stipple_vertex(stipple);
        triangle = chunk.triangle;
        barycentric = unpackUnorm2x16(here.barycentric);
        in_chunk = here.triangle == triangle && stipple < object.flags.w;  // flags.w: the candidates in all
    }
    if (kDrawnList) {
        stipple = drawn_stipples[gl_VertexIndex];
        StippleVertex listed = stipple_vertex(stipple);
        triangle = listed.triangle;
        barycentric = unpackUnorm2x16(listed.barycentric);
    }
    TriangleDraw draw = triangle_draw(triangle);
    float index = float(stipple - draw.first_stipple);
    // The vertex path's draw of every candidate leaves the polygons whose density changes across them to its
    // chunk draw (kSpecGradientListed) and has none of their code; the other variants read the candidates
    // first (nearly all they draw survive).
    const bool kFlatOnly = kGradientListed && !kDrawnList && !kGradientChunks;
    uint candidates = kFlatOnly ? 0u : polygon_candidates(triangle, draw.first_stipple, object.flags);
    float here = kFlatOnly ? draw.density : density_where_it_lies(draw, triangle, index, barycentric, candidates);
    float intensity = kFlatOnly && draw.least != draw.most ? 0.0f : stipple_intensity(here, index);
    // A flat polygon's density carries its last stipple's intensity already (solid_dots_density); where the
    // density changes across the polygon, each stipple's is decided where it lies, by the polygon's threshold.
    if (!kFlatOnly && draw.least != draw.most)
        intensity = drawn_intensity(here, index, polygon_selection(triangle_info(triangle)), object.flags[triangle >> 31u]);
    if (!in_chunk) intensity = 0.0f;
    out_intensity = intensity;
    if (intensity <= 0.0f) {
        gl_PointSize = object.shading.y;
        gl_Position = vec4(0.0, 0.0, 2.0, 1.0);  // z > w: beyond the far plane, clipped
        return;
    }
    // Larger dots where the polygon's candidates cannot carry its density (stipple_scale): on a polygon whose
    // density changes across it, the density where the stipple lies (a floor close up needs large dots near
    // the eye, not far away).
    if (kFlatOnly) candidates = polygon_candidates(triangle, draw.first_stipple, object.flags);
    gl_PointSize = object.shading.y * stipple_scale(here, float(candidates));
    if (kRoundPoints && intensity < 1.0f) {  // the fractional last dot: smaller, of full ink
        vec2 dot_now = fractional_round_dot(intensity, gl_PointSize);
        gl_PointSize = dot_now.x;
        out_intensity = dot_now.y;
    }
    if (!kRoundPoints && enlarged_square_is_round(gl_PointSize)) {  // a disc of the square's area
        gl_PointSize = enlarged_square_extent(gl_PointSize);
        out_intensity = -intensity;  // stipple.frag: negative, a disc
    }
    if (kCountDrawn) {
        atomicAdd(counters.drawn, 1u);
        atomicOr(drawn_mask[stipple >> 5u], 1u << (stipple & 31u));
    }
    PolygonFrame polygon = polygon_frame(triangle);
    vec3 position = stipple_position(polygon, barycentric);  // survivors only
    gl_Position = object.model_view_proj * vec4(position, 1.0);
    // Large dots stay on their own slanted surface (large_dot_depth_pull): round points, and small dots
    // enlarged where the candidates cannot carry the density, as the splat does. Until 2026-12-05 only round
    // points' were pulled (pulling every survivor cost 5% of this pass under lavapipe's mask), and close up
    // the enlarged dots lost their upper edge behind their own surface: the default scene at 0.35 of its
    // framing distance read 16.8% of ink on this path, 19.4% on the splat. Only the subgroups holding an
    // enlarged dot compute the slope now, which framed views seldom have.
    if (kRoundPoints || gl_PointSize > object.shading.y) {
        vec2 slope = window_depth_slope_at(gl_Position, object.model_view_proj * vec4(polygon.edge_u, 0.0),
                                           object.model_view_proj * vec4(polygon.edge_v, 0.0), frame.viewport.xy);
        gl_Position.z -= large_dot_depth_pull(slope, gl_PointSize) * gl_Position.w;
    }
    if (kOutlineShift) {  // moved along its own plane: its depth follows (window_depth_slope_at, of the plane itself)
        vec2 slope = window_depth_slope_at(object.model_view_proj * vec4(position, 1.0), object.model_view_proj * vec4(polygon.edge_u, 0.0),
                                           object.model_view_proj * vec4(polygon.edge_v, 0.0), frame.viewport.xy);
        ivec2 move = outline_shift(gl_Position, gl_PointSize, kRoundPoints || out_intensity < 0.0f, slope);
        gl_Position.xy += vec2(2.0f * float(move.x) * frame.viewport.z, -2.0f * float(move.y) * frame.viewport.w) * gl_Position.w;
        gl_Position.z += dot(slope, vec2(move)) * gl_Position.w;
    }
}
