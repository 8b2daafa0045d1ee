#version 460
// Object-space lines (beyond the paper): hidden-line removal and the visible pieces. One invocation
// per edge that line_edges.comp listed (a contour, border or crease this frame) walks the edge across
// the screen in pixel steps against the depth pass, and appends each run of visible samples as a
// piece in pixels, drawn as a capsule by line_pieces.vert and read back by the CPU for vector output.
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"
#include "dispatch.h"
#include "stipple_position.h"

layout(local_size_x = kDensityWorkgroupSize) in;
// The depth pass's format: 24-bit unorm (X8_D24 words) or 32-bit float (the words are float bits).
layout(constant_id = kSpecDepthUnorm24) const bool kDepthUnorm24 = true;

layout(set = 0, binding = kBindingFrame) uniform FrameBlock { FrameUniforms frame; };
layout(set = 0, binding = kBindingObject) uniform ObjectBlock { ObjectUniforms object; };
layout(set = 0, binding = kBindingSilhouetteEdges) uniform usamplerBuffer edge_texels;  // one gather an edge
layout(set = 0, binding = kBindingLineCandidates, std430) readonly buffer Candidates {
    LineCandidates candidates;
    uint candidate[];
};
layout(set = 0, binding = kBindingLinePieces, std430) buffer Pieces {
    LinePiecesHeader pieces;
    LinePiece piece[];
};
// One bit per polygon, set when it faces away (the density pass's, as line_edges.comp reads it).
layout(set = 0, binding = kBindingFacing, std430) readonly buffer Facing { uint facing_away[]; };
// The depth words as texels (kBindingSceneDepthTexels): a software GPU gathers them, where it loads a
// storage buffer lane by lane.
layout(set = 1, binding = kBindingSceneDepthTexels) uniform usamplerBuffer scene_depth_texels;

// A sample of a line may lie this far behind the depth pass's surface and still count as visible, on
// top of the depth pass's own polygon offset (which already covers the surface's slope across the
// pixel the sample falls in): the rasteriser's and this shader's arithmetic differ by a few ulps.
const uint kDepthToleranceUnorm24 = 4u;           // in 2^-24 steps
const float kDepthToleranceFloat = 4.0 / 16777216.0;

// Longest walk, in pixel steps (an edge longer on screen is sampled more coarsely).
const uint kMaxSteps = 8192u;

// Whether a line point at window position `px` (pixels, top row first) and window depth z is in front
// of the depth pass's surface there (or no surface covers the pixel).
bool sample_visible(vec2 px, float z) {
    ivec2 p = ivec2(floor(px));
    ivec2 size = ivec2(frame.viewport.xy);
    if (p.x < 0 || p.y < 0 || p.x >= size.x || p.y >= size.y) return false;  // off the image: not drawn
    uint word = texelFetch(scene_depth_texels, int(uint(p.y) * uint(size.x) + uint(p.x))).x;
    if (kDepthUnorm24) {
        uint surface = word & 0xFFFFFFu;
        return surface == 0xFFFFFFu || uint(z * 16777215.0 + 0.5) <= surface + kDepthToleranceUnorm24;
    }
    float surface = uintBitsToFloat(word);
    return surface >= 1.0 || z <= surface + kDepthToleranceFloat;
}

// The depth pass's window depth at `px` (1 where no surface covers it; 2 off the image).
float surface_depth(vec2 px) {
    ivec2 p = ivec2(floor(px));
    ivec2 size = ivec2(frame.viewport.xy);
    if (p.x < 0 || p.y < 0 || p.x >= size.x || p.y >= size.y) return 2.0;
    uint word = texelFetch(scene_depth_texels, int(uint(p.y) * uint(size.x) + uint(p.x))).x;
    return kDepthUnorm24 ? float(word & 0xFFFFFFu) / 16777215.0 : uintBitsToFloat(word);
}

void append_piece(vec2 a, vec2 b, uint edge, uint kind) {
    uint slot = atomicAdd(pieces.vertex_count, 6u) / 6u;
    if (slot >= pieces.capacity) return;  // counted, not stored: the read-back reports the overflow
    piece[slot] = LinePiece(a.x, a.y, b.x, b.y, edge, kind);
}

