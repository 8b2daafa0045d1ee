#version 460
// The per-frame density of every polygon (§2.1-2.3, §3.2), one invocation per polygon. The kListDrawn
// variant also appends the work items of each polygon that draws a stipple to the splat's work
// list. For objects that draw lines (kFlagFacingBits) it also records which polygons face away, one bit each, so that the
// line pass reads two bits per edge instead of evaluating both polygons again; the kFacingOnly variant
// does only that (for objects whose densities come from the CPU).
// The kGradientPass variant runs after it, over the polygons it listed as large on screen (their density
// changes across them, stipple_density_here): it writes the bounds of that density and, with
// kListDrawn, their work items. lavapipe runs both sides of a branch under a mask, so the bounds'
// code in this pass cost every polygon (the 871k-triangle dragon's pass 36-52 ms, 21-30 without it),
// where a few hundred need it.
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "shared_types.h"
#include "dispatch.h"
#include "stipple_formulas.h"
#include "uniform_branch.h"
#include "triangle_draws.h"
#include "stipple_position.h"

layout(local_size_x = kDensityWorkgroupSize) in;
layout(constant_id = kSpecListDrawn) const bool kListDrawn = false;
layout(constant_id = kSpecFacingOnly) const bool kFacingOnly = false;
layout(constant_id = kSpecFacingBits) const bool kFacingBits = false;
layout(constant_id = kSpecGradientPass) const bool kGradientPass = false;
layout(constant_id = kSpecListGradientChunks) const bool kListGradientChunks = false;
layout(constant_id = kSpecListVaryingApart) const bool kListVaryingApart = false;

layout(set = 0, binding = kBindingFrame) uniform FrameBlock { FrameUniforms frame; };
layout(set = 0, binding = kBindingObject) uniform ObjectBlock { ObjectUniforms object; };
layout(set = 0, binding = kBindingTriangleDraw, std430) buffer TriangleDraws { TriangleDraw draws[]; };
// A polygon's constants as one texel: a software GPU gathers it at once, where it loads a storage
// buffer's members one by one, lane by lane.
layout(set = 0, binding = kBindingFullAreas, std430) readonly buffer FullAreas { float full_areas[]; };
layout(set = 0, binding = kBindingDrawnPolygons, std430) buffer DrawnList {
    DrawnPolygons drawn;
    uint drawn_polygons[];
};
layout(set = 0, binding = kBindingFacing, std430) buffer Facing { uint facing_away[]; };
layout(set = 0, binding = kBindingDrawnStipples, std430) buffer GradientChunks {
    DrawCommand chunk_draw;  // kGradientChunk vertices, an instance per chunk
    uint chunk_first[];
};
// The same binding for the splat with GPU densities (kSpecListVaryingApart): the work items of the polygons
// whose density varies across them, which the splat draws in a dispatch of their own (splat.comp).
layout(set = 0, binding = kBindingDrawnStipples, std430) buffer VaryingList {
    DrawnPolygons varied;
    uint varied_items[];
};
layout(set = 0, binding = kBindingGradientPolygons, std430) buffer GradientList {
    DrawnPolygons gradient;  // its dispatch (groups of kDensityWorkgroupSize) and count
    uint gradient_polygons[];
};

// The subgroup's facing bits from one ballot, or-ed into the words the renderer cleared before the pass:
// an atomic per subgroup and word, and no barrier (a shader with barriers costs lavapipe a quarter of
// the pass: it runs it as coroutines). A subgroup's invocations are consecutive polygons starting at a
// multiple of its size, so its bits fill part of one word, or whole words. Called by every invocation
// of the subgroup.
void write_facing_bits(bool in_range, PolygonView p) {
    uvec4 bits = subgroupBallot(in_range && polygon_faces_away(p.center, p.normal, density_params(frame, object)));
    uint first = linear_invocation() - gl_SubgroupInvocationID;  // the subgroup's first polygon
    if (!subgroupElect()) return;
    uint words = (gl_SubgroupSize + 31u) / 32u;
    for (uint k = 0u; k < words && k < 4u; ++k)
        if (bits[k] != 0u) atomicOr(facing_away[(first >> 5u) + k], bits[k] << (first & 31u));
}

