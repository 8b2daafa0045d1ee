#version 460
// Skinning, node animation and morphing in one pass, one invocation per vertex: the morph targets'
// deltas are added in the vertex's own space, then the weighted sum of its palette matrices moves it
// to object space (a node-animated mesh has one influence, its node). Normals go through the inverse
// transpose of that blended matrix. src/anim/deform_cpu.cpp is the reference this must match.
#extension GL_GOOGLE_include_directive : require
#include "deform_types.h"
#include "dispatch.h"

layout(local_size_x = kDeformWorkgroupSize) in;

// DeformVertex[] as five RGBA32UI texels a vertex (a software GPU gathers a texel at once, where it
// loads a storage buffer's members lane by lane); the last, weights1, is read only with over 4 pairs.
layout(set = 0, binding = kBindingDeformVertices) uniform usamplerBuffer vertex_texels;
layout(set = 0, binding = kBindingDeformMorphDeltas) uniform samplerBuffer delta_texels;  // position, normal
// Three texels per slot: the top three rows of its affine matrix (the fourth is always 0 0 0 1). A
// texel buffer rather than a storage buffer: a software GPU gathers a texel's four floats at once.
layout(set = 0, binding = kBindingDeformPalette) uniform samplerBuffer palette_rows;
layout(set = 0, binding = kBindingDeformMorphWeights, std430) readonly buffer Weights { float morph_weights[]; };
layout(set = 0, binding = kBindingDeformPositions, std430) writeonly buffer Positions { float positions[]; };
layout(set = 0, binding = kBindingDeformNormals, std430) writeonly buffer Normals { float normals[]; };

layout(push_constant) uniform Push { DeformPush push; };
layout(constant_id = kSpecDeformInfluences) const uint kInfluences = kDeformMaxInfluences;

// The blended matrix's three rows: three fetches an influence.
struct Blend {
    vec4 r0, r1, r2;
};

// One influence: its slot's rows times its weight.
Blend weighted_rows(float weight, uint slot) {
    return Blend(weight * texelFetch(palette_rows, int(3u * slot)), weight * texelFetch(palette_rows, int(3u * slot + 1u)),
                 weight * texelFetch(palette_rows, int(3u * slot + 2u)));
}

// One influence added to the blend. Called with constant slot halves only: indexing a vector with a
// variable makes a software GPU spill it to memory.
void add_influence(inout Blend m, float weight, uint slot) {
    if (weight != 0.0) {
        Blend w = weighted_rows(weight, slot);
        m.r0 += w.r0;
        m.r1 += w.r1;
        m.r2 += w.r2;
    }
}

void main() {
    uint v = linear_invocation();
    if (v >= push.vertex_count) return;
    int texel = int(5u * v);
    uvec4 position_morph = texelFetch(vertex_texels, texel);      // position, morph_first
    uvec4 normal_weights = texelFetch(vertex_texels, texel + 1);  // normal, morph_weights

    vec3 position = uintBitsToFloat(position_morph.xyz);
    vec3 normal = uintBitsToFloat(normal_weights.xyz);
    uint targets = normal_weights.w >> 16u;
    uint first_weight = normal_weights.w & 0xFFFFu;
    for (uint k = 0u; k < targets; ++k) {
        float w = morph_weights[first_weight + k];
        int delta = int(2u * (position_morph.w + k));
        position += w * texelFetch(delta_texels, delta).xyz;
        normal += w * texelFetch(delta_texels, delta + 1).xyz;
    }

    // The blended matrix (only its top three rows matter: palette matrices are affine). The used pairs
    // come first, and a vertex has at least one.
    uvec4 slots = texelFetch(vertex_texels, texel + 2);
    vec4 w0 = uintBitsToFloat(texelFetch(vertex_texels, texel + 3));
    Blend m = weighted_rows(w0.x, slots.x & 0xFFFFu);
    if (kInfluences > 1u) add_influence(m, w0.y, slots.x >> 16u);
    if (kInfluences > 2u) add_influence(m, w0.z, slots.y & 0xFFFFu);
    if (kInfluences > 3u) add_influence(m, w0.w, slots.y >> 16u);
    if (kInfluences > 4u) {
        vec4 w1 = uintBitsToFloat(texelFetch(vertex_texels, texel + 4));
        if (w1 != vec4(0.0)) {
            add_influence(m, w1.x, slots.z & 0xFFFFu);
            if (kInfluences > 5u) add_influence(m, w1.y, slots.z >> 16u);
            if (kInfluences > 6u) add_influence(m, w1.z, slots.w & 0xFFFFu);
            if (kInfluences > 7u) add_influence(m, w1.w, slots.w >> 16u);
        }
    }

    vec4 homogeneous = vec4(position, 1.0);
    vec3 p = vec3(dot(m.r0, homogeneous), dot(m.r1, homogeneous), dot(m.r2, homogeneous));
    // Inverse transpose by cofactors: its columns are the cross products of the matrix's columns,
    // over det; only det's sign survives the normalisation (and a singular matrix still gives one).
    vec3 c0 = vec3(m.r0.x, m.r1.x, m.r2.x), c1 = vec3(m.r0.y, m.r1.y, m.r2.y), c2 = vec3(m.r0.z, m.r1.z, m.r2.z);
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
