#version 460
// Indirect path (beyond the paper): after the density pass, the list of the stipples drawn this frame
// (index below the polygon's density, §3.2; see DrawCommand in shared_types.h), drawn by one indirect
// draw of that many points. Culled candidates never reach the vertex stage, and one draw replaces one
// per polygon (a software GPU pays microseconds per draw: ~30,000 draws made the bunny's frame 80 ms).
// One invocation per polygon; a subgroup claims its slots with one atomic. density_cpu.cpp writes the
// same list for the cpu path, in polygon order.
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
#include "shared_types.h"
#include "stipple_formulas.h"
#include "triangle_draws.h"

layout(local_size_x = kDensityWorkgroupSize) in;

layout(set = 0, binding = kBindingObject) uniform ObjectBlock { ObjectUniforms object; };
layout(set = 0, binding = kBindingDrawnStipples, std430) buffer DrawnStipples {
    DrawCommand draw;  // vertex_count: the stipples listed so far (cleared before the pass)
    uint drawn_stipples[];
};

void main() {
    uint t = gl_GlobalInvocationID.x;
    uint triangles = object.flags.y;
    uint first = 0u;
    uint count = 0u;
    if (t < triangles) {
        TriangleDraw polygon = triangle_draw(t);  // as texels: two gathers instead of three loads
        first = polygon.first_stipple;
        // To the most density any of its stipples sees: the vertex shader culls those of a large polygon
        // that the density where they lie does not reach (stipple_density_here).
        count = drawn_stipple_count(polygon.most, polygon_candidates(t, first, object.flags));
    }
    uint total = subgroupAdd(count);
    if (total == 0u) return;  // the same in the whole subgroup
    uint base = 0u;
    if (subgroupElect()) base = atomicAdd(draw.vertex_count, total);
    base = subgroupBroadcastFirst(base) + subgroupExclusiveAdd(count);
    for (uint i = 0u; i < count; ++i) drawn_stipples[base + i] = first + i;
}
