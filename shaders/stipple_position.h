// A candidate stipple's object-space position from its polygon and its place in it (StippleVertex,
// shared_types.h): a + u (b - a) + v (c - a). Declares the mesh buffers (set 0) it reads.
#ifndef STIPPLE_POSITION_H
#define STIPPLE_POSITION_H

layout(set = 0, binding = kBindingMeshPositions, std430) readonly buffer MeshPositions { float mesh_positions[]; };
layout(set = 0, binding = kBindingMeshIndices, std430) readonly buffer MeshIndices { uint mesh_indices[]; };

vec3 mesh_vertex(uint index) {
    return vec3(mesh_positions[3u * index], mesh_positions[3u * index + 1u], mesh_positions[3u * index + 2u]);
}

// The polygon's corner a and its edges b - a, c - a.
struct PolygonFrame {
    vec3 origin;
    vec3 edge_u;
    vec3 edge_v;
};

PolygonFrame polygon_frame(uint triangle) {
    vec3 a = mesh_vertex(mesh_indices[3u * triangle]);
    vec3 b = mesh_vertex(mesh_indices[3u * triangle + 1u]);
    vec3 c = mesh_vertex(mesh_indices[3u * triangle + 2u]);
    return PolygonFrame(a, b - a, c - a);
}

vec3 stipple_position(PolygonFrame polygon, vec2 barycentric) {
    return polygon.origin + barycentric.x * polygon.edge_u + barycentric.y * polygon.edge_v;
}

#endif
