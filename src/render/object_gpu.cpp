#include "render/object_gpu.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/gtc/matrix_inverse.hpp>

#include "core/error.hpp"
#include "core/hash.hpp"
#include "mesh/orientation.hpp"
#include "gpu/context.hpp"
#include "render/density_formulas.hpp"
#include "render/deform_pass.hpp"
#include "render/descriptor_schema.hpp"
#include "render/path_buffers.hpp"
#include "render/polygon_constants.hpp"
#include "render/shared_types.hpp"
#include "render/silhouette_edges.hpp"
#include "render/stipple_renderer.hpp"
#include "stipple/barycentric.hpp"

namespace stipple {

using gpu::Buffer;
using gpu::MemoryUse;

std::string mebibytes(uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / 1048576.0);
    return text;
}

namespace {

// The edge table, read as RGBA32UI texels (line_edges.comp, line_walk.comp).
constexpr VkBufferUsageFlags kEdgeUsage = VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;

// Each candidate as (u, v) in its triangle (stipple/barycentric.hpp), 16 bits each.
std::vector<gpu::StippleVertex> pack_stipples(const Mesh& mesh, const StippleSet& stipples) {
    std::vector<gpu::StippleVertex> vertices(stipples.size());
    for (size_t i = 0; i < vertices.size(); ++i)
        vertices[i] = {pack_barycentric(mesh, stipples.triangle[i], stipples.positions[i]), stipples.triangle[i]};
    return vertices;
}

}  // namespace

uint64_t planned_object_bytes(const Mesh& mesh, size_t stipples, bool copy) {
    const uint64_t v = mesh.positions.size(), t = mesh.triangle_count(), s = stipples;
    // The buffers every path needs (mesh, stipples, polygon constants and densities) and its largest path
    // buffers, beside the drawn-stipple mask. The path buffers: the gradient pass's list of polygons, and the
    // splat's three lists the size of its work list (a slot per polygon and per kSplatShortRun candidates)
    // or the indirect path's work list and survivors (a slot per candidate).
    const uint64_t work_list = 4 * t + 4 * s / gpu::kSplatShortRun;
    const uint64_t path_buffers = 4 * t + std::max(3 * work_list, work_list + 4 * s);
    // The shape's part (positions and normals, indices, candidates, polygon constants) once for its copies.
    const uint64_t shape = copy ? 0 : 24 * v + 12 * t + 8 * s + 16 * t;
    return shape + 16 * t + s / 8 + path_buffers;
}

uint64_t check_object_fits(const gpu::Context& context, const Mesh& mesh, size_t stipples, uint64_t planned_before,
                           bool copy) {
    const uint64_t v = mesh.positions.size(), t = mesh.triangle_count(), s = stipples;
    const uint64_t largest = std::max({8 * s, 16 * t, 12 * t, 12 * v});  // stipples, polygons, indices, positions
    const uint64_t needed = planned_object_bytes(mesh, stipples, copy);
    const std::string what = mesh.source.empty() ? std::string("the object") : mesh.source;
    const std::string lower = ": lower --dmax or --max-stipples, or use a simplified model";
    if (largest > context.max_storage_buffer_bytes()) {
        // Say what to lower: the stipples, or the mesh (its polygons' buffer, 16 bytes each, or its vertices'),
        // which no stipple option shrinks (an 8.7M-triangle model was told to lower --dmax).
        const uint64_t limit = context.max_storage_buffer_bytes();
        const bool mesh_bound = std::max(16 * t, 12 * v) > limit;  // polygons, or positions (indices: 12 * t < 16 * t)
        fail(what + ": its " + std::to_string(s) + " stipples on " + std::to_string(t) + " polygons need a " +
             mebibytes(largest) + " buffer, and this device's largest is " + mebibytes(limit) +
             (mesh_bound ? ": the mesh is too large for this device (at most " + std::to_string(limit / 16) +
                               " polygons and " + std::to_string(limit / 12) + " vertices): use a simplified model"
                         : lower));
    }
    // The stipple shaders read the mesh, the polygons and the candidates as texels (a vertex, triangle or
    // stipple a texel, or a float or index a texel where three-component texel buffers are not read).
    const uint64_t texels = std::max((context.features.vec3_texels ? 1 : 3) * std::max(v, t), s);
    if (texels > context.properties.limits.maxTexelBufferElements)
        fail(what + ": its " + std::to_string(v) + " vertices, " + std::to_string(t) + " polygons and " +
             std::to_string(s) + " stipples exceed this device's texel buffer limit (" +
             std::to_string(context.properties.limits.maxTexelBufferElements) +
             " texels): lower --dmax or --max-stipples, or use a simplified model");
    const uint64_t free_now = context.device_memory_available();
    const uint64_t available = free_now > planned_before ? free_now - planned_before : 0;
    if (needed > available) {
        // A scene's objects count together: say what the ones before hold, or will.
        const uint64_t held = context.bytes_allocated() + planned_before;
        const std::string in_use =
            held >= (uint64_t(1) << 20) ? " (" + mebibytes(held) + (planned_before ? " taken" : " in use") + " by this drawing)" : "";
        fail(what + ": its " + std::to_string(s) + " stipples on " + std::to_string(t) + " polygons need about " +
             mebibytes(needed) + " of GPU memory, and the device has " + mebibytes(available) + " free" + in_use + lower);
    }
    return needed;
}

