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

// The polygon's window depth change per pixel along x and y (rows from the top), from its projected
// corners; zero where the polygon is seen edge-on.
vec2 window_depth_slope(PolygonFrame polygon, mat4 model_view_proj, vec2 viewport) {
    vec4 a = model_view_proj * vec4(polygon.origin, 1.0);
    vec4 b = model_view_proj * vec4(polygon.origin + polygon.edge_u, 1.0);
    vec4 c = model_view_proj * vec4(polygon.origin + polygon.edge_v, 1.0);
    vec2 half_size = 0.5 * viewport;
    if (a.w <= 0.0 || b.w <= 0.0 || c.w <= 0.0) {
        // A corner behind the eye (a floor seen from just above it, whose stipples near the eye are large
        // dots that were cut in half): the plane's window depth is still affine in the window coordinates,
        // z/w = k0 + kx x/w + ky y/w, so z = k0 w + kx x + ky y holds at every clip-space point of the plane;
        // solved for (kx, ky, k0) from its corner and two edge directions, no division by w.
        vec4 u = b - a, v = c - a;
        mat3 rows = transpose(mat3(vec3(a.x, a.y, a.w), vec3(u.x, u.y, u.w), vec3(v.x, v.y, v.w)));
        float det = determinant(rows);
        float scale = length(vec3(a.x, a.y, a.w)) * length(vec3(u.x, u.y, u.w)) * length(vec3(v.x, v.y, v.w));
        if (!(abs(det) > 1e-6 * scale)) return vec2(0.0);
        vec3 k = inverse(rows) * vec3(a.z, u.z, v.z);
        return vec2(k.x / half_size.x, -k.y / half_size.y);
    }
    vec3 wa = vec3(a.xy / a.w * vec2(half_size.x, -half_size.y), a.z / a.w);
    vec3 e1 = vec3(b.xy / b.w * vec2(half_size.x, -half_size.y), b.z / b.w) - wa;
    vec3 e2 = vec3(c.xy / c.w * vec2(half_size.x, -half_size.y), c.z / c.w) - wa;
    float det = e1.x * e2.y - e1.y * e2.x;
    if (abs(det) < 1e-3) return vec2(0.0);
    return vec2(e1.z * e2.y - e2.z * e1.y, e2.z * e1.x - e1.z * e2.x) / det;
}
#endif
