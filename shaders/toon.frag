#version 460
// §3.1 Toon silhouettes: the surface takes ink where it is seen edge-on (toon_surface_ink), written
// opaque over the paper so the nearest surface wins with the depth test.
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"
#include "stipple_formulas.h"

layout(location = 0) in vec3 in_normal_view;
layout(location = 1) in vec3 in_position_view;
layout(location = 0) out vec4 out_color;

layout(set = 0, binding = kBindingFrame) uniform FrameBlock { FrameUniforms frame; };
layout(set = 0, binding = kBindingObject) uniform ObjectBlock { ObjectUniforms object; };

void main() {
    // A polygon facing away is drawn only when it can be seen through an opening (its object is open
    // or two-sided): it is seen from its inside, so its normal is flipped.
    vec3 normal = gl_FrontFacing ? normalize(in_normal_view) : -normalize(in_normal_view);
    // Parallel lines of sight in an orthographic view (FrameUniforms::projection.z): the eye ray is +z.
    vec3 to_eye = frame.projection.z != 0.0 ? vec3(0.0, 0.0, 1.0) : normalize(-in_position_view);
    float ink = toon_surface_ink(dot(normal, to_eye), object.shading.z);
    out_color = vec4(mix(frame.paper_color.rgb, object.ink_color.rgb, ink), 1.0);
}
