#version 460
// An animated object's per-polygon constants from its deformed mesh (after shaders/deform.comp, before
// the density pass): center, unit normal and area, packed as src/render/polygon_constants.cpp packs
// them for a static object. The center is quantised in the object's box, which holds every pose of
// every animation, so it never leaves it. The selection value (§2.3) belongs to the polygon, not to its
// shape: it is kept. One invocation per polygon. The mesh is read through texel buffers: on a software
// GPU a fetch gathers a texel at once, where a storage buffer is read float by float, lane by lane.
#extension GL_GOOGLE_include_directive : require
#include "deform_types.h"
#include "dispatch.h"
#include "stipple_formulas.h"

layout(local_size_x = kDensityWorkgroupSize) in;

layout(set = 0, binding = kBindingPolygonPositions) uniform samplerBuffer mesh_positions;
layout(set = 0, binding = kBindingPolygonIndices) uniform usamplerBuffer mesh_indices;
layout(set = 0, binding = kBindingPolygonInfos, std430) buffer TriangleInfos { TriangleInfo infos[]; };
layout(push_constant) uniform Push { PolygonConstantsPush push; };
layout(constant_id = kSpecPolygonVec3Texels) const bool kVec3Texels = true;

vec3 vertex_at(uint index) {
    if (kVec3Texels) return texelFetch(mesh_positions, int(index)).xyz;
    return vec3(texelFetch(mesh_positions, int(3u * index)).x, texelFetch(mesh_positions, int(3u * index + 1u)).x,
                texelFetch(mesh_positions, int(3u * index + 2u)).x);
}

uvec3 triangle_at(uint t) {
    if (kVec3Texels) return texelFetch(mesh_indices, int(t)).xyz;
    return uvec3(texelFetch(mesh_indices, int(3u * t)).x, texelFetch(mesh_indices, int(3u * t + 1u)).x,
                 texelFetch(mesh_indices, int(3u * t + 2u)).x);
}

void main() {
    uint t = linear_invocation();
    if (t >= push.triangle_count) return;
    // The arithmetic of pack_polygon_constants, so a rest pose packs as a static object does.
    uvec3 corners = triangle_at(t);
    vec3 a = vertex_at(corners.x);
    vec3 b = vertex_at(corners.y);
    vec3 c = vertex_at(corners.z);
    // The CPU works in double; here the edges are divided by their largest component first, so neither
    // the cross product nor its squared length overflows single precision (it did for edges beyond
    // ~1e9 units: an infinite length, a zero normal). The area is that scale squared times half the
    // scaled length, infinite only where the CPU's float area is too.
    vec3 edge_ab = b - a, edge_ac = c - a;
    vec3 largest = max(abs(edge_ab), abs(edge_ac));
    float scale = max(largest.x, max(largest.y, largest.z));
    vec3 cross_product = scale > 0.0 ? cross(edge_ab / scale, edge_ac / scale) : vec3(0.0);
    float len = length(cross_product);
    vec3 normal = len > 0.0 ? cross_product / len : vec3(0.0, 0.0, 1.0);
    vec3 center = (a + b + c) / 3.0;
    vec3 inverse_size = vec3(1.0) / max(push.box_size.xyz, vec3(1e-30));
    vec3 unit = clamp((center - push.box_min.xyz) * inverse_size, 0.0, 1.0);

    TriangleInfo info;
    info.center_xy = packUnorm2x16(unit.xy);
    info.center_z_selection = (packUnorm2x16(vec2(unit.z, 0.0)) & 0xFFFFu) | (infos[t].center_z_selection & 0xFFFF0000u);
    info.normal = packSnorm2x16(unit_to_octahedral(normal));
    info.area = (0.5 * len * scale) * scale;
    infos[t] = info;
}
