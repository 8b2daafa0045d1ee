// A candidate stipple's object-space position from its polygon and its place in it (StippleVertex,
// shared_types.h): a + u (b - a) + v (c - a). Declares the mesh's texel buffers (set 0) it reads.
//
// Texel buffers, not storage buffers: a software GPU (lavapipe) loads a storage buffer float by float
// and lane by lane, where a texel fetch gathers a whole texel for every lane at once. The corners were
// twelve such loads; on the vertex path, where lavapipe runs them for every candidate (the survivors'
// code under a mask), they were two thirds of the pass (docs/architecture.md).
#ifndef STIPPLE_POSITION_H
#define STIPPLE_POSITION_H

layout(set = 0, binding = kBindingMeshPositions) uniform samplerBuffer mesh_positions;
layout(set = 0, binding = kBindingMeshIndices) uniform usamplerBuffer mesh_indices;
// The candidates (StippleVertex), a texel each, for passes that read them at scattered places.
layout(set = 0, binding = kBindingStippleTexels) uniform usamplerBuffer stipple_texels;
// Three-component texel buffers are optional in Vulkan: without them each texel holds one float (index).
layout(constant_id = kSpecMeshVec3Texels) const bool kMeshVec3Texels = true;

vec3 mesh_vertex(uint index) {
    if (kMeshVec3Texels) return texelFetch(mesh_positions, int(index)).xyz;
    return vec3(texelFetch(mesh_positions, int(3u * index)).x, texelFetch(mesh_positions, int(3u * index + 1u)).x,
                texelFetch(mesh_positions, int(3u * index + 2u)).x);
}

uvec3 mesh_triangle(uint triangle) {
    if (kMeshVec3Texels) return texelFetch(mesh_indices, int(triangle)).xyz;
    return uvec3(texelFetch(mesh_indices, int(3u * triangle)).x, texelFetch(mesh_indices, int(3u * triangle + 1u)).x,
                 texelFetch(mesh_indices, int(3u * triangle + 2u)).x);
}

StippleVertex stipple_vertex(uint index) {
    uvec2 texel = texelFetch(stipple_texels, int(index)).xy;
    return StippleVertex(texel.x, texel.y);
}

// The polygon's corner a and its edges b - a, c - a.
struct PolygonFrame {
    vec3 origin;
    vec3 edge_u;
    vec3 edge_v;
};

PolygonFrame polygon_frame(uint triangle) {
    uvec3 corners = mesh_triangle(triangle);
    vec3 a = mesh_vertex(corners.x);
    vec3 b = mesh_vertex(corners.y);
    vec3 c = mesh_vertex(corners.z);
    return PolygonFrame(a, b - a, c - a);
}

// The polygon's corners in view space (stipple_density_here, polygon_density_bounds).
void view_corners(uint triangle, mat4 model_view, out vec3 a, out vec3 b, out vec3 c) {
    uvec3 corners = mesh_triangle(triangle);
    a = vec3(model_view * vec4(mesh_vertex(corners.x), 1.0f));
    b = vec3(model_view * vec4(mesh_vertex(corners.y), 1.0f));
    c = vec3(model_view * vec4(mesh_vertex(corners.z), 1.0f));
}

vec3 stipple_position(PolygonFrame polygon, vec2 barycentric) {
    return polygon.origin + barycentric.x * polygon.edge_u + barycentric.y * polygon.edge_v;
}

// The window depth change per pixel along x and y (rows from the top) of a plane through clip-space point
// `at` spanned by clip-space directions u and v (the model-view-projection applied with w = 0); zero where
// the plane is seen edge-on. The window depth is affine in the window coordinates, z/w = k0 + kx x/w + ky y/w,
// so z = k0 w + kx x + ky y at every clip-space point of the plane: solved for (kx, ky, k0) from the point
// and the two directions, with no division by w, so a polygon with a corner behind the eye has its slope too
// (a floor seen from just above it, whose large dots near the eye were half discs until 2026-12-05).
vec2 window_depth_slope_at(vec4 at, vec4 u, vec4 v, vec2 viewport) {
    mat3 rows = transpose(mat3(vec3(at.x, at.y, at.w), vec3(u.x, u.y, u.w), vec3(v.x, v.y, v.w)));
    float det = determinant(rows);
    float scale = length(vec3(at.x, at.y, at.w)) * length(vec3(u.x, u.y, u.w)) * length(vec3(v.x, v.y, v.w));
    if (!(abs(det) > 1e-6 * scale)) return vec2(0.0);
    vec3 k = inverse(rows) * vec3(at.z, u.z, v.z);
    return vec2(k.x, -k.y) / (0.5 * viewport);
}

// The polygon's window depth slope (window_depth_slope_at), from its corner and edges.
vec2 window_depth_slope(PolygonFrame polygon, mat4 model_view_proj, vec2 viewport) {
    return window_depth_slope_at(model_view_proj * vec4(polygon.origin, 1.0), model_view_proj * vec4(polygon.edge_u, 0.0),
                                 model_view_proj * vec4(polygon.edge_v, 0.0), viewport);
}
#endif