// Whether the polygon lies wholly outside the view (clip_outside_bits in stipple_formulas.h): only read
// where its centroid does (`center_bits` nonzero), so a view that holds the whole object reads no corner.
bool polygon_outside_view(uint triangle, mat4 model_view_proj, vec2 slack, uint center_bits) {
    if (center_bits == 0u) return false;
    uvec3 corners = mesh_triangle(triangle);
    return triangle_outside_view(center_bits, model_view_proj * vec4(mesh_vertex(corners.x), 1.0f),
                                 model_view_proj * vec4(mesh_vertex(corners.y), 1.0f),
                                 model_view_proj * vec4(mesh_vertex(corners.z), 1.0f), slack);
}

// How many workgroups of kDensityWorkgroupSize start in slots [base, base + n) of a list.
uint groups_starting_in(uint base, uint n) {
    const uint group = kDensityWorkgroupSize;
    return (base + n + group - 1u) / group - (base + group - 1u) / group;
}

// n consecutive slots of the work list (or of the varying polygons' list, VaryingList); the splat's dispatch
// grows to the workgroups that start in them.
uint claim_slots(uint n, bool to_varied) {
    uint base = to_varied ? atomicAdd(varied.count, n) : atomicAdd(drawn.count, n);
    if (groups_starting_in(base, n) > 0u) {
        if (to_varied)
            GROW_DISPATCH(varied, base + n)
        else
            GROW_DISPATCH(drawn, base + n)
    }
    return base;
}

// Lists the subgroup's polygons that are large on screen for the gradient pass: one atomic add per
// subgroup that has any. Called by every invocation of the subgroup.
void list_gradient(bool large, uint t) {
    uvec4 ballot = subgroupBallot(large);
    uint listed = subgroupBallotBitCount(ballot);
    if (listed == 0u) return;
    uint base = 0u;
    if (subgroupElect()) {
        base = atomicAdd(gradient.count, listed);
        if (groups_starting_in(base, listed) > 0u) GROW_DISPATCH(gradient, base + listed)
    }
    base = subgroupBroadcastFirst(base);
    if (large) gradient_polygons[base + subgroupBallotExclusiveBitCount(ballot)] = t;
}

// The polygon's work items: runs of splat_run_length drawn stipples (see DrawnPolygons), up to the most
// density any of its stipples sees. One atomic add per subgroup hands out the slots of all its polygons'
// items, each polygon's consecutive (a prefix sum over the lanes). Slot ranges tile 0, 1, 2, ..., so each
// range adds the workgroups of the splat's dispatch that start in it. Called by every invocation of the
// subgroup (listing nothing where `listing` is false), with the same `to_varied` (the list: VaryingList).
void list_work_items(bool listing, bool to_varied, uint first, float candidates, float most) {
    uint drawn_here = listing ? drawn_stipple_count(most, uint(candidates)) : 0u;
    uint run = splat_run_length(drawn_here, splat_dot_side(object.shading.y, most, candidates), object.shading.y);
    uint items = (drawn_here + run - 1u) / run;
    uint listed_here = subgroupAdd(items);
    if (listed_here == 0u) return;
    uint base = 0u;
    if (subgroupElect()) base = claim_slots(listed_here, to_varied);
    base = subgroupBroadcastFirst(base) + subgroupExclusiveAdd(items);
    for (uint i = 0u; i < items; ++i) {
        if (to_varied)
            varied_items[base + i] = first + i * run;
        else
            drawn_polygons[base + i] = first + i * run;
    }
}

// The vertex path's chunks of a polygon whose density changes across it (GradientChunks): its candidates
// up to the most density any of them sees, kGradientChunk a chunk. One atomic add per subgroup, as above.
// Called by every invocation of the subgroup.
void list_gradient_chunks(bool listing, uint first, float candidates, float most) {
    uint drawn_here = listing ? drawn_stipple_count(most, uint(candidates)) : 0u;
    uint chunks = (drawn_here + kGradientChunk - 1u) / kGradientChunk;
    uint listed_here = subgroupAdd(chunks);
    if (listed_here == 0u) return;
    uint base = 0u;
    if (subgroupElect()) base = atomicAdd(chunk_draw.instance_count, listed_here);
    base = subgroupBroadcastFirst(base) + subgroupExclusiveAdd(chunks);
    for (uint i = 0u; i < chunks; ++i) chunk_first[base + i] = first + i * kGradientChunk;
}

