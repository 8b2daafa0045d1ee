#version 460
// Hidden-stipple removal (§2.1): the object's polygons fill the depth buffer, pushed back by a
// polygon offset (dynamic depth bias), so that only stipples on visible surfaces pass the depth test.
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"

layout(location = 0) in vec3 in_position;

layout(set = 0, binding = kBindingFrame) uniform FrameBlock { FrameUniforms frame; };
layout(set = 0, binding = kBindingObject) uniform ObjectBlock { ObjectUniforms object; };

void main() {
    gl_Position = object.model_view_proj * vec4(in_position, 1.0);
}
