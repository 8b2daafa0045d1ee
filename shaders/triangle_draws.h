// Reading a polygon's TriangleDraw (its density this frame, its first stipple, the density's bounds) at a
// scattered place: through the RGBA32UI texel view of the densities (kBindingTriangleDrawTexels), one gather on a software
// GPU where a storage buffer is loaded member by member, lane by lane (docs/architecture.md).
#ifndef TRIANGLE_DRAWS_H
#define TRIANGLE_DRAWS_H

layout(set = 0, binding = kBindingTriangleDrawTexels) uniform usamplerBuffer triangle_draw_texels;
layout(set = 0, binding = kBindingTriangleInfoTexels) uniform usamplerBuffer info_texels;

TriangleDraw triangle_draw(uint triangle) {
    uvec4 texel = texelFetch(triangle_draw_texels, int(triangle));
    return TriangleDraw(uintBitsToFloat(texel.x), texel.y, uintBitsToFloat(texel.z), uintBitsToFloat(texel.w));
}

// Its constants (TriangleInfo), one gather.
TriangleInfo triangle_info(uint triangle) {
    uvec4 raw = texelFetch(info_texels, int(triangle));
    return TriangleInfo(raw.x, raw.y, raw.z, uintBitsToFloat(raw.w));
}

// Its candidates: from its first stipple to the next polygon's (object.flags.y polygons,
// object.flags.w stipples in all).
uint polygon_candidates(uint triangle, uint first_stipple, uvec4 flags) {
    uint end = triangle + 1u < flags.y ? texelFetch(triangle_draw_texels, int(triangle + 1u)).y : flags.w;
    return end - first_stipple;
}

// A work item of the density pass (a run of one polygon's drawn stipples, from its first stipple `item`):
// stipples [begin, end) of polygon t, cut as the density pass cut them (splat_run_length), up to the most
// density any of its stipples sees (a large polygon's density changes across it, stipple_density_here);
// `side`: its dots' side on the splat. The splat and the indirect path's list read the items alike.
// Needs stipple_formulas.h.
void work_item_run(uint item, uint t, TriangleDraw draw, uint candidates, float point_size, out uint begin, out uint end,
                   out float side) {
    begin = item - draw.first_stipple;
    uint drawn = drawn_stipple_count(draw.most, candidates);
    // Larger when owed more; on a polygon whose density changes across it, the largest of its dots
    // (each is drawn at its own, splat.comp).
    side = splat_dot_side(point_size, draw.most, float(candidates));
    end = min(drawn, begin + splat_run_length(drawn, side, point_size));
}

#endif
