#version 460
// An animated object's per-polygon constants from its deformed mesh (after shaders/deform.comp, before
// the density pass): center, unit normal and area, packed as src/render/polygon_constants.cpp packs
// them for a static object. The center is quantised in the object's box, which holds every pose of
// every animation (ObjectUniforms.box_*), so it never leaves it. The selection value (§2.3) belongs to
// the polygon, not to its shape: it is kept. One invocation per polygon.
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"
#include "stipple_formulas.h"
#include "stipple_position.h"

layout(local_size_x = kDensityWorkgroupSize) in;

layout(set = 0, binding = kBindingObject) uniform ObjectBlock { ObjectUniforms object; };
layout(set = 0, binding = kBindingTriangleInfo, std430) buffer TriangleInfos { TriangleInfo infos[]; };

void main() {
    uint t = gl_GlobalInvocationID.x;
    if (t >= object.flags.y) return;
    // The arithmetic of pack_polygon_constants, so a rest pose packs as a static object does.
    vec3 a = mesh_vertex(mesh_indices[3u * t]);
    vec3 b = mesh_vertex(mesh_indices[3u * t + 1u]);
    vec3 c = mesh_vertex(mesh_indices[3u * t + 2u]);
    vec3 cross_product = cross(b - a, c - a);
    float len = length(cross_product);
    vec3 normal = len > 0.0 ? cross_product / len : vec3(0.0, 0.0, 1.0);
    vec3 center = (a + b + c) / 3.0;
    vec3 inverse_size = vec3(1.0) / max(object.box_size.xyz, vec3(1e-30));
    vec3 unit = clamp((center - object.box_min.xyz) * inverse_size, 0.0, 1.0);

    TriangleInfo info;
    info.center_xy = packUnorm2x16(unit.xy);
    info.center_z_selection = (packUnorm2x16(vec2(unit.z, 0.0)) & 0xFFFFu) | (infos[t].center_z_selection & 0xFFFF0000u);
    info.normal = packSnorm2x16(unit_to_octahedral(normal));
    info.area = 0.5 * len;
    infos[t] = info;
}
