#version 460
// §3.1 Raskar-Cohen lines, the edges to draw this frame: every edge of a polygon that faces away from
// the viewer (the paper draws the back faces' outlines; each edge here once, however many back faces
// share it). The front faces' depth, drawn before, then hides all but the silhouette's neighbourhood.
// One invocation per edge; each subgroup appends its edges' index pairs to the indexed draw of this
// frame's lines with one atomic add (one per edge would serialise on the counter).
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_ballot : require
#include "shared_types.h"
#include "stipple_formulas.h"

layout(local_size_x = kDensityWorkgroupSize) in;

layout(set = 0, binding = kBindingObject) uniform ObjectBlock { ObjectUniforms object; };
layout(set = 0, binding = kBindingTriangleInfo, std430) readonly buffer TriangleInfos { TriangleInfo infos[]; };
layout(set = 0, binding = kBindingSilhouetteEdges, std430) readonly buffer Edges { SilhouetteEdge edges[]; };
layout(set = 0, binding = kBindingSilhouetteLines, std430) buffer Lines {
    SilhouetteLines lines;
    uint line_indices[];
};

bool faces_away(uint polygon) {
    PolygonView p = polygon_view(infos[polygon], 0.0f, object);
    return polygon_faces_away(p.center, p.normal);
}

void main() {
    uint e = gl_GlobalInvocationID.x;
    SilhouetteEdge edge;
    bool drawn = false;
    if (e < object.flags.z) {
        edge = edges[e];
        drawn = faces_away(edge.first_polygon) ||
                (edge.second_polygon != kNoPolygon && faces_away(edge.second_polygon));
    }
    uvec4 ballot = subgroupBallot(drawn);
    uint drawn_here = subgroupBallotBitCount(ballot);
    if (drawn_here == 0u) return;
    uint base = 0u;
    if (subgroupElect()) base = atomicAdd(lines.index_count, 2u * drawn_here);
    base = subgroupBroadcastFirst(base);
    if (!drawn) return;
    uint at = base + 2u * subgroupBallotExclusiveBitCount(ballot);
    line_indices[at] = edge.first_vertex;
    line_indices[at + 1u] = edge.second_vertex;
}
