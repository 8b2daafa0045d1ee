#version 460
// §3.1 Raskar-Cohen silhouette lines: back faces drawn as wide lines in ink; the depth test against
// the front faces lets only the edges next to the silhouette through.
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"

layout(constant_id = kSpecLineCaps) const bool kLineCaps = false;

layout(location = 0) out vec4 out_color;

layout(set = 0, binding = kBindingObject) uniform ObjectBlock { ObjectUniforms object; };

void main() {
    if (kLineCaps && length(gl_PointCoord - 0.5) > 0.5) discard;  // a round cap
    out_color = vec4(object.ink_color.rgb, 1.0);
}
