#version 460
// §3.1 Raskar-Cohen lines' round caps (kSpecLineCaps in the silhouette fragment shaders): a point of the
// line's width at one end of each kept edge, so that wide lines over a fine mesh's short edges join in a solid
// band. Drawn without vertex inputs over this frame's index list (line_edges.comp), a vertex per entry, its
// header read as the draw's command: the second end of each pair is culled, so a contour's vertex is capped
// about once where both ends would cap it twice (a cap costs the width squared; the edges' two ends doubled a
// fine mesh's line pass). Which end: the edge table's first vertex, the smaller index, so a vertex that is the
// larger end of both its edges (a quarter of them, for indices in no order along the contour) has no cap of its
// own; its neighbours' caps, a few pixels away where the width is tens of pixels, cover its joint.
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"
#include "stipple_position.h"

layout(set = 0, binding = kBindingObject) uniform ObjectBlock { ObjectUniforms object; };
layout(set = 0, binding = kBindingSilhouetteLines, std430) readonly buffer Lines {
    SilhouetteLines lines;
    uint line_indices[];
};

void main() {
    uint entry = uint(gl_VertexIndex) - kIndexListFirstIndex;
    gl_PointSize = object.lines.x;
    if ((entry & 1u) != 0u) {  // the edge's second end
        gl_Position = vec4(0.0, 0.0, 2.0, 1.0);  // beyond the far plane: clipped
        return;
    }
    gl_Position = object.model_view_proj * vec4(mesh_vertex(line_indices[entry]), 1.0);
}