uint64_t check_model_fits(const gpu::Context& context, const ObjectData& model, const GenerationParams& generation,
                          uint64_t planned_before) {
    return check_object_fits(context, *model.mesh, planned_stipple_count(model, generation), planned_before);
}

uint64_t check_visible_list_fits(const gpu::Context& context, uint64_t candidates, const std::string& lower) {
    const uint64_t bytes = sizeof(gpu::VisibleStipplesHeader) + sizeof(gpu::VisibleStipple) * candidates;
    // 20 bytes a candidate where drawing needs 8 (check_object_fits): vector output of 8.4M-16.8M candidates on
    // a device of 128 MiB storage buffers wrote past the descriptor's range.
    if (bytes > context.max_storage_buffer_bytes())
        fail("vector output of " + std::to_string(candidates) + " candidate stipples needs a " + mebibytes(bytes) +
             " list, and this device's largest buffer is " + mebibytes(context.max_storage_buffer_bytes()) + ": " +
             lower + ", or write a PNG");
    return bytes;
}

namespace {

enum StagedIndex { kPositions, kNormals, kIndices, kStipples, kPolygons, kDensities, kStagedCount };

// A new shape from an object's upload and its staged data uploaded (`buffers`, in StagedIndex order; the
// densities are the object's: upload_frame).
std::shared_ptr<ObjectShape> make_shape(const gpu::Context& context, const ObjectUpload& upload, std::vector<Buffer>& buffers,
                                        bool vec3_texels) {
    auto shape = std::make_shared<ObjectShape>(context);
    shape->key = upload.shape_key;
    ObjectGeometry& geometry = shape->geometry;
    geometry.index_count = upload.index_count;
    geometry.triangle_count = upload.triangle_count;
    geometry.open_surface = upload.open_surface;
    geometry.stipple_count = upload.stipple_count;
    geometry.first_stipple = upload.first_stipple;
    geometry.positions = std::move(buffers[kPositions]);
    geometry.normals = std::move(buffers[kNormals]);
    geometry.indices = std::move(buffers[kIndices]);
    geometry.stipples = std::move(buffers[kStipples]);
    const auto storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    // A placeholder until the object first draws lines (the descriptor set needs a buffer in every binding).
    geometry.silhouette_edges = Buffer(context, kPathBufferPlaceholderBytes, kEdgeUsage, MemoryUse::DeviceLocal);
    geometry.silhouette_edge_texels =
        gpu::create_texel_view(context, geometry.silhouette_edges.handle(), VK_FORMAT_R32G32B32A32_UINT);

    PolygonConstants& polygons = shape->polygons;
    polygons.cpu = upload.polygons.cpu;
    polygons.corner_positions = upload.polygons.corner_positions;
    polygons.corner_indices = upload.polygons.corner_indices;
    polygons.bounds = upload.polygons.bounds;
    polygons.origin = upload.polygons.origin;
    polygons.box_min = upload.polygons.box_min;
    polygons.box_size = upload.polygons.box_size;
    polygons.gpu = std::move(buffers[kPolygons]);
    // Filled for animated objects (create_object_animation); the descriptor set needs a buffer.
    polygons.full_areas = Buffer(context, kPathBufferPlaceholderBytes, storage, MemoryUse::DeviceLocal);

    double surface_area = 0.0;
    for (const gpu::TriangleInfo& info : polygons.cpu) surface_area += double(info.area);
    geometry.surface_area = float(surface_area);
    // Within the device's texel buffer limit (check_object_fits).
    geometry.position_texels = gpu::create_texel_view(context, geometry.positions.handle(),
                                                      vec3_texels ? VK_FORMAT_R32G32B32_SFLOAT : VK_FORMAT_R32_SFLOAT);
    geometry.index_texels = gpu::create_texel_view(context, geometry.indices.handle(),
                                                   vec3_texels ? VK_FORMAT_R32G32B32_UINT : VK_FORMAT_R32_UINT);
    static_assert(sizeof(gpu::TriangleInfo) == 16, "TriangleInfo is read as one RGBA32UI texel");
    polygons.texels = gpu::create_texel_view(context, polygons.gpu.handle(), VK_FORMAT_R32G32B32A32_UINT);
    static_assert(sizeof(gpu::StippleVertex) == 8, "StippleVertex is read as one RG32UI texel");
    geometry.stipple_texels = gpu::create_texel_view(context, geometry.stipples.handle(), VK_FORMAT_R32G32_UINT);
    return shape;
}

// The object's own buffers: its densities (`densities`: device-local, initialised with each polygon's first
// stipple) and the placeholders of the buffers made when a frame first needs them.
void upload_frame(const gpu::Context& context, Buffer densities, bool count_drawn, ObjectGpu& object) {
    const auto storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    ObjectFrame& frame = object.frame;
    frame.triangle_draw = std::move(densities);
    static_assert(sizeof(gpu::TriangleDraw) == 16, "TriangleDraw is read as one RGBA32UI texel");
    frame.triangle_draw_texels = gpu::create_texel_view(context, frame.triangle_draw.handle(), VK_FORMAT_R32G32B32A32_UINT);
    for (PathBuffer kind : kPathBuffers)
        path_buffer(frame, kind) = make_path_buffer(context, kind, kPathBufferPlaceholderBytes);
    frame.silhouette_lines = make_index_list_buffer(context, kPathBufferPlaceholderBytes);
    frame.depth_triangles = make_index_list_buffer(context, kPathBufferPlaceholderBytes);
    frame.visible_stipples = Buffer(context, kPathBufferPlaceholderBytes, storage | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                    MemoryUse::DeviceLocal);
    frame.facing = Buffer(context, kPathBufferPlaceholderBytes, storage, MemoryUse::DeviceLocal);
    frame.line_candidates = make_index_list_buffer(context, kPathBufferPlaceholderBytes);
    frame.line_pieces = make_index_list_buffer(context, kPathBufferPlaceholderBytes);
    const VkDeviceSize mask_bytes = count_drawn ? sizeof(uint32_t) * ((object.geometry.stipple_count + 31) / 32) : 0;
    frame.debug = Buffer(context, sizeof(gpu::DebugCounters) + mask_bytes, storage | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                         MemoryUse::Readback);
    frame.object_uniforms =
        Buffer(context, sizeof(gpu::ObjectUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryUse::Upload);
}

// Each polygon's density zero, with its first stipple (TriangleDraw), as the GPU starts from.
std::vector<gpu::TriangleDraw> initial_draws(std::span<const uint32_t> first_stipple, size_t triangles) {
    std::vector<gpu::TriangleDraw> draws(triangles);
    for (size_t t = 0; t < draws.size(); ++t) draws[t] = {0.0f, first_stipple[t], 0.0f, 0.0f};
    return draws;
}

void check_point_size(const gpu::Context& context, const ObjectParams& params) {
    if (drawn_point_size(params.point_size) > context.features.max_point_size)
        fail("--point-size " + std::to_string(params.point_size) + " (drawn " + std::to_string(drawn_point_size(params.point_size)) +
             " px across) exceeds this device's maximum of " + std::to_string(context.features.max_point_size));
}

// How the model matrix scales lengths from object to world: the mean (the cube root of the volume's
// scale), the most (its longest column, as the scene's framing takes it) and whether it is a similarity
// (every direction scaled alike), where the two are the same.
struct ModelScale {
    float mean = 1.0f, most = 1.0f;
    bool uniform = true;
};

ModelScale model_scale(const glm::mat4& model) {
    const glm::mat3 m(model);
    ModelScale s;
    s.mean = std::cbrt(std::abs(glm::determinant(m)));
    const float lengths[3] = {glm::length(m[0]), glm::length(m[1]), glm::length(m[2])};
    s.most = std::max({lengths[0], lengths[1], lengths[2]});
    const float tolerance = 1e-5f * s.most;
    for (int i = 0; i < 3; ++i) {
        if (std::abs(lengths[i] - s.most) > tolerance) s.uniform = false;
        if (std::abs(glm::dot(m[i], m[(i + 1) % 3])) > tolerance * s.most) s.uniform = false;
    }
    // A similarity keeps the mean it always used, so that its drawing does not move by a rounding.
    if (s.uniform) s.most = s.mean;
    return s;
}

}  // namespace

Buffer make_index_list_buffer(const gpu::Context& context, VkDeviceSize bytes) {
    return Buffer(context, bytes,
                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDEX_BUFFER_BIT |
                      VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                  MemoryUse::DeviceLocal);
}

ObjectGpu::ObjectGpu(std::shared_ptr<ObjectShape> shape_)
    : shape(std::move(shape_)), geometry(shape->geometry), polygons(shape->polygons) {}

ObjectGpu::~ObjectGpu() {
    if (pool) vkDestroyDescriptorPool(context->device, pool, nullptr);
    if (frame.triangle_draw_texels) vkDestroyBufferView(context->device, frame.triangle_draw_texels, nullptr);
}

ObjectShape::~ObjectShape() {
    for (VkBufferView view : {geometry.position_texels, geometry.index_texels, polygons.texels, geometry.silhouette_edge_texels,
                              geometry.stipple_texels, retired_edge_texels})
        if (view) vkDestroyBufferView(context->device, view, nullptr);
}

ObjectUpload prepare_object_upload(const gpu::Context& context, const Mesh& mesh, const StippleSet& stipples,
                                   uint64_t seed, const anim::Motion& motion) {
    STIPPLE_CHECK(stipples.first.size() == mesh.triangle_count() + 1, "stipple set does not match the mesh");
    check_object_fits(context, mesh, stipples.size());
    ObjectUpload upload;
    upload.index_count = uint32_t(mesh.indices.size());
    upload.triangle_count = uint32_t(mesh.triangle_count());
    upload.open_surface = border_edge_count(mesh) > 0;
    upload.stipple_count = uint32_t(stipples.size());
    upload.first_stipple.assign(stipples.first.begin(), stipples.first.end());
    upload.polygons = compute_polygon_constants(mesh, stipples, seed, motion ? &motion.headroom->bounds : nullptr);
    if (motion) {
        upload.motion = motion;
        upload.full_areas = animated_full_areas(mesh, motion);
    }
    upload.shape_key = object_shape_key(mesh, stipples, seed);
    const std::vector<gpu::StippleVertex> vertices = pack_stipples(mesh, stipples);
    const std::vector<gpu::TriangleDraw> draws = initial_draws(upload.first_stipple, upload.triangle_count);
    const auto storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vertex = VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
    upload.staged.resize(kStagedCount);
    // The stipple shaders read the corners of the polygons whose stipples they place.
    // Texels too: an animated object's polygon pass reads them so (render/deform_pass.hpp).
    const auto texels = VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;
    upload.staged[kPositions] = gpu::stage_buffer(context, std::span(mesh.positions), vertex | storage | texels);
    // Storage too: an animated object's deformation pass writes them.
    upload.staged[kNormals] = gpu::stage_buffer(context, std::span(mesh.normals), vertex | storage);
    upload.staged[kIndices] = gpu::stage_buffer(context, std::span(mesh.indices), VK_BUFFER_USAGE_INDEX_BUFFER_BIT | storage | texels);
    upload.staged[kStipples] = gpu::stage_buffer(context, std::span(vertices), vertex | storage | texels);
    upload.staged[kPolygons] =
        gpu::stage_buffer(context, std::span<const gpu::TriangleInfo>(upload.polygons.cpu), storage | texels);
    upload.staged[kDensities] = gpu::stage_buffer(context, std::span<const gpu::TriangleDraw>(draws), storage | texels);
    return upload;
}

uint64_t object_shape_key(const Mesh& mesh, const StippleSet& stipples, uint64_t seed) {
    uint64_t key = mix64(seed);
    key = hash_values(std::span(mesh.positions), key);
    key = hash_values(std::span(mesh.normals), key);
    key = hash_values(std::span(mesh.indices), key);
    key = hash_values(std::span(&mesh.origin, 1), key);
    key = hash_values(std::span(stipples.positions), key);
    key = hash_values(std::span(stipples.triangle), key);
    key = hash_values(std::span(stipples.first), key);
    return hash_values(std::span(stipples.selection), key);
}

std::unique_ptr<ObjectGpu> create_object_gpu(const gpu::Context& context, VkDescriptorSetLayout set_layout,
                                             const Buffer& frame_uniforms, const ObjectUpload& upload,
                                             const glm::mat4& model, const ObjectParams& params, bool count_drawn,
                                             bool vec3_texels) {
    validate_params(params);
    check_point_size(context, params);
    STIPPLE_CHECK(upload.staged.size() == kStagedCount, "object upload is not staged");
    std::vector<Buffer> buffers = gpu::upload_staged(context, upload.staged);  // one submission for all
    auto object = std::make_unique<ObjectGpu>(make_shape(context, upload, buffers, vec3_texels));
    object->context = &context;
    object->frame_uniforms = frame_uniforms.handle();
    object->params = params;
    object->model = model;
    upload_frame(context, std::move(buffers[kDensities]), count_drawn, *object);
    if (upload.motion) object->animation = create_object_animation(context, *object, upload.motion, upload.full_areas);
    check_animated_path(*object);
    create_object_descriptors(context, set_layout, *object);
    ensure_path_buffers(*object, params.density_path);
    return object;
}

std::unique_ptr<ObjectGpu> create_object_copy(const gpu::Context& context, VkDescriptorSetLayout set_layout,
                                              const Buffer& frame_uniforms, std::shared_ptr<ObjectShape> shape,
                                              const glm::mat4& model, const ObjectParams& params, bool count_drawn) {
    validate_params(params);
    check_point_size(context, params);
    auto object = std::make_unique<ObjectGpu>(std::move(shape));
    object->context = &context;
    object->frame_uniforms = frame_uniforms.handle();
    object->params = params;
    object->model = model;
    const std::vector<gpu::TriangleDraw> draws = initial_draws(object->geometry.first_stipple, object->geometry.triangle_count);
    upload_frame(context,
                 gpu::create_device_buffer(context, std::span<const gpu::TriangleDraw>(draws),
                                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT),
                 count_drawn, *object);
    check_animated_path(*object);
    create_object_descriptors(context, set_layout, *object);
    ensure_path_buffers(*object, params.density_path);
    return object;
}

namespace {

// The shape's edge table, built by the first of its objects to draw lines. Read back from the GPU: the shape
// keeps no CPU copy of its mesh, and most objects never need this. Refused (a one-line error) before anything
// is marked built, so that no object draws lines from a table that was not made.
void ensure_shape_edges(ObjectShape& shape) {
    ObjectGeometry& geometry = shape.geometry;
    if (geometry.silhouette_edges_built) return;
    const gpu::Context& context = *shape.context;
    std::vector<std::byte> bytes = gpu::read_buffer(context, geometry.indices);
    std::vector<uint32_t> indices(geometry.index_count);
    std::memcpy(indices.data(), bytes.data(), sizeof(uint32_t) * indices.size());
    bytes = gpu::read_buffer(context, geometry.positions);
    std::vector<glm::vec3> positions(bytes.size() / sizeof(glm::vec3));
    std::memcpy(positions.data(), bytes.data(), sizeof(glm::vec3) * positions.size());
    const std::vector<uint32_t> welded = weld_by_position(positions);
    for (uint32_t& index : indices) index = welded[index];
    std::vector<gpu::SilhouetteEdge> edges = build_silhouette_edges(indices);
    if (edges.size() > gpu::kLineEdgeMask)
        fail(std::to_string(edges.size()) + " edges: object-space lines take at most " +
             std::to_string(gpu::kLineEdgeMask) + " per object");
    if (edges.size() > context.properties.limits.maxTexelBufferElements)
        fail(std::to_string(edges.size()) + " edges: the device's texel buffers hold at most " +
             std::to_string(context.properties.limits.maxTexelBufferElements));
    // The edge table is the largest of the lines' buffers a shader reads whole (16 bytes an edge; the index
    // list 8, a piece each below is capped).
    if (sizeof(gpu::SilhouetteEdge) * uint64_t(edges.size()) > context.max_storage_buffer_bytes())
        fail(std::to_string(edges.size()) + " edges: their lines need a " +
             mebibytes(sizeof(gpu::SilhouetteEdge) * uint64_t(edges.size())) + " buffer, and this device's largest is " +
             mebibytes(context.max_storage_buffer_bytes()) + ": draw it without lines, or use a simplified model");
    geometry.border_edge_count = uint32_t(
        std::count_if(edges.begin(), edges.end(), [](const auto& e) { return e.second_polygon == gpu::kNoPolygon; }));
    if (!edges.empty()) {
        Buffer table = gpu::create_device_buffer(context, std::span<const gpu::SilhouetteEdge>(edges), kEdgeUsage);
        const VkBufferView table_texels = gpu::create_texel_view(context, table.handle(), VK_FORMAT_R32G32B32A32_UINT);
        // The placeholder and its view stay while the shape lives: the descriptor sets of its other objects name
        // them until those draw lines too (ensure_line_buffers rewrites each object's set).
        shape.retired_edges = std::move(geometry.silhouette_edges);
        shape.retired_edge_texels = geometry.silhouette_edge_texels;
        geometry.silhouette_edges = std::move(table);
        geometry.silhouette_edge_texels = table_texels;
    }
    geometry.silhouette_edge_count = uint32_t(edges.size());
    geometry.silhouette_edges_built = true;
}

}  // namespace

void ensure_line_buffers(ObjectGpu& object) {
    if (object.line_buffers_ready) return;
    ensure_shape_edges(*object.shape);
    const gpu::Context& context = *object.context;
    const uint64_t edges = object.geometry.silhouette_edge_count;
    if (edges == 0) {
        object.line_buffers_ready = true;
        return;
    }
    object.frame.silhouette_lines = make_index_list_buffer(context, gpu::kIndexListHeaderBytes + 2 * sizeof(uint32_t) * edges);
    object.frame.facing = Buffer(context, sizeof(uint32_t) * ((object.geometry.triangle_count + 31) / 32),
                                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                 MemoryUse::DeviceLocal);
    object.frame.line_candidates = make_index_list_buffer(context, sizeof(gpu::LineCandidates) + sizeof(uint32_t) * edges);
    // Room for one visible piece per edge: most edges draw no object-space line, and few of those
    // that do are split by an occluder. Pieces beyond it are dropped (and reported by the read-back).
    // At most what one storage buffer holds (a model of millions of edges: 153 MiB of pieces for 6.4M).
    const uint64_t most_pieces = (context.max_storage_buffer_bytes() - sizeof(gpu::LinePiecesHeader)) / sizeof(gpu::LinePiece);
    object.frame.line_piece_capacity = uint32_t(std::min<uint64_t>(edges + 256, most_pieces));
    object.frame.line_pieces =
        make_index_list_buffer(context, sizeof(gpu::LinePiecesHeader) + sizeof(gpu::LinePiece) * object.frame.line_piece_capacity);
    write_object_descriptors(object);
    object.line_buffers_ready = true;  // only now: a failed allocation above leaves it to be tried again
}

bool draws_edge_lines(const ObjectGpu& object) {
    return draws_edge_lines(object.params) && object.line_buffers_ready && object.geometry.silhouette_edge_count > 0;
}

bool depth_holds_back_faces(const ObjectGpu& object) {
    // A closed surface hides its back faces behind its front ones, so the depth pass culls them (half the
    // rasteriser's work). Through the holes of an open one they are what is seen, and what they hide must
    // stay hidden (docs/paper-reading.md, "Open surfaces").
    return object.params.two_sided || object.geometry.open_surface;
}

glm::mat4 up_axis_rotation(UpAxis up, glm::vec3 center) {
    // Columns: where the model's x, y and z axes go. Each is a proper rotation taking `up` to +y.
    glm::mat3 r(1.0f);
    switch (up) {
        case UpAxis::Y: return glm::mat4(1.0f);
        case UpAxis::Z: r = glm::mat3(glm::vec3(1, 0, 0), glm::vec3(0, 0, -1), glm::vec3(0, 1, 0)); break;     // -90 about x
        case UpAxis::NegZ: r = glm::mat3(glm::vec3(1, 0, 0), glm::vec3(0, 0, 1), glm::vec3(0, -1, 0)); break;  // +90 about x
        case UpAxis::X: r = glm::mat3(glm::vec3(0, 1, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 0, 1)); break;     // +90 about z
        case UpAxis::NegX: r = glm::mat3(glm::vec3(0, -1, 0), glm::vec3(1, 0, 0), glm::vec3(0, 0, 1)); break;  // -90 about z
        case UpAxis::NegY: r = glm::mat3(glm::vec3(-1, 0, 0), glm::vec3(0, -1, 0), glm::vec3(0, 0, 1)); break; // 180 about z
    }
    // About the bounding-sphere centre: the object stays where its scene (and the camera's framing) put it.
    glm::mat4 m(r);
    m[3] = glm::vec4(center - r * center, 1.0f);
    return m;
}

glm::mat4 object_to_world(const ObjectGpu& object) {
    // A model stored about its own centre (Mesh::origin) is put back where its file has it, before the scene's
    // transform: the transform and the framing (ObjectData::bounds) read the file's coordinates.
    glm::mat4 placed = object.model;
    if (object.polygons.origin != glm::vec3(0.0f)) placed = glm::translate(placed, object.polygons.origin);
    return placed * up_axis_rotation(object.params.up, object.polygons.bounds.center);
}

namespace {

// The radius in world of the object's bounding sphere about its centre: stretched by the model's largest
// stretch, or for a model that scales its axes unequally the farthest corner of its box where that is nearer
// (transformed_radius): a terrain's heights exaggerated 10 times stretched its sphere 10 times, and the thinned
// lines with it. An animated object's box holds every pose (its headroom's).
float world_radius(const ObjectGpu& object, const ModelScale& scale) {
    const Sphere& bounds = object.polygons.bounds;
    if (scale.uniform) return bounds.radius * scale.most;
    const Bounds box{object.polygons.box_min, object.polygons.box_min + object.polygons.box_size};
    return transformed_radius(bounds, box, object_to_world(object));
}

}  // namespace

gpu::ObjectUniforms make_object_uniforms(const ObjectGpu& object, const FrameView& view, LineWidths widths) {
    const ObjectParams& p = object.params;
    const Sphere& bounds = object.polygons.bounds;
    gpu::ObjectUniforms u{};
    const glm::mat4 model = object_to_world(object);
    u.model_view = view.camera.view * model;
    u.model_view_proj = (view.camera.proj * view.camera.view) * model;  // as FrameUniforms::view_proj times it
    u.normal_view = glm::inverseTranspose(u.model_view);
    const ModelScale scale = model_scale(object.model);
    // The reference view (and the stipples' areas, extrinsic.w) at the mean scale; an unequal scale of
    // the axes is corrected per polygon (polygon_view). The depth range A is the sphere's extent in world.
    const float radius_mean = std::max(bounds.radius * scale.mean, 1e-20f);
    const float radius_world = std::max(world_radius(object, scale), 1e-20f);
    // At print detail a stipple is drawn as the disc of its screen ink, enlarged (FrameView::detail_scale).
    const bool print = view.detail_scale != 1.0f;
    const float point_size = print ? 2.0f * stipple_ink_radius(p.point_size) * view.detail_scale : drawn_point_size(p.point_size);
    u.shading = glm::vec4(p.shading_exponent, point_size, p.toon_sharpness, 0.0f);
    // Reference view of generation: the bounding-sphere radius spans kReferenceHeight / 2 pixels.
    u.extrinsic = glm::vec4(p.pr, p.min_area, 0.5f * kReferenceHeight / radius_mean, scale.mean * scale.mean);
    glm::vec3 center_view = glm::vec3(u.model_view * glm::vec4(bounds.center, 1.0f));
    u.intrinsic = glm::vec4(p.de, radius_world, -center_view.z, scale.uniform ? 0.0f : 1.0f);
    u.ink_color = glm::vec4(p.ink.value_or(view.ink_color), 1.0f);
    uint32_t flags = gpu::kFlagBackfaceCull;
    if (p.shading) flags |= gpu::kFlagShading;
    if (p.extrinsic) flags |= gpu::kFlagExtrinsic;
    if (p.intrinsic) flags |= gpu::kFlagIntrinsic;
    if (print || draws_round_points(p.point_size)) flags |= gpu::kFlagRoundPoints;
    if (p.toon) flags |= gpu::kFlagToonFade;
    if (p.two_sided) flags |= gpu::kFlagTwoSided;
    if (!p.faint_dots) flags |= gpu::kFlagSolidDots;
    if (object.animation) flags |= gpu::kFlagStretch;
    if (!depth_holds_back_faces(object)) flags |= gpu::kFlagDepthOneSided;
    if (view.cull_outside_view) flags |= gpu::kFlagCullOutsideView;
    const ObjectGeometry& g = object.geometry;
    if (draws_edge_lines(object)) {
        flags |= gpu::kFlagFacingBits;
        if (p.silhouette_lines) flags |= gpu::kFlagSilhouetteLines;
        if (p.contours) flags |= gpu::kFlagContours;
        if (p.borders) flags |= gpu::kFlagBorders;
        if (p.creases) flags |= gpu::kFlagCreases;
    }
    u.flags = glm::uvec4(flags, g.triangle_count, object.line_buffers_ready ? g.silhouette_edge_count : 0u, g.stipple_count);
    u.box_min = glm::vec4(object.polygons.box_min, 0.0f);
    // w: how far a centroid quantised in the box (16 bits an axis, TriangleInfo) may lie from the true one, in
    // view depth (twice the bound), so that the density pass and the stipples agree on which centroids lie
    // nearer than the near plane (PolygonDensity::unplaced, density_reference_point).
    u.box_size = glm::vec4(object.polygons.box_size, glm::length(object.polygons.box_size) * scale.most / 65535.0f);
    u.lines = glm::vec4(widths.outline, std::cos(glm::radians(p.crease_angle)), widths.crease, 0.0f);
    return u;
}

float projected_radius_px(const ObjectGpu& object, const FrameView& view) {
    const Sphere& bounds = object.polygons.bounds;
    float radius_world = world_radius(object, model_scale(object.model));
    glm::vec3 center_view = glm::vec3(view.camera.view * object_to_world(object) * glm::vec4(bounds.center, 1.0f));
    // Not nearer than a ten-thousandth of the radius (the eye at the centre): a fixed 1e-6 was farther than the
    // whole camera distance of a model 1e-8 units across, and thinned its lines to half.
    float distance = scaling_depth(view.camera, std::max(-center_view.z, std::max(radius_world * 1e-4f, 1e-30f)));
    // Thinned as at the extent the stipples are chosen for, then enlarged with them (detail_scale).
    return radius_world * view.camera.proj[1][1] * 0.5f * float(view.extent.height) / (distance * view.detail_scale);
}

LineWidths object_line_widths(const ObjectGpu& object, const FrameView& view, float max_width) {
    const float projected_radius = projected_radius_px(object, view);
    const auto width = [&](float user_width) {
        const float thinned = formulas::silhouette_line_width(user_width, projected_radius, object.params.silhouette_thinning);
        return std::min(thinned * view.detail_scale, max_width);
    };
    // Creases no thinner than a pixel, the floor thinning keeps (a weight of 0.1 drew them in broken dots).
    const float crease = std::max(1.0f, object.params.silhouette_width * object.params.crease_weight);
    return {width(object.params.silhouette_width), width(crease)};
}

}  // namespace stipple
