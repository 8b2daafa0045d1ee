#include "render/object_gpu.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/packing.hpp>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "gpu/context.hpp"
#include "gpu/shared_types.hpp"
#include "gpu/vk_check.hpp"
#include "render/density_cpu.hpp"
#include "render/density_formulas.hpp"
#include "render/silhouette_edges.hpp"
#include "render/stipple_renderer.hpp"
#include "stipple/selection_order.hpp"

namespace stipple {

using gpu::Buffer;
using gpu::MemoryUse;

namespace {

// The inverse of formulas::octahedral_to_unit: the unit sphere onto the octahedron, the lower half folded out.
glm::vec2 unit_to_octahedral(glm::vec3 n) {
    n /= std::abs(n.x) + std::abs(n.y) + std::abs(n.z);
    glm::vec2 p(n.x, n.y);
    if (n.z < 0.0f) {
        glm::vec2 sign(p.x >= 0.0f ? 1.0f : -1.0f, p.y >= 0.0f ? 1.0f : -1.0f);
        p = (1.0f - glm::abs(glm::vec2(p.y, p.x))) * sign;
    }
    return p;
}

uint32_t unorm16(float value) { return uint32_t(std::lround(std::clamp(value, 0.0f, 1.0f) * 65535.0f)); }

// Packed per-polygon constants (shared_types.h: TriangleInfo), centroids in the box [box_min, box_min + box_size].
std::vector<gpu::TriangleInfo> triangle_infos(const Mesh& mesh, const StippleSet& stipples, uint64_t stipples_seed,
                                              glm::vec3 box_min, glm::vec3 box_size) {
    std::vector<gpu::TriangleInfo> infos(mesh.triangle_count());
    std::vector<float> selection = stipples.selection.size() == infos.size()
                                       ? stipples.selection
                                       : polygon_selection_values(mesh, stipples_seed);
    const glm::vec3 inverse_size = glm::vec3(1.0f) / glm::max(box_size, glm::vec3(1e-30f));
    for (size_t t = 0; t < infos.size(); ++t) {
        glm::vec3 a = mesh.positions[mesh.indices[3 * t]];
        glm::vec3 b = mesh.positions[mesh.indices[3 * t + 1]];
        glm::vec3 c = mesh.positions[mesh.indices[3 * t + 2]];
        glm::vec3 cross = glm::cross(b - a, c - a);
        float length = glm::length(cross);
        glm::vec3 normal = length > 0.0f ? cross / length : glm::vec3(0.0f, 0.0f, 1.0f);
        glm::vec3 center = ((a + b + c) / 3.0f - box_min) * inverse_size;
        uint32_t selection_step = std::min(uint32_t(selection[t] * 65536.0f), 65535u);
        infos[t].center_xy = unorm16(center.x) | unorm16(center.y) << 16;
        infos[t].center_z_selection = unorm16(center.z) | selection_step << 16;
        infos[t].normal = glm::packSnorm2x16(unit_to_octahedral(normal));
        infos[t].area = 0.5f * length;
    }
    return infos;
}

// Each candidate as (u, v) in its triangle, position = a + u (b - a) + v (c - a), 16 bits each.
std::vector<gpu::StippleVertex> pack_stipples(const Mesh& mesh, const StippleSet& stipples) {
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

// Lengths scale by this much from object to world (the mean for non-uniform scales).
float linear_scale(const glm::mat4& model) { return std::cbrt(std::abs(glm::determinant(glm::mat3(model)))); }

Buffer make_path_buffer(const gpu::Context& context, PathBuffer kind, VkDeviceSize bytes) {
    const auto storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    const auto indirect = VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT;
    const auto destination = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    switch (kind) {
        case PathBuffer::DrawnPolygons:
        case PathBuffer::GpuCommands:  // written by a compute pass, read as indirect arguments
            return Buffer(context, bytes, storage | indirect | destination, MemoryUse::DeviceLocal);
        case PathBuffer::DrawStaging: return Buffer(context, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::Upload);
        case PathBuffer::CpuCommands: break;
    }
    return Buffer(context, bytes, indirect, MemoryUse::Upload);
}

Buffer make_lines_buffer(const gpu::Context& context, VkDeviceSize bytes) {
    return Buffer(context, bytes,
                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDEX_BUFFER_BIT |
                      VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                  MemoryUse::DeviceLocal);
}

void write_descriptors(VkDevice device, VkDescriptorSet set, VkBuffer frame_uniforms, const ObjectGpu& object) {
    struct Entry {
        uint32_t binding;
        VkDescriptorType type;
        VkBuffer buffer;
    };
    const Entry entries[] = {
        {gpu::kBindingFrame, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, frame_uniforms},
        {gpu::kBindingObject, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, object.object_uniforms.handle()},
        {gpu::kBindingTriangleDraw, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, object.triangle_draw.handle()},
        {gpu::kBindingTriangleInfo, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, object.triangle_info.handle()},
        {gpu::kBindingDrawCommands, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, object.gpu_commands.handle()},
        {gpu::kBindingDebug, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, object.debug.handle()},
        {gpu::kBindingStipples, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, object.stipples.handle()},
        {gpu::kBindingDrawnPolygons, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, object.drawn_polygons.handle()},
        {gpu::kBindingMeshPositions, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, object.positions.handle()},
        {gpu::kBindingMeshIndices, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, object.indices.handle()},
        {gpu::kBindingSilhouetteEdges, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, object.silhouette_edges.handle()},
        {gpu::kBindingSilhouetteLines, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, object.silhouette_lines.handle()},
    };
    VkDescriptorBufferInfo infos[std::size(entries)];
    VkWriteDescriptorSet writes[std::size(entries)];
    for (size_t i = 0; i < std::size(entries); ++i) {
        infos[i] = {entries[i].buffer, 0, VK_WHOLE_SIZE};
        writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[i].dstSet = set;
        writes[i].dstBinding = entries[i].binding;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = entries[i].type;
        writes[i].pBufferInfo = &infos[i];
    }
    vkUpdateDescriptorSets(device, uint32_t(std::size(writes)), writes, 0, nullptr);
}

}  // namespace

ObjectGpu::~ObjectGpu() {
    if (pool) vkDestroyDescriptorPool(device, pool, nullptr);
}

std::unique_ptr<ObjectGpu> create_object_gpu(const gpu::Context& context, VkDescriptorSetLayout set_layout,
                                             const Buffer& frame_uniforms, const Mesh& mesh,
                                             const StippleSet& stipples, const glm::mat4& model,
                                             const ObjectParams& params, bool count_drawn) {
    validate_params(params);
    STIPPLE_CHECK(stipples.first.size() == mesh.triangle_count() + 1, "stipple set does not match the mesh");
    if (params.point_size > context.features.max_point_size)
        fail("--point-size " + std::to_string(params.point_size) + " exceeds this device's maximum of " +
             std::to_string(context.features.max_point_size));

    auto object = std::make_unique<ObjectGpu>();
    object->device = context.device;
    object->params = params;
    object->model = model;
    object->bounds = compute_bounding_sphere(mesh);
    object->index_count = uint32_t(mesh.indices.size());
    object->triangle_count = uint32_t(mesh.triangle_count());
    object->stipple_count = uint32_t(stipples.size());
    const Bounds box = compute_bounds(mesh);
    object->box_min = box.min;
    object->box_size = box.max - box.min;
    object->triangles = triangle_infos(mesh, stipples, params.generation.seed, object->box_min, object->box_size);
    object->first_stipple.assign(stipples.first.begin(), stipples.first.end());

    std::vector<gpu::StippleVertex> vertices = pack_stipples(mesh, stipples);
    std::vector<gpu::TriangleDraw> draws(object->triangle_count);
    for (size_t t = 0; t < draws.size(); ++t) draws[t] = {0.0f, object->first_stipple[t]};

    const auto storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    // The stipple shaders read the corners of the polygons whose stipples they place.
    object->positions =
        gpu::create_device_buffer(context, std::span(mesh.positions), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | storage);
    object->normals = gpu::create_device_buffer(context, std::span(mesh.normals), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    object->indices =
        gpu::create_device_buffer(context, std::span(mesh.indices), VK_BUFFER_USAGE_INDEX_BUFFER_BIT | storage);
    object->stipples = gpu::create_device_buffer(context, std::span<const gpu::StippleVertex>(vertices),
                                                 VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | storage);
    object->triangle_info =
        gpu::create_device_buffer(context, std::span<const gpu::TriangleInfo>(object->triangles), storage);
    object->triangle_draw = gpu::create_device_buffer(context, std::span<const gpu::TriangleDraw>(draws), storage);
    // Every path's own buffers start as placeholders (the descriptor set needs a buffer in every binding)
    // and grow when an object first draws with that path: an object costs only what its path uses.
    for (PathBuffer kind : kPathBuffers) path_buffer(*object, kind) = make_path_buffer(context, kind, kPathBufferPlaceholderBytes);
    // The silhouette edges too, built when the object first draws Raskar-Cohen lines.
    object->silhouette_edges = Buffer(context, kPathBufferPlaceholderBytes, storage, MemoryUse::DeviceLocal);
    object->silhouette_lines = make_lines_buffer(context, kPathBufferPlaceholderBytes);
    VkDeviceSize debug_bytes = count_drawn ? 16 + 4 * ((object->stipple_count + 31) / 32) : 16;
    object->debug = Buffer(context, debug_bytes, storage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Readback);
    object->object_uniforms =
        Buffer(context, sizeof(gpu::ObjectUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryUse::Upload);

    object->context = &context;
    object->frame_uniforms = frame_uniforms.handle();
    VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 2}, {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 10}};
    VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool_info.maxSets = 1;
    pool_info.poolSizeCount = uint32_t(std::size(sizes));
    pool_info.pPoolSizes = sizes;
    VK_CHECK(vkCreateDescriptorPool(context.device, &pool_info, nullptr, &object->pool));
    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = object->pool;
    alloc.descriptorSetCount = 1;
    alloc.pSetLayouts = &set_layout;
    VK_CHECK(vkAllocateDescriptorSets(context.device, &alloc, &object->set));
    ensure_path_buffers(*object, params.density_path);
    write_descriptors(context.device, object->set, object->frame_uniforms, *object);
    return object;
}

VkDeviceSize path_buffer_bytes(const ObjectGpu& object, DensityPath path, PathBuffer kind) {
    const VkDeviceSize n = object.triangle_count;
    const VkDeviceSize list = sizeof(gpu::DrawnPolygons) + sizeof(uint32_t) * n;
    switch (kind) {
        case PathBuffer::DrawnPolygons: return draws_by_splat(path) ? list : 0;
        case PathBuffer::DrawStaging:
            if (path == DensityPath::Cpu) return staged_list_offset(object);
            return path == DensityPath::CpuSplat ? staged_list_offset(object) + list : 0;
        case PathBuffer::GpuCommands: return path == DensityPath::Indirect ? 16 + sizeof(gpu::DrawCommand) * n : 0;
        case PathBuffer::CpuCommands: return path == DensityPath::Cpu ? sizeof(gpu::DrawCommand) * n : 0;
    }
    return 0;
}

gpu::Buffer& path_buffer(ObjectGpu& object, PathBuffer kind) {
    switch (kind) {
        case PathBuffer::DrawnPolygons: return object.drawn_polygons;
        case PathBuffer::DrawStaging: return object.draw_staging;
        case PathBuffer::GpuCommands: return object.gpu_commands;
        case PathBuffer::CpuCommands: break;
    }
    return object.cpu_commands;
}

const gpu::Buffer& path_buffer(const ObjectGpu& object, PathBuffer kind) {
    return path_buffer(const_cast<ObjectGpu&>(object), kind);
}

const char* path_buffer_name(PathBuffer kind) {
    switch (kind) {
        case PathBuffer::DrawnPolygons: return "drawn_polygons";
        case PathBuffer::DrawStaging: return "draw_staging";
        case PathBuffer::GpuCommands: return "gpu_commands";
        case PathBuffer::CpuCommands: break;
    }
    return "cpu_commands";
}

void ensure_silhouette_edges(ObjectGpu& object) {
    if (object.silhouette_edges_built) return;
    object.silhouette_edges_built = true;
    // Read back from the GPU: the object keeps no CPU copy of its mesh, and most objects never need this.
    std::vector<std::byte> bytes = gpu::read_buffer(*object.context, object.indices);
    std::vector<uint32_t> indices(object.index_count);
    std::memcpy(indices.data(), bytes.data(), sizeof(uint32_t) * indices.size());
    std::vector<gpu::SilhouetteEdge> edges = build_silhouette_edges(indices);
    object.silhouette_edge_count = uint32_t(edges.size());
    if (edges.empty()) return;
    object.silhouette_edges = gpu::create_device_buffer(*object.context, std::span<const gpu::SilhouetteEdge>(edges),
                                                        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    object.silhouette_lines =
        make_lines_buffer(*object.context, gpu::kSilhouetteLinesHeaderBytes + 2 * sizeof(uint32_t) * edges.size());
    write_descriptors(object.device, object.set, object.frame_uniforms, object);
}

void ensure_path_buffers(ObjectGpu& object, DensityPath path) {
    bool grown = false;
    for (PathBuffer kind : kPathBuffers) {
        VkDeviceSize bytes = path_buffer_bytes(object, path, kind);
        Buffer& buffer = path_buffer(object, kind);
        if (bytes <= buffer.size()) continue;
        buffer = make_path_buffer(*object.context, kind, bytes);
        grown = true;
    }
    if (grown) write_descriptors(object.device, object.set, object.frame_uniforms, object);
}

gpu::ObjectUniforms make_object_uniforms(const ObjectGpu& object, const FrameView& view) {
    const ObjectParams& p = object.params;
    gpu::ObjectUniforms u{};
    u.model = object.model;
    u.model_view = view.camera.view * object.model;
    u.normal_view = glm::inverseTranspose(u.model_view);
    float scale = linear_scale(object.model);
    float radius_world = std::max(object.bounds.radius * scale, 1e-20f);
    u.shading = glm::vec4(p.shading_exponent, p.point_size, p.toon_sharpness, 0.0f);
    // Reference view of generation: the bounding-sphere radius spans kReferenceHeight / 2 pixels.
    u.extrinsic = glm::vec4(p.pr, p.min_area, 0.5f * kReferenceHeight / radius_world, scale * scale);
    glm::vec3 center_view = glm::vec3(u.model_view * glm::vec4(object.bounds.center, 1.0f));
    u.intrinsic = glm::vec4(p.de, radius_world, -center_view.z, 0.0f);
    uint32_t flags = gpu::kFlagBackfaceCull;
    if (p.shading) flags |= gpu::kFlagShading;
    if (p.extrinsic) flags |= gpu::kFlagExtrinsic;
    if (p.intrinsic) flags |= gpu::kFlagIntrinsic;
    if (p.point_size > 2.5f) flags |= gpu::kFlagRoundPoints;
    if (p.toon) flags |= gpu::kFlagToonFade;
    u.flags = glm::uvec4(flags, object.triangle_count, object.silhouette_edge_count, object.stipple_count);
    u.box_min = glm::vec4(object.box_min, 0.0f);
    u.box_size = glm::vec4(object.box_size, 0.0f);
    return u;
}

float object_line_width(const ObjectGpu& object, const FrameView& view, float max_width) {
    float radius_world = object.bounds.radius * linear_scale(object.model);
    glm::vec3 center_view = glm::vec3(view.camera.view * object.model * glm::vec4(object.bounds.center, 1.0f));
    float distance = std::max(-center_view.z, 1e-6f);
    float projected_radius = radius_world * view.camera.proj[1][1] * 0.5f * float(view.extent.height) / distance;
    float width = formulas::silhouette_line_width(object.params.silhouette_width, projected_radius,
                                                  object.params.silhouette_thinning);
    return std::min(width, max_width);
}

double run_cpu_density(ObjectGpu& object, const gpu::FrameUniforms& frame) {
    std::vector<float> densities(object.triangle_count);
    auto* draws = static_cast<gpu::TriangleDraw*>(object.draw_staging.mapped());
    // Both cores: the GPU work of this frame has not been submitted yet, so the CPU is otherwise idle.
    parallel_for_chunks(densities.size(), 16384, [&](size_t, size_t begin, size_t end) {
        std::span<float> part(densities.data() + begin, end - begin);
        compute_densities_cpu(std::span(object.triangles).subspan(begin, end - begin),
                              std::span(object.first_stipple).subspan(begin, end - begin + 1), frame, object.uniforms,
                              part);
        for (size_t t = begin; t < end; ++t) draws[t] = {densities[t], object.first_stipple[t]};
    });
    double sum = 0.0;
    for (float d : densities) sum += d;
    if (draws_by_splat(object.params.density_path)) {
        auto* list = reinterpret_cast<uint32_t*>(static_cast<std::byte*>(object.draw_staging.mapped()) +
                                                 staged_list_offset(object));
        uint32_t* polygons = list + sizeof(gpu::DrawnPolygons) / sizeof(uint32_t);
        uint32_t count = 0;
        for (uint32_t t = 0; t < object.triangle_count; ++t)
            if (densities[t] > 0.0f) polygons[count++] = t;
        const uint32_t group = gpu::kDensityWorkgroupSize;
        const gpu::DrawnPolygons header{(count + group - 1) / group, 1u, 1u, count};
        std::memcpy(list, &header, sizeof header);
        object.cpu_drawn_polygons = count;
        object.cpu_command_count = 0;
    } else {
        auto* commands = static_cast<gpu::DrawCommand*>(object.cpu_commands.mapped());
        object.cpu_command_count =
            build_draw_commands(densities, object.first_stipple, std::span(commands, object.triangle_count));
        object.cpu_commands.flush();
    }
    object.draw_staging.flush();
    return sum;
}

VkDeviceSize staged_list_offset(const ObjectGpu& object) {
    return sizeof(gpu::TriangleDraw) * VkDeviceSize(object.triangle_count);
}

}  // namespace stipple
