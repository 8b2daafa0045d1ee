#version 460
// Indirect path (beyond the paper): after the density pass, the list of the stipples drawn this frame
// (index below the polygon's density, §3.2; see DrawCommand in shared_types.h), drawn by one indirect
// draw of that many points. Culled candidates never reach the vertex stage, and one draw replaces one
// per polygon (a software GPU pays microseconds per draw: ~30,000 draws made the bunny's frame 80 ms).
// One invocation per work item of the density pass (DrawnPolygons: a run of at most kSplatChunk of a
// polygon's stipples, as the splat takes them), dispatched indirectly; a subgroup claims its slots with
// one atomic. (One invocation per polygon lost stipples on lavapipe, which ends every loop of an
// invocation after 65535 iterations: a polygon drawing more listed only that many.) density_cpu.cpp
// writes the same list for the cpu path, in polygon order.
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
#include "shared_types.h"
#include "dispatch.h"
#include "stipple_formulas.h"
#include "triangle_draws.h"
#include "stipple_position.h"

layout(local_size_x = kDensityWorkgroupSize) in;

layout(set = 0, binding = kBindingObject) uniform ObjectBlock { ObjectUniforms object; };
layout(set = 0, binding = kBindingDrawnPolygons, std430) readonly buffer DrawnList {
    DrawnPolygons drawn;
    uint drawn_polygons[];
};
layout(set = 0, binding = kBindingDrawnStipples, std430) buffer DrawnStipples {
    DrawCommand draw;  // vertex_count: the stipples listed so far (cleared before the pass)
    uint drawn_stipples[];
};

void main() {
    uint slot = linear_invocation();
    uint first = 0u;
    uint count = 0u;
    if (slot < drawn.count) {
        uint item = drawn_polygons[slot];  // the run's first stipple
        uint t = stipple_vertex(item).triangle;
        TriangleDraw polygon = triangle_draw(t);  // as texels: one gather instead of four loads
        // Up to the most density any of its stipples sees: the vertex shader culls those of a large polygon
        // that the density where they lie does not reach (stipple_density_here).
        uint begin, end;
        float side;
        work_item_run(item, t, polygon, polygon_candidates(t, polygon.first_stipple, object.flags), object.shading.y,
                      begin, end, side);
        first = item;
        count = end > begin ? end - begin : 0u;
    }
    uint total = subgroupAdd(count);
    if (total == 0u) return;  // the same in the whole subgroup
    uint base = 0u;
    if (subgroupElect()) base = atomicAdd(draw.vertex_count, total);
    base = subgroupBroadcastFirst(base) + subgroupExclusiveAdd(count);
    for (uint i = 0u; i < count; ++i) drawn_stipples[base + i] = first + i;
}