// Near a vertex the depth pass cannot tell: the pixel holding the vertex (and its neighbours) shows
// whichever of the polygons around the vertex covers the pixel's centre, and at the vertex they all
// have the line's depth. A hidden edge leaving a vertex of the outline then passes its first samples
// (a stub poking inside the outline), and a visible contour edge fails its last ones where a steeper
// polygon of the fan is nearer at the pixel centre (a gap of a pixel at every vertex of the contour, so
// the export could not join it into one loop). Samples this close to an end take the visibility of the
// first sample beyond, so an edge is cut only where its own middle is hidden or shown.
const float kVertexZonePx = 2.5;
const float kBridgePx = 3.5;

// Walks the edge between object-space points p0 and p1 in pixel steps and appends its visible runs.
// A run ends halfway between its last visible sample and the first hidden one; a run reaching an end
// of the edge ends exactly at the projected vertex, so the pieces of neighbouring edges meet exactly.
// A run of one sample is below what the test resolves and is dropped. An edge too short for both
// vertex zones is visible or hidden as a whole, as its middle.
//
// Hidden stretches up to kBridgePx long inside a visible run are bridged. Along a contour the polygon
// beside the edge is seen edge-on and projects to a sliver; the pixel centres next to the line then
// lie in the next polygon in, whose plane passes in front of the line (the surface is convex there)
// by more than any slope offset covers, and single samples fail all along the outline. An occluder
// that narrow is below what the line, at least a pixel wide, could show anyway.
//
// A contour is also seen from its back face's side: a sample hidden where it lies counts as visible
// when it is visible `away_px` off the line, on the side where the polygon facing away projects. A
// mesh's contour zig-zags, and on the concave side of each zig a whole edge lies a little behind the
// next front polygon in (whose plane passes in front of it), one triangle edge long: more than any
// bridge, and the outline of a smooth torus, with nothing in front of it, broke into strokes that moved
// from view to view (until 2026-12-04). Beside the line on the side away from the polygon facing away
// (at a contour both polygons project to the same side: the fold) lies what the fold shows behind it:
// the paper, or a surface farther away. Only where what hides the sample lies within a polygon's depth of
// the line (the contour polygon's own depth span, the one facing away: the next polygon in, not another
// part): a contour running just inside a nearer part's outline (a shell's inner wall) stays hidden.
const float kContourSidePx = 1.5;
// The margin, in depth spans of the polygon facing away (its centre's window depth from the edge's): 1.5
// closes a torus's outline at every yaw tried, where 1 left a gap; each more lets more of a shell's inner
// wall through (a sphere inside another 0.8% larger, its contour 0.8 px inside: about 34% of the hidden
// contour drawn at 1.5, 41% at 2, 55% at 3, all of it without the margin, 7% without the side test).
const float kSideDepthSpans = 1.5;

