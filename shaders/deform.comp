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

// One influence added to the blended matrix. Called with constant slot halves only: indexing a vector
// with a variable makes a software GPU spill it to memory.
void add_influence(inout mat4 m, float weight, uint slot) {
    if (weight != 0.0) m += weight * palette[slot];
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

    // The blended matrix (only its top three rows matter: palette matrices are affine). Weights are
    // sorted by nothing, but a vertex has at least one, and most have none in the second set.
    uvec4 slots = vertex.slots;
    vec4 w0 = vertex.weights0;
    mat4 m = w0.x * palette[slots.x & 0xFFFFu];
    add_influence(m, w0.y, slots.x >> 16u);
    add_influence(m, w0.z, slots.y & 0xFFFFu);
    add_influence(m, w0.w, slots.y >> 16u);
    vec4 w1 = vertex.weights1;
    if (w1 != vec4(0.0)) {
        add_influence(m, w1.x, slots.z & 0xFFFFu);
        add_influence(m, w1.y, slots.z >> 16u);
        add_influence(m, w1.z, slots.w & 0xFFFFu);
        add_influence(m, w1.w, slots.w >> 16u);
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
