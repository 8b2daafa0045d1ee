#version 460
// Skinning, node animation and morphing in one pass, one invocation per vertex: the morph targets'
// deltas are added in the vertex's own space, then the weighted sum of its palette matrices moves it
// to object space (a node-animated mesh has one influence, its node). Normals go through the inverse
// transpose of that blended matrix. src/anim/deform_cpu.cpp is the reference this must match.
#extension GL_GOOGLE_include_directive : require
#include "deform_types.h"

layout(local_size_x = kDeformWorkgroupSize) in;

layout(set = 0, binding = kBindingDeformVertices, std430) readonly buffer Vertices { DeformVertex vertices[]; };
layout(set = 0, binding = kBindingDeformMorphDeltas, std430) readonly buffer Deltas { MorphDelta deltas[]; };
layout(set = 0, binding = kBindingDeformPalette, std430) readonly buffer Palette { mat4 palette[]; };
layout(set = 0, binding = kBindingDeformMorphWeights, std430) readonly buffer Weights { float morph_weights[]; };
layout(set = 0, binding = kBindingDeformPositions, std430) writeonly buffer Positions { float positions[]; };
layout(set = 0, binding = kBindingDeformNormals, std430) writeonly buffer Normals { float normals[]; };

layout(push_constant) uniform Push { DeformPush push; };

uint slot_of(uvec4 slots, uint i) {
    uint word = slots[i >> 1u];
    return (i & 1u) == 0u ? (word & 0xFFFFu) : (word >> 16u);
}

void main() {
    uint v = gl_GlobalInvocationID.x;
    if (v >= push.vertex_count) return;
    DeformVertex vertex = vertices[v];

    vec3 position = vertex.position;
    vec3 normal = vertex.normal;
    uint targets = vertex.morph_weights >> 16u;
    uint first_weight = vertex.morph_weights & 0xFFFFu;
    for (uint k = 0u; k < targets; ++k) {
        float w = morph_weights[first_weight + k];
        MorphDelta d = deltas[vertex.morph_first + k];
        position += w * d.position.xyz;
        normal += w * d.normal.xyz;
    }

    // The blended matrix (only its top three rows matter: palette matrices are affine).
    mat4 m = vertex.weights0.x * palette[slot_of(vertex.slots, 0u)];
    for (uint i = 1u; i < 4u; ++i) {
        float w = vertex.weights0[i];
        if (w != 0.0) m += w * palette[slot_of(vertex.slots, i)];
    }
    if (vertex.weights1 != vec4(0.0)) {
        for (uint i = 0u; i < 4u; ++i) {
            float w = vertex.weights1[i];
            if (w != 0.0) m += w * palette[slot_of(vertex.slots, 4u + i)];
        }
    }

    vec3 p = (m * vec4(position, 1.0)).xyz;
    // Inverse transpose by cofactors: its columns are the cross products of the matrix's columns,
    // over det; only det's sign survives the normalisation (and a singular matrix still gives one).
    vec3 c0 = m[0].xyz, c1 = m[1].xyz, c2 = m[2].xyz;
    vec3 x = cross(c1, c2);
    float det_sign = dot(c0, x) < 0.0 ? -1.0 : 1.0;
    vec3 n = mat3(x, cross(c2, c0), cross(c0, c1)) * normal;
    float len = length(n);
    n = len > 0.0 ? n * (det_sign / len) : vec3(0.0, 0.0, 1.0);

    positions[3u * v] = p.x;
    positions[3u * v + 1u] = p.y;
    positions[3u * v + 2u] = p.z;
    normals[3u * v] = n.x;
    normals[3u * v + 1u] = n.y;
    normals[3u * v + 2u] = n.z;
}
