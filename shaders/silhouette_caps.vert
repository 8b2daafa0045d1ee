#version 460
// §3.1 Raskar-Cohen lines' round caps (kSpecLineCaps in the silhouette fragment shaders): points of the line's
// width at the ends of the kept edges, so that wide lines join in a solid band. Drawn without vertex inputs over
// this frame's index list (line_edges.comp), a vertex per entry, its header read as the draw's command (its
// vertex_offset, always 0, as firstInstance). A cap costs the width squared: each edge caps its first end (the
// smaller index), and its second only where the edge is longer on screen than a quarter of the width. On a
// fine mesh, whose edges are a few pixels where the width is tens, a contour vertex then has about one cap
// where both ends gave it two (a vertex that is the larger end of both its edges, a third of them, is covered by
// its neighbours' caps, a few pixels away); a long edge, a coarse mesh's, caps both its ends.
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"
#include "stipple_position.h"

layout(set = 0, binding = kBindingFrame) uniform FrameBlock { FrameUniforms frame; };
layout(set = 0, binding = kBindingObject) uniform ObjectBlock { ObjectUniforms object; };
layout(set = 0, binding = kBindingSilhouetteLines, std430) readonly buffer Lines {
    SilhouetteLines lines;
    uint line_indices[];
};

// Window position of a clip-space point (the other end of an edge, behind the eye, counts as far).
vec2 on_screen(vec4 clip) { return clip.w > 0.0 ? clip.xy / clip.w * 0.5 * vec2(frame.viewport.xy) : vec2(1e9); }

void main() {
    uint entry = uint(gl_VertexIndex) - kIndexListFirstIndex;
    gl_PointSize = object.lines.x;
    gl_Position = object.model_view_proj * vec4(mesh_vertex(line_indices[entry]), 1.0);
    if ((entry & 1u) != 0u) {  // the edge's second end: capped only where the edge is long on screen
        vec4 first = object.model_view_proj * vec4(mesh_vertex(line_indices[entry - 1u]), 1.0);
        if (distance(on_screen(first), on_screen(gl_Position)) <= 0.25 * object.lines.x)
            gl_Position = vec4(0.0, 0.0, 2.0, 1.0);  // beyond the far plane: clipped
    }
}
