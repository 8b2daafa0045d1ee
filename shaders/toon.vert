#version 460
// The depth pass of objects in toon silhouette mode (§3.1): the same polygon-offset depth as
// depth.vert, plus what toon.frag needs to shade the surface by N.E.
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;

layout(set = 0, binding = kBindingFrame) uniform FrameBlock { FrameUniforms frame; };
layout(set = 0, binding = kBindingObject) uniform ObjectBlock { ObjectUniforms object; };

layout(location = 0) out vec3 out_normal_view;
layout(location = 1) out vec3 out_position_view;

void main() {
    out_normal_view = mat3(object.normal_view) * in_normal;
    out_position_view = (object.model_view * vec4(in_position, 1.0)).xyz;
    gl_Position = object.model_view_proj * vec4(in_position, 1.0);
}
