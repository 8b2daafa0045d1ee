#version 460
// The per-frame density of every polygon (§2.1-2.3, §3.2), one invocation per polygon. The kListDrawn
// variant also appends each polygon that draws a stipple to the splat's work list.
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_ballot : require
#include "shared_types.h"
#include "stipple_formulas.h"

layout(local_size_x = kDensityWorkgroupSize) in;
layout(constant_id = kSpecListDrawn) const bool kListDrawn = false;

layout(set = 0, binding = kBindingFrame) uniform FrameBlock { FrameUniforms frame; };
layout(set = 0, binding = kBindingObject) uniform ObjectBlock { ObjectUniforms object; };
layout(set = 0, binding = kBindingTriangleDraw, std430) buffer TriangleDraws { TriangleDraw draws[]; };
layout(set = 0, binding = kBindingTriangleInfo, std430) readonly buffer TriangleInfos { TriangleInfo infos[]; };
layout(set = 0, binding = kBindingFullAreas, std430) readonly buffer FullAreas { float full_areas[]; };
layout(set = 0, binding = kBindingDrawnPolygons, std430) buffer DrawnList {
    DrawnPolygons drawn;
    uint drawn_polygons[];
};

void main() {
    uint t = gl_GlobalInvocationID.x;
    if (t >= object.flags.y) return;
    // The candidates run from this polygon's first stipple to the next one's (first_stipple is constant,
    // written once at creation).
    uint end = t + 1u < object.flags.y ? draws[t + 1u].first_stipple : object.flags.w;
    float candidates = float(end - draws[t].first_stipple);
    TriangleInfo info = infos[t];
    PolygonView view = polygon_view(info, candidates, object);
    if ((object.flags.x & kFlagStretch) != 0u) view.due = stretched_due(candidates, info.area, full_areas[t]);
    float density = polygon_density(view, density_params(frame, object));
    draws[t].density = density;
    if (!kListDrawn) return;
    // One atomic add per subgroup hands out its slots; the slot ranges tile 0, 1, 2, ..., so each
    // range adds the workgroups of the splat's dispatch that start in it.
    bool listed = density > 0.0f;
    uvec4 ballot = subgroupBallot(listed);
    uint listed_here = subgroupBallotBitCount(ballot);
    if (listed_here == 0u) return;
    uint base = 0u;
    if (subgroupElect()) {
        base = atomicAdd(drawn.count, listed_here);
        const uint group = kDensityWorkgroupSize;
        uint starts = (base + listed_here + group - 1u) / group - (base + group - 1u) / group;
        if (starts > 0u) atomicAdd(drawn.groups_x, starts);
    }
    base = subgroupBroadcastFirst(base);
    if (listed) drawn_polygons[base + subgroupBallotExclusiveBitCount(ballot)] = t;
}
