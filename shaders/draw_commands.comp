#version 460
// GPU-driven path (beyond the paper): after the density pass, compacted indirect draws of the
// surviving stipple ranges, so culled stipples never reach the vertex stage. Runs of polygons that draw
// all their candidates are merged into one draw (draws_merge_with_previous), exactly as the CPU path does.
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"
#include "stipple_formulas.h"

layout(local_size_x = kDensityWorkgroupSize) in;

layout(set = 0, binding = kBindingObject) uniform ObjectBlock { ObjectUniforms object; };
layout(set = 0, binding = kBindingTriangleDraw, std430) readonly buffer TriangleDraws { TriangleDraw draws[]; };
layout(set = 0, binding = kBindingDrawCommands, std430) buffer DrawCommands {
    DrawCommandsHeader header;
    DrawCommand commands[];
};

uint candidates(uint t) {
    return (t + 1u < object.flags.y ? draws[t + 1u].first_stipple : object.flags.w) - draws[t].first_stipple;
}

uint drawn(uint t) { return drawn_stipple_count(draws[t].density, candidates(t)); }

// Polygon t joins the draw of polygon t - 1 (same rule as build_draw_commands in density_cpu.cpp).
bool merges_with_previous(uint t) {
    if (t == 0u || t % kMaxMergedPolygons == 0u || drawn(t) == 0u) return false;
    uint previous = drawn(t - 1u);
    return previous > 0u && previous == candidates(t - 1u);  // all candidates
}

void main() {
    uint t = gl_GlobalInvocationID.x;
    uint triangles = object.flags.y;
    if (t >= triangles) return;
    uint count = drawn(t);
    if (count == 0u || merges_with_previous(t)) return;
    for (uint next = t + 1u; next < triangles && merges_with_previous(next); ++next) count += drawn(next);
    uint slot = atomicAdd(header.count, 1u);
    commands[slot] = DrawCommand(count, 1u, draws[t].first_stipple, 0u);
}
