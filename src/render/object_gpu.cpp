#include "render/object_gpu.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/gtc/matrix_inverse.hpp>

#include "core/error.hpp"
#include "gpu/context.hpp"
#include "render/density_formulas.hpp"
#include "render/deform_pass.hpp"
#include "render/descriptor_schema.hpp"
#include "render/path_buffers.hpp"
#include "render/polygon_constants.hpp"
#include "render/shared_types.hpp"
#include "render/silhouette_edges.hpp"
#include "render/stipple_renderer.hpp"

namespace stipple {

using gpu::Buffer;
using gpu::MemoryUse;

namespace {

// Each candidate as (u, v) in its triangle, position = a + u (b - a) + v (c - a), 16 bits each.
std::vector<gpu::StippleVertex> pack_stipples(const Mesh& mesh, const StippleSet& stipples) {
    auto unorm16 = [](float value) { return uint32_t(std::lround(std::clamp(value, 0.0f, 1.0f) * 65535.0f)); };
    std::vector<gpu::StippleVertex> vertices(stipples.size());
    for (size_t i = 0; i < vertices.size(); ++i) {
        const uint32_t t = stipples.triangle[i];
        const glm::dvec3 a = mesh.positions[mesh.indices[3 * t]];
        const glm::dvec3 e0 = glm::dvec3(mesh.positions[mesh.indices[3 * t + 1]]) - a;
        const glm::dvec3 e1 = glm::dvec3(mesh.positions[mesh.indices[3 * t + 2]]) - a;
        const glm::dvec3 d = glm::dvec3(stipples.positions[i]) - a;
        const double d00 = glm::dot(e0, e0), d01 = glm::dot(e0, e1), d11 = glm::dot(e1, e1);
        const double denominator = d00 * d11 - d01 * d01;
        double u = 0.0, v = 0.0;  // a degenerate polygon holds its stipples at a corner
        if (denominator > 0.0) {
            u = (d11 * glm::dot(d, e0) - d01 * glm::dot(d, e1)) / denominator;
            v = (d00 * glm::dot(d, e1) - d01 * glm::dot(d, e0)) / denominator;
        }
        vertices[i] = {unorm16(float(u)) | unorm16(float(v)) << 16, t};
    }
    return vertices;
}

ObjectGeometry upload_geometry(const gpu::Context& context, const Mesh& mesh, const StippleSet& stipples) {
    ObjectGeometry geometry;
    geometry.index_count = uint32_t(mesh.indices.size());
    geometry.triangle_count = uint32_t(mesh.triangle_count());
    geometry.stipple_count = uint32_t(stipples.size());
    geometry.first_stipple.assign(stipples.first.begin(), stipples.first.end());
    const auto storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    // The stipple shaders read the corners of the polygons whose stipples they place.
    geometry.positions =
        gpu::create_device_buffer(context, std::span(mesh.positions), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | storage);
    // Storage too: an animated object's deformation pass writes them.
    geometry.normals =
        gpu::create_device_buffer(context, std::span(mesh.normals), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | storage);
    geometry.indices =
        gpu::create_device_buffer(context, std::span(mesh.indices), VK_BUFFER_USAGE_INDEX_BUFFER_BIT | storage);
    std::vector<gpu::StippleVertex> vertices = pack_stipples(mesh, stipples);
    geometry.stipples = gpu::create_device_buffer(context, std::span<const gpu::StippleVertex>(vertices),
                                                  VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | storage);
    // A placeholder until the object first draws lines (the descriptor set needs a buffer in every binding).
    geometry.silhouette_edges = Buffer(context, kPathBufferPlaceholderBytes, storage, MemoryUse::DeviceLocal);
    return geometry;
}

Buffer make_lines_buffer(const gpu::Context& context, VkDeviceSize bytes) {
    return Buffer(context, bytes,
                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDEX_BUFFER_BIT |
                      VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                  MemoryUse::DeviceLocal);
}

ObjectFrame create_frame_state(const gpu::Context& context, const ObjectGeometry& geometry, bool count_drawn) {
    ObjectFrame frame;
    const auto storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    std::vector<gpu::TriangleDraw> draws(geometry.triangle_count);
    for (size_t t = 0; t < draws.size(); ++t) draws[t] = {0.0f, geometry.first_stipple[t]};
    frame.triangle_draw = gpu::create_device_buffer(context, std::span<const gpu::TriangleDraw>(draws), storage);
    for (PathBuffer kind : kPathBuffers)
        path_buffer(frame, kind) = make_path_buffer(context, kind, kPathBufferPlaceholderBytes);
    frame.silhouette_lines = make_lines_buffer(context, kPathBufferPlaceholderBytes);
    const VkDeviceSize mask_bytes = count_drawn ? sizeof(uint32_t) * ((geometry.stipple_count + 31) / 32) : 0;
    frame.debug = Buffer(context, sizeof(gpu::DebugCounters) + mask_bytes, storage | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                         MemoryUse::Readback);
    frame.object_uniforms =
        Buffer(context, sizeof(gpu::ObjectUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryUse::Upload);
    return frame;
}

// Lengths scale by this much from object to world (the mean for non-uniform scales).
float linear_scale(const glm::mat4& model) { return std::cbrt(std::abs(glm::determinant(glm::mat3(model)))); }

}  // namespace

ObjectGpu::~ObjectGpu() {
    if (pool) vkDestroyDescriptorPool(context->device, pool, nullptr);
}

std::unique_ptr<ObjectGpu> create_object_gpu(const gpu::Context& context, VkDescriptorSetLayout set_layout,
                                             const Buffer& frame_uniforms, const Mesh& mesh,
                                             const StippleSet& stipples, const glm::mat4& model,
                                             const ObjectParams& params, bool count_drawn,
                                             const anim::Motion& motion) {
    validate_params(params);
    STIPPLE_CHECK(stipples.first.size() == mesh.triangle_count() + 1, "stipple set does not match the mesh");
    if (params.point_size > context.features.max_point_size)
        fail("--point-size " + std::to_string(params.point_size) + " exceeds this device's maximum of " +
             std::to_string(context.features.max_point_size));

    auto object = std::make_unique<ObjectGpu>();
    object->context = &context;
    object->frame_uniforms = frame_uniforms.handle();
    object->params = params;
    object->model = model;
    object->geometry = upload_geometry(context, mesh, stipples);
    object->polygons = make_polygon_constants(context, mesh, stipples, params.generation.seed,
                                              motion ? &motion.headroom->bounds : nullptr);
    object->frame = create_frame_state(context, object->geometry, count_drawn);
    if (motion) object->animation = create_object_animation(context, *object, mesh, motion);
    check_animated_path(*object);
    create_object_descriptors(context, set_layout, *object);
    ensure_path_buffers(*object, params.density_path);
    return object;
}

void ensure_silhouette_edges(ObjectGpu& object) {
    ObjectGeometry& geometry = object.geometry;
    if (geometry.silhouette_edges_built) return;
    geometry.silhouette_edges_built = true;
    // Read back from the GPU: the object keeps no CPU copy of its mesh, and most objects never need this.
    std::vector<std::byte> bytes = gpu::read_buffer(*object.context, geometry.indices);
    std::vector<uint32_t> indices(geometry.index_count);
    std::memcpy(indices.data(), bytes.data(), sizeof(uint32_t) * indices.size());
    std::vector<gpu::SilhouetteEdge> edges = build_silhouette_edges(indices);
    geometry.silhouette_edge_count = uint32_t(edges.size());
    if (edges.empty()) return;
    geometry.silhouette_edges = gpu::create_device_buffer(*object.context, std::span<const gpu::SilhouetteEdge>(edges),
                                                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    object.frame.silhouette_lines =
        make_lines_buffer(*object.context, gpu::kSilhouetteLinesHeaderBytes + 2 * sizeof(uint32_t) * edges.size());
    write_object_descriptors(object);
}

gpu::ObjectUniforms make_object_uniforms(const ObjectGpu& object, const FrameView& view) {
    const ObjectParams& p = object.params;
    const Sphere& bounds = object.polygons.bounds;
    gpu::ObjectUniforms u{};
    u.model = object.model;
    u.model_view = view.camera.view * object.model;
    u.normal_view = glm::inverseTranspose(u.model_view);
    float scale = linear_scale(object.model);
    float radius_world = std::max(bounds.radius * scale, 1e-20f);
    u.shading = glm::vec4(p.shading_exponent, p.point_size, p.toon_sharpness, 0.0f);
    // Reference view of generation: the bounding-sphere radius spans kReferenceHeight / 2 pixels.
    u.extrinsic = glm::vec4(p.pr, p.min_area, 0.5f * kReferenceHeight / radius_world, scale * scale);
    glm::vec3 center_view = glm::vec3(u.model_view * glm::vec4(bounds.center, 1.0f));
    u.intrinsic = glm::vec4(p.de, radius_world, -center_view.z, 0.0f);
    uint32_t flags = gpu::kFlagBackfaceCull;
    if (p.shading) flags |= gpu::kFlagShading;
    if (p.extrinsic) flags |= gpu::kFlagExtrinsic;
    if (p.intrinsic) flags |= gpu::kFlagIntrinsic;
    if (p.point_size > 2.5f) flags |= gpu::kFlagRoundPoints;
    if (p.toon) flags |= gpu::kFlagToonFade;
    if (object.animation) flags |= gpu::kFlagStretch;
    const ObjectGeometry& g = object.geometry;
    u.flags = glm::uvec4(flags, g.triangle_count, g.silhouette_edge_count, g.stipple_count);
    u.box_min = glm::vec4(object.polygons.box_min, 0.0f);
    u.box_size = glm::vec4(object.polygons.box_size, 0.0f);
    return u;
}

float object_line_width(const ObjectGpu& object, const FrameView& view, float max_width) {
    const Sphere& bounds = object.polygons.bounds;
    float radius_world = bounds.radius * linear_scale(object.model);
    glm::vec3 center_view = glm::vec3(view.camera.view * object.model * glm::vec4(bounds.center, 1.0f));
    float distance = std::max(-center_view.z, 1e-6f);
    float projected_radius = radius_world * view.camera.proj[1][1] * 0.5f * float(view.extent.height) / distance;
    float width = formulas::silhouette_line_width(object.params.silhouette_width, projected_radius,
                                                  object.params.silhouette_thinning);
    return std::min(width, max_width);
}

}  // namespace stipple