void walk_edge(vec3 p0, vec3 p1, uint edge, uint kind, vec3 away_point) {
    mat4 model_view_proj = object.model_view_proj;
    vec4 c0 = model_view_proj * vec4(p0, 1.0);
    vec4 c1 = model_view_proj * vec4(p1, 1.0);
    if (c0.z < 0.0 && c1.z < 0.0) return;  // wholly before the near plane (Vulkan clip z >= 0)
    if (c0.z < 0.0) c0 = mix(c0, c1, c0.z / (c0.z - c1.z));
    else if (c1.z < 0.0) c1 = mix(c1, c0, c1.z / (c1.z - c0.z));
    vec3 n0 = c0.xyz / c0.w, n1 = c1.xyz / c1.w;
    // Window coordinates with the renderer's negative-height viewport (y up in NDC, top row first); the
    // window depth is linear in screen space along the projected edge.
    vec2 size = frame.viewport.xy;
    vec2 s0 = vec2(0.5 * (n0.x + 1.0) * size.x, 0.5 * (1.0 - n0.y) * size.y);
    vec2 s1 = vec2(0.5 * (n1.x + 1.0) * size.x, 0.5 * (1.0 - n1.y) * size.y);
    float length_px = distance(s0, s1);
    if (!(length_px < 1e6)) return;  // not finite: degenerate projection
    vec2 away_px = vec2(0.0);  // (0, 0): the line alone is tested
    float side_margin = 0.0;   // how far behind what hides it a sample may lie for the side test
    if (kind == kLineKindContour && length_px > 0.0) {
        vec4 ca = model_view_proj * vec4(away_point, 1.0);
        if (ca.w > 0.0) {
            vec2 sa = vec2(0.5 * (ca.x / ca.w + 1.0) * size.x, 0.5 * (1.0 - ca.y / ca.w) * size.y);
            vec2 across = vec2(s0.y - s1.y, s1.x - s0.x) / length_px;
            float side = dot(sa - s0, across);
            if (side != 0.0) away_px = -sign(side) * kContourSidePx * across;
            side_margin = kSideDepthSpans * abs(ca.z / ca.w - 0.5 * (n0.z + n1.z));
        }
    }
    uint steps = clamp(uint(ceil(length_px)), 1u, kMaxSteps);
    float step = 1.0 / float(steps);
    uint run = 0u;        // visible samples in the current run
    bool gap = false;     // the run is followed by hidden samples, from `end` on
    bool ran = false;     // a visible sample has been seen
    float start = 0.0, end = 0.0;
    float bridge = kBridgePx / max(length_px, 1e-6);  // in edge parameter
    // The part of the edge whose samples are trusted (see kVertexZonePx).
    float zone = kVertexZonePx / max(length_px, 1e-6);
    float trusted_from = zone < 0.5 ? zone : 0.5, trusted_to = zone < 0.5 ? 1.0 - zone : 0.5;
    for (uint i = 0u; i <= steps; ++i) {
        float u = float(i) * step;
        float tested = clamp(u, trusted_from, trusted_to);
        vec2 at = mix(s0, s1, tested);
        float z = mix(n0.z, n1.z, tested);
        bool visible = sample_visible(at, z);
        if (!visible && away_px != vec2(0.0) && z - surface_depth(at) <= side_margin)
            visible = sample_visible(at + away_px, z);
        if (!visible) {
            if (run > 0u && !gap) end = u - 0.5 * step, gap = true;
            continue;
        }
        if (gap && u - 0.5 * step - end > bridge) {  // a real occlusion: the run ends where it began
            if (run > 1u) append_piece(mix(s0, s1, start), mix(s0, s1, end), edge, kind);
            run = 0u;
        }
        // The first run starts at the vertex when only a bridgeable stretch hides the edge before it.
        if (run == 0u) start = i == 0u || (!ran && u - 0.5 * step <= bridge) ? 0.0 : u - 0.5 * step;
        ran = true;
        gap = false;
        ++run;
    }
    // Hidden samples within kBridgePx of the end are bridged too: the run reaches the vertex (and at the
    // start, above, leaves it), so that the pieces of neighbouring edges meet.
    if (run > 1u) append_piece(mix(s0, s1, start), gap && 1.0 - end > bridge ? mix(s0, s1, end) : s1, edge, kind);
}

void main() {
    uint slot = linear_invocation();
    if (slot >= candidates.count) return;
    uint listed = candidate[slot];
    uint e = listed & kLineEdgeMask;
    uvec4 edge = texelFetch(edge_texels, int(e));  // SilhouetteEdge: first_vertex, second_vertex, first_polygon, second_polygon
    uint kind = listed >> kLineKindShift;
    vec3 p0 = mesh_vertex(edge.x), p1 = mesh_vertex(edge.y);
    // A contour's polygon facing away: where its centre projects is the side the fold shows behind.
    vec3 away_point = 0.5 * (p0 + p1);
    if (kind == kLineKindContour) {
        uint away = ((facing_away[edge.z >> 5u] >> (edge.z & 31u)) & 1u) != 0u ? edge.z : edge.w;
        uvec3 corners = mesh_triangle(away);
        away_point = (mesh_vertex(corners.x) + mesh_vertex(corners.y) + mesh_vertex(corners.z)) / 3.0;
    }
    walk_edge(p0, p1, e, kind, away_point);
}
