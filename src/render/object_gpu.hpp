#pragma once
// One object's data on the GPU (mesh for the depth pass, candidate stipples, per-polygon constants,
// per-frame densities and draws) and the CPU copies the CPU density path needs.
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "gpu/pipelines.hpp"
#include "gpu/resources.hpp"
#include "mesh/mesh.hpp"
#include "params/object_params.hpp"
#include "shared_types.h"
#include "stipple/stipple_set.hpp"

namespace stipple {

struct FrameView;

struct ObjectGpu {
    ObjectGpu() = default;
    ~ObjectGpu();
    ObjectGpu(const ObjectGpu&) = delete;
    ObjectGpu& operator=(const ObjectGpu&) = delete;

    ObjectParams params;
    glm::mat4 model{1.0f};
    Sphere bounds;                 // object space
    uint32_t index_count = 0;
    uint32_t triangle_count = 0;
    uint32_t stipple_count = 0;
    glm::vec3 box_min{0.0f}, box_size{0.0f};   // object space: the TriangleInfo centroids' quantisation box
    std::vector<gpu::TriangleInfo> triangles;  // CPU copies for the CPU density path
    std::vector<uint32_t> first_stipple;       // per polygon, and one more: where the last one's candidates end

    float candidates(size_t triangle) const { return float(first_stipple[triangle + 1] - first_stipple[triangle]); }
    gpu::ObjectUniforms uniforms{};            // this frame's
    uint32_t cpu_command_count = 0;            // CPU path: draws written this frame
    uint32_t cpu_drawn_polygons = 0;           // cpu-splat path: polygons in this frame's list
    float line_width = 1.0f;                   // Raskar-Cohen line width this frame (thinned)

    gpu::Buffer positions;        // mesh vertices (depth pass)
    gpu::Buffer normals;          // mesh vertex normals (toon silhouettes)
    gpu::Buffer indices;          // mesh triangles (depth pass)
    gpu::Buffer stipples;         // StippleVertex per candidate
    gpu::Buffer triangle_info;    // TriangleInfo per polygon (16 bytes, packed)
    gpu::Buffer triangle_draw;    // TriangleDraw per polygon: density per frame, first stipple constant
    // Buffers of one density path or two (PathBuffer), full size once an object draws with that path.
    gpu::Buffer drawn_polygons;   // splat paths: DrawnPolygons header + the polygons drawing this frame
    gpu::Buffer draw_staging;     // CPU paths: densities (and cpu-splat's list) on their way to the GPU
    gpu::Buffer gpu_commands;     // indirect path: count (16 bytes) + DrawCommand per polygon
    gpu::Buffer cpu_commands;     // cpu path: DrawCommand per surviving range
    gpu::Buffer silhouette_edges;  // SilhouetteEdge per mesh edge, once the object draws Raskar-Cohen lines
    gpu::Buffer silhouette_lines;  // SilhouetteLines header + this frame's line indices (2 per edge at most)
    uint32_t silhouette_edge_count = 0;
    bool silhouette_edges_built = false;
    gpu::Buffer debug;            // drawn count (16 bytes) + drawn bit mask, when counting
    gpu::Buffer object_uniforms;  // ObjectUniforms

    const gpu::Context* context = nullptr;
    VkDevice device = VK_NULL_HANDLE;
    VkBuffer frame_uniforms = VK_NULL_HANDLE;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkDescriptorSet set = VK_NULL_HANDLE;
};

// The buffers only some density paths use; the others hold a placeholder of this size.
inline constexpr VkDeviceSize kPathBufferPlaceholderBytes = 32;
enum class PathBuffer { DrawnPolygons, DrawStaging, GpuCommands, CpuCommands };
inline constexpr PathBuffer kPathBuffers[] = {PathBuffer::DrawnPolygons, PathBuffer::DrawStaging,
                                              PathBuffer::GpuCommands, PathBuffer::CpuCommands};
const char* path_buffer_name(PathBuffer kind);
gpu::Buffer& path_buffer(ObjectGpu& object, PathBuffer kind);
const gpu::Buffer& path_buffer(const ObjectGpu& object, PathBuffer kind);
// The bytes `path` needs in that buffer (0: the path does not use it).
VkDeviceSize path_buffer_bytes(const ObjectGpu& object, DensityPath path, PathBuffer kind);
// Grows the buffers `path` uses to their full size (rewriting the descriptor set); the GPU must not be
// using the object (StippleRenderer::prepare's contract).
void ensure_path_buffers(ObjectGpu& object, DensityPath path);
// Builds the object's edge table (§3.1 lines drawn from edges) the first time it is needed; same contract.
void ensure_silhouette_edges(ObjectGpu& object);

std::unique_ptr<ObjectGpu> create_object_gpu(const gpu::Context& context, VkDescriptorSetLayout set_layout,
                                             const gpu::Buffer& frame_uniforms, const Mesh& mesh,
                                             const StippleSet& stipples, const glm::mat4& model,
                                             const ObjectParams& params, bool count_drawn);

// The object's uniforms for this frame (view-dependent terms included).
gpu::ObjectUniforms make_object_uniforms(const ObjectGpu& object, const FrameView& view);

// The silhouette line width this frame (§3.1 thinning), at most `max_width` (the device's limit).
float object_line_width(const ObjectGpu& object, const FrameView& view, float max_width);

// The CPU density path for one object: densities into draw_staging and the surviving ranges, with
// runs of fully drawn polygons merged, into cpu_commands, and for cpu-splat the list of polygons
// that draw after the densities in draw_staging. Returns the sum of the densities.
double run_cpu_density(ObjectGpu& object, const gpu::FrameUniforms& frame);

// Where draw_staging holds the cpu-splat path's list (DrawnPolygons header, then the polygons).
VkDeviceSize staged_list_offset(const ObjectGpu& object);

}  // namespace stipple
