#version 460
// Object-space lines (beyond the paper): each visible piece that line_edges.comp found, drawn as a
// capsule of the object's line width, or its crease width for a crease (thinned with distance like the Raskar-Cohen lines, §3.1): a quad
// around the piece, reaching past both ends, in which line_pieces.frag keeps the pixels within half
// the width of the piece. Even width, round ends, and round joins where the pieces of a line meet.
// Six vertices per piece (two triangles), the piece read from the list by its vertex index.
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"

layout(set = 0, binding = kBindingFrame) uniform FrameBlock { FrameUniforms frame; };
layout(set = 0, binding = kBindingObject) uniform ObjectBlock { ObjectUniforms object; };
layout(set = 0, binding = kBindingLinePieces, std430) readonly buffer Pieces {
    LinePiecesHeader pieces;
    LinePiece piece[];
};

layout(location = 0) flat out vec4 out_piece;  // a.xy, b.xy in pixels, top row first
layout(location = 1) flat out float out_width;  // the piece's line width in pixels: creases have their own

void main() {
    uint slot = uint(gl_VertexIndex) / 6u;
    if (slot >= pieces.capacity) {  // appended beyond the buffer: dropped
        gl_Position = vec4(0.0, 0.0, 2.0, 1.0);  // z > w: clipped
        return;
    }
    LinePiece p = piece[slot];
    vec2 a = vec2(p.ax, p.ay), b = vec2(p.bx, p.by);
    float length_px = distance(a, b);
    vec2 along = length_px > 1e-6 ? (b - a) / length_px : vec2(1.0, 0.0);
    vec2 side = vec2(-along.y, along.x);
    float width = p.kind == kLineKindCrease ? object.lines.z : object.lines.x;
    float reach = 0.5 * width + 1.0;  // a pixel beyond the capsule: every pixel centre it covers is inside
    const uint kCorners[6] = uint[](0u, 1u, 2u, 2u, 1u, 3u);  // bit 1: the b end; bit 0: the left side
    uint corner = kCorners[uint(gl_VertexIndex) % 6u];
    vec2 px = ((corner & 2u) != 0u ? b + reach * along : a - reach * along) + ((corner & 1u) != 0u ? reach : -reach) * side;
    // Pixels to NDC with the renderer's negative-height viewport (y up in NDC, top row first).
    gl_Position = vec4(2.0 * px.x * frame.viewport.z - 1.0, 1.0 - 2.0 * px.y * frame.viewport.w, 0.0, 1.0);
    out_piece = vec4(a, b);
    out_width = width;
}