// The gradient pass: a polygon the density pass listed as large on screen gets the bounds of the density
// across it (below the least every stipple is whole; lists and work items run to the most).
void gradient_main() {
    uint k = linear_invocation();
    if (k >= gradient.count) return;
    uint t = gradient_polygons[k];
    TriangleDraw draw = triangle_draw(t);
    float candidates = float(polygon_candidates(t, draw.first_stipple, object.flags));
    DensityParams q = density_params(frame, object);
    q.flags = object.flags[unfoldable_zero()];
    vec3 a, b, c;
    view_corners(t, object.model_view, a, b, c);
    if (draw.density < 0.0f) {  // its centroid nearer than the near plane (large_polygon_stored_density)
        draw.density = large_polygon_density(draw.density, a, b, c, q);
        draws[t].density = draw.density;
    }
    vec2 bounds = polygon_density_bounds(draw.density, a, b, c, q);
    // Large on screen by the cheap test, yet flat (below kGradientAreaStart): drawn as the density pass draws a
    // flat polygon, its last stipple solid or absent.
    if (bounds.x == bounds.y) {
        float flat_density = solid_dots_density(draw.density, candidates, polygon_selection(triangle_info(t)), q.flags);
        draws[t].density = flat_density;
        bounds = vec2(flat_density);
    }
    draws[t].least = bounds.x;
    draws[t].most = bounds.y;
    // With kListVaryingApart the work items of a polygon whose density does vary go to their own list; the
    // others (listed as large by the cheap test, yet flat) join the work list.
    bool apart = kListVaryingApart && bounds.x != bounds.y;
    if (kListDrawn) list_work_items(!apart, false, draw.first_stipple, candidates, bounds.y);
    if (kListDrawn && kListVaryingApart) list_work_items(apart, true, draw.first_stipple, candidates, bounds.y);
    if (kListGradientChunks) list_gradient_chunks(bounds.x != bounds.y, draw.first_stipple, candidates, bounds.y);
}

void main() {
    if (kGradientPass) {
        gradient_main();
        return;
    }
    uint t = linear_invocation();
    uint flags = object.flags[unfoldable_zero()];  // object.flags.x, see uniform_branch.h
    bool in_range = t < object.flags.y;
    // The candidates run from this polygon's first stipple to the next one's (first_stipple is constant,
    // written once at creation), read through the texel view (triangle_draws.h): two gathers where the
    // storage buffer's members cost a load per lane each (the pass 0.5-0.9 ms faster on the 654k hand).
    float candidates = 0.0f;
    uint first = 0u;
    if (in_range && !kFacingOnly) {
        first = texelFetch(triangle_draw_texels, int(t)).y;
        candidates = float(polygon_candidates(t, first, object.flags));
    }
    TriangleInfo info = triangle_info(in_range ? t : 0u);
    PolygonView p = polygon_view(info, candidates, object);
    // Compiled only into the variants for objects with lines (kSpecFacingBits); uniform, so every
    // invocation of a subgroup takes part in its ballot.
    if ((kFacingBits || kFacingOnly) && (flags & kFlagFacingBits) != 0u) write_facing_bits(in_range, p);
    if (kFacingOnly || !in_range) return;
    if ((flags & kFlagStretch) != 0u) p.due = stretched_due(candidates, info.area, full_areas[t]);
    DensityParams q = density_params(frame, object);
    q.flags = flags;
    PolygonDensity terms = polygon_density_terms(p, q);
    float density = selected_density(terms, p.selection);
    // Wholly outside the view: nothing drawn (clip_outside_bits), its corners read only where its centroid
    // lies outside. Not a uniform branch: lavapipe reads them for a subgroup any of whose polygons needs it.
    bool outside = false;
    if ((flags & kFlagCullOutsideView) != 0u) {
        vec2 slack = view_cull_slack(frame.viewport.xy, object.shading.y);
        uint center_bits = clip_outside_bits(object.model_view_proj * vec4(polygon_center_object(info, object), 1.0f), slack);
        outside = polygon_outside_view(t, object.model_view_proj, slack, center_bits);
    }
    if (outside) density = 0.0f;
    // A polygon large on screen draws each stipple at the density where it lies (stipple_density_here):
    // the gradient pass writes the bounds of that density over it, and lists its work items after them.
    bool large = !outside && may_carry_gradient(terms, p, q, density);
    list_gradient(large, t);
    // Drawn flat: its last stipple solid or absent (solid_dots_density); a large polygon's are decided where
    // each lies (its gradient pass, and the shaders that draw it).
    if (!large) density = solid_dots_density(density, candidates, p.selection, flags);
    draws[t].density = large ? large_polygon_stored_density(terms, density) : density;
    draws[t].least = density;
    draws[t].most = density;
    if (kListDrawn) list_work_items(!large, false, first, candidates, density);
}
