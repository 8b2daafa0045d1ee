#version 460
// The triangles the depth pass draws this frame, for an object whose triangles are small on screen:
// those that may cover a pixel centre of the frame. The others produce no fragment, so leaving them
// out of the depth pass changes no depth, no stencil and no colour, but each of them costs a software
// rasteriser its triangle setup on its one geometry thread: on a 650k-triangle hand at 1280x1024 two
// thirds of them cover no pixel centre (docs/architecture.md). One invocation per triangle; the kept
// triangles' indices are appended to DepthTriangles, whose header is the depth pass's indexed indirect draw.
//
// Conservative by construction: a triangle is dropped only when its screen box holds no pixel centre
// of the frame, when each of the few centres in its box lies outside it by more than kMargin pixels, or,
// for an object whose depth pass culls the faces facing away, when it clearly faces away. The rasteriser
// snaps corners to 1/256 pixel, and this pass may round window coordinates differently from the vertex
// stage by far less: a margin of 1/32 pixel, and an orientation trusted only when its doubled area
// exceeds a 64th of the perimeter (what moving each corner by 1/128 pixel could change). A triangle
// with a corner on or behind the eye plane (w <= 0), one of uncertain orientation, or one whose box
// holds more than kMaxTestedCentres centres is kept.
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "shared_types.h"
#include "dispatch.h"
#include "stipple_position.h"
#include "uniform_branch.h"

layout(local_size_x = kDensityWorkgroupSize) in;

layout(set = 0, binding = kBindingFrame) uniform FrameBlock { FrameUniforms frame; };
layout(set = 0, binding = kBindingObject) uniform ObjectBlock { ObjectUniforms object; };
layout(set = 0, binding = kBindingDepthTriangles, std430) buffer DepthList {
    DepthTriangles header;
    uint depth_indices[];
};

const float kMargin = 1.0f / 32.0f;
const int kMaxTestedCentres = 16;

// Window coordinates as the depth pass's viewport maps them (y down: StippleRenderer::begin_rendering).
vec2 to_window(vec4 clip) {
    vec2 ndc = clip.xy / clip.w;
    return vec2((ndc.x * 0.5f + 0.5f) * frame.viewport.x, (0.5f - ndc.y * 0.5f) * frame.viewport.y);
}

// `one_sided`: the depth pass culls the faces facing away (front faces wind counter-clockwise with y
// up, so clockwise in these y-down coordinates: a negative doubled area).
bool may_cover_pixel_centre(vec4 c0, vec4 c1, vec4 c2, bool one_sided) {
    if (c0.w <= 0.0f || c1.w <= 0.0f || c2.w <= 0.0f) return true;
    vec2 corners[3] = vec2[3](to_window(c0), to_window(c1), to_window(c2));
    vec3 lengths = vec3(length(corners[1] - corners[0]), length(corners[2] - corners[1]), length(corners[0] - corners[2]));
    float doubled_area = (corners[1].x - corners[0].x) * (corners[2].y - corners[0].y) -
                         (corners[2].x - corners[0].x) * (corners[1].y - corners[0].y);
    bool certain = abs(doubled_area) > (lengths.x + lengths.y + lengths.z) * (1.0f / 64.0f);
    if (one_sided && certain && doubled_area > 0.0f) return false;  // faces away: culled by the depth pass
    // Pixel centres x + 0.5 inside the box (widened by the margin), within the frame. The box is
    // clamped before it becomes integers: a corner near the eye plane lies very far out.
    vec2 lo = clamp(min(corners[0], min(corners[1], corners[2])) - kMargin, vec2(-1.0f), frame.viewport.xy + 1.0f);
    vec2 hi = clamp(max(corners[0], max(corners[1], corners[2])) + kMargin, vec2(-1.0f), frame.viewport.xy + 1.0f);
    ivec2 first = max(ivec2(ceil(lo - 0.5f)), ivec2(0));
    ivec2 last = min(ivec2(floor(hi - 0.5f)), ivec2(frame.viewport.xy) - 1);
    if (any(lessThan(last, first))) return false;  // no pixel centre of the frame in its box
    ivec2 span = last - first + 1;
    if (!certain || span.x * span.y > kMaxTestedCentres) return true;
    // Each edge's signed distance to a centre, positive inside, must be at least -kMargin.
    float orientation = sign(doubled_area);
    vec3 nx, ny, offset;
    for (int e = 0; e < 3; ++e) {
        vec2 a = corners[e], b = corners[(e + 1) % 3];
        vec2 normal = orientation * vec2(-(b.y - a.y), b.x - a.x) / lengths[e];
        nx[e] = normal.x;
        ny[e] = normal.y;
        offset[e] = -dot(normal, a) + kMargin;
    }
    for (int y = first.y; y <= last.y; ++y)
        for (int x = first.x; x <= last.x; ++x) {
            vec2 centre = vec2(x, y) + 0.5f;
            vec3 distance = nx * centre.x + ny * centre.y + offset;
            if (all(greaterThanEqual(distance, vec3(0.0f)))) return true;
        }
    return false;
}

void main() {
    // object.flags.x, read where lavapipe cannot fold it (uniform_branch.h)
    bool one_sided = (object.flags[unfoldable_zero()] & kFlagDepthOneSided) != 0u;
    uint t = linear_invocation();
    bool keep = false;
    uvec3 corners = uvec3(0u);
    if (t < object.flags.y) {
        corners = mesh_triangle(t);
        vec4 c0 = object.model_view_proj * vec4(mesh_vertex(corners.x), 1.0f);
        vec4 c1 = object.model_view_proj * vec4(mesh_vertex(corners.y), 1.0f);
        vec4 c2 = object.model_view_proj * vec4(mesh_vertex(corners.z), 1.0f);
        keep = may_cover_pixel_centre(c0, c1, c2, one_sided);
    }
    // One atomic add per subgroup for its kept triangles, each lane's place from a prefix sum.
    uint indices = keep ? 3u : 0u;
    uint kept_here = subgroupAdd(indices);
    if (kept_here == 0u) return;
    uint base = 0u;
    if (subgroupElect()) base = atomicAdd(header.index_count, kept_here);
    base = subgroupBroadcastFirst(base) + subgroupExclusiveAdd(indices);
    if (keep) {
        depth_indices[base] = corners.x;
        depth_indices[base + 1u] = corners.y;
        depth_indices[base + 2u] = corners.z;
    }
}
