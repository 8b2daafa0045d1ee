#version 460
// This frame's lines from the mesh's edge table; one invocation per edge. What an edge carries comes
// from the two facing bits of its polygons (written by the density pass) and, for creases, their
// normals (stipple_formulas.h: raskar_cohen_edge, contour_edge, crease_edge):
//  - §3.1 Raskar-Cohen: the edge's index pair is appended to the indexed wide-line draw, which the
//    front faces' depth then trims to the silhouette;
//  - object-space lines (beyond the paper), one kind per edge (contour before crease; a border is
//    neither): the edge and its kind are appended to the list that line_walk.comp walks.
// Each subgroup appends to each list with one atomic add. The walk is a pass of its own: a software
// GPU runs a branch's code for every lane when any takes it, and most edges carry no line.
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_ballot : require
#include "shared_types.h"
#include "dispatch.h"
#include "stipple_formulas.h"

layout(local_size_x = kDensityWorkgroupSize) in;

layout(set = 0, binding = kBindingObject) uniform ObjectBlock { ObjectUniforms object; };
// The edge table and the polygons' normals as texels: a software GPU gathers a texel at once, where it
// loads a storage buffer's members one lane at a time.
layout(set = 0, binding = kBindingSilhouetteEdges) uniform usamplerBuffer edge_texels;
layout(set = 0, binding = kBindingTriangleInfoTexels) uniform usamplerBuffer triangle_info_texels;
layout(set = 0, binding = kBindingSilhouetteLines, std430) buffer Lines {
    SilhouetteLines lines;
    uint line_indices[];
};
layout(set = 0, binding = kBindingFacing, std430) readonly buffer Facing { uint facing_away[]; };
layout(set = 0, binding = kBindingLineCandidates, std430) buffer Candidates {
    LineCandidates candidates;
    uint candidate[];
};

bool faces_away(uint polygon) { return ((facing_away[polygon >> 5u] >> (polygon & 31u)) & 1u) != 0u; }

// TriangleInfo's third word is its octahedral normal.
vec3 polygon_normal(uint polygon) {
    return octahedral_to_unit(unpackSnorm2x16(texelFetch(triangle_info_texels, int(polygon)).z));
}

void main() {
    uint e = linear_invocation();
    uint flags = object.flags.x;
    bool raskar_cohen = false;
    uint kind = 0u;
    SilhouetteEdge edge;
    if (e < object.flags.z) {
        uvec4 texel = texelFetch(edge_texels, int(e));
        edge = SilhouetteEdge(texel.x, texel.y, texel.z, texel.w);
        bool has_second = edge.second_polygon != kNoPolygon;
        bool first_away = faces_away(edge.first_polygon);
        bool second_away = has_second && faces_away(edge.second_polygon);
        raskar_cohen = (flags & kFlagSilhouetteLines) != 0u && raskar_cohen_edge(first_away, has_second, second_away);
        if ((flags & kFlagContours) != 0u && contour_edge(first_away, has_second, second_away))
            kind = kLineKindContour;
        else if ((flags & kFlagCreases) != 0u && has_second &&
                 crease_edge(has_second, polygon_normal(edge.first_polygon), polygon_normal(edge.second_polygon),
                             object.lines.y))
            kind = kLineKindCrease;
        else if ((flags & kFlagBorders) != 0u && !has_second)
            kind = kLineKindBorder;
    }

    uvec4 ballot = subgroupBallot(raskar_cohen);
    uint here = subgroupBallotBitCount(ballot);
    if (here > 0u) {
        uint base = 0u;
        if (subgroupElect()) base = atomicAdd(lines.index_count, 2u * here);
        base = subgroupBroadcastFirst(base);
        if (raskar_cohen) {
            uint at = base + 2u * subgroupBallotExclusiveBitCount(ballot);
            line_indices[at] = edge.first_vertex;
            line_indices[at + 1u] = edge.second_vertex;
        }
    }

    // The slot ranges tile 0, 1, 2, ..., so a range in which a workgroup starts grows the walk's dispatch.
    ballot = subgroupBallot(kind != 0u);
    here = subgroupBallotBitCount(ballot);
    if (here > 0u) {
        uint base = 0u;
        if (subgroupElect()) {
            base = atomicAdd(candidates.count, here);
            const uint group = kDensityWorkgroupSize;
            if ((base + here + group - 1u) / group > (base + group - 1u) / group) GROW_DISPATCH(candidates, base + here)
        }
        base = subgroupBroadcastFirst(base);
        if (kind != 0u) candidate[base + subgroupBallotExclusiveBitCount(ballot)] = e | kind << kLineKindShift;
    }
}
