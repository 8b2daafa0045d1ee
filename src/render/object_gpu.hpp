#pragma once
// One object's data on the GPU, in three parts by how often they change:
//   ObjectGeometry    uploaded once: the mesh (depth pass, stipple placement) and the candidate stipples;
//   PolygonConstants  the per-polygon constants the density reads (centroid, normal, area, selection),
//                     with the bounds and quantisation box of the object's shape: computed on the CPU at
//                     creation, and rewritten each frame for an animated object (render/deform_pass.hpp);
//   ObjectFrame       this frame's uniforms, densities and the buffers of the density paths in use.
// The first two make an ObjectShape, which static copies of one model (equal mesh, stipples and seed: the
// shape key) share in a renderer: a crowd of copies holds its mesh and candidates once.
// The CPU density paths read PolygonConstants (cpu, corner_*) and ObjectGeometry::first_stipple (nothing
// else).
#include <memory>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "anim/headroom.hpp"
#include "gpu/resources.hpp"
#include "mesh/mesh.hpp"
#include "params/object_params.hpp"
#include "render/density_formulas.hpp"
#include "shared_types.h"
#include "stipple/object_data.hpp"
#include "stipple/stipple_set.hpp"

namespace stipple {

struct FrameView;
struct ObjectAnimation;

struct ObjectGeometry {
    uint32_t index_count = 0;
    uint32_t triangle_count = 0;
    uint32_t stipple_count = 0;
    float surface_area = 0.0f;  // object space, of the rest shape: the sum of its polygons' areas
    std::vector<uint32_t> first_stipple;  // per polygon, and one more: where the last one's candidates end
    float candidates(size_t triangle) const { return float(first_stipple[triangle + 1] - first_stipple[triangle]); }

    // Mesh vertices (depth pass, line passes; the stipple shaders read the corners) and vertex normals
    // (toon silhouettes): an animated object's are rewritten each frame by the deformation pass.
    gpu::Buffer positions;
    gpu::Buffer normals;
    gpu::Buffer indices;    // mesh triangles
    // The stipple shaders read both as texels (shaders/stipple_position.h): a vertex (triangle) per
    // texel where the device reads three-component texel buffers (mesh_vec3_texels), else a float (index).
    VkBufferView position_texels = VK_NULL_HANDLE;
    VkBufferView index_texels = VK_NULL_HANDLE;
    gpu::Buffer stipples;   // StippleVertex per candidate: (u, v) in its polygon, so it follows the surface
    VkBufferView stipple_texels = VK_NULL_HANDLE;  // the same as RG32UI texels (kBindingStippleTexels)
    // Every edge of the mesh once with its polygons (§3.1 and object-space lines), built the first time
    // lines are drawn.
    gpu::Buffer silhouette_edges;
    VkBufferView silhouette_edge_texels = VK_NULL_HANDLE;  // its RGBA32UI texels, as the line passes read it
    uint32_t silhouette_edge_count = 0;
    uint32_t border_edge_count = 0;  // edges with one polygon (once the edges are built)
    bool open_surface = false;       // the mesh has such edges (known from the start: depth_holds_back_faces)
    bool silhouette_edges_built = false;
};

struct PolygonConstants {
    gpu::Buffer gpu;                      // TriangleInfo per polygon (16 bytes, packed)
    VkBufferView texels = VK_NULL_HANDLE;  // the same as RGBA32UI texels (kBindingTriangleInfoTexels)
    std::vector<gpu::TriangleInfo> cpu;   // the same, for the CPU density paths (an animated object's: its rest pose)
    // The mesh's corners, for the CPU density paths' gradients across large polygons (stipple_formulas.h,
    // polygon_density_gradient): object space, three indices a polygon.
    std::vector<glm::vec3> corner_positions;
    std::vector<uint32_t> corner_indices;
    // Object space, of the rest shape (distance enhancement's reference scale, thinning): the sphere
    // generation framed in its reference view.
    Sphere bounds;
    glm::vec3 box_min{0.0f}, box_size{0.0f};  // object space: the box the centroids are quantised in (every pose)
    glm::vec3 origin{0.0f};  // Mesh::origin: where the file puts object space's (0, 0, 0) (object_to_world)
    gpu::Buffer full_areas;  // animated objects: float per polygon, rest area x headroom; else a placeholder
};

struct ObjectFrame {
    gpu::ObjectUniforms uniforms{};
    gpu::Buffer object_uniforms;   // ObjectUniforms, uploaded each frame
    gpu::Buffer triangle_draw;     // TriangleDraw per polygon: density per frame, first stipple constant
    VkBufferView triangle_draw_texels = VK_NULL_HANDLE;  // the same as RGBA32UI texels (kBindingTriangleDrawTexels)
    // Buffers of one density path or two (PathBuffer), full size once the object draws with that path.
    gpu::Buffer drawn_polygons;    // splat paths: DrawnPolygons header + the work items drawing this frame
    gpu::Buffer draw_staging;      // CPU paths: densities (and the CPU's list) on their way to the GPU
    gpu::Buffer drawn_stipples;    // indirect and cpu paths: DrawCommand + the stipples drawing this frame
    gpu::Buffer gradient_polygons;  // GPU density paths: DrawnPolygons header + the polygons large on screen
    gpu::Buffer splat_ring;        // splat paths: DrawnPolygons header + the work items astride the outline
    gpu::Buffer silhouette_lines;  // SilhouetteLines header + this frame's line indices (2 per edge at most)
    // DepthTriangles header + the triangles the depth pass draws this frame (render/depth_triangles.hpp),
    // full size once the object first lists them
    gpu::Buffer depth_triangles;
    bool depth_listed = false;     // the depth pass draws that list this frame
    // Points paths: its dots astride the outline are moved onto the surface this frame (stipple.vert,
    // kSpecOutlineShift; small on screen, kOutlineShiftBelowPx)
    bool outline_shift = false;
    gpu::Buffer facing;            // one bit per polygon: it faces away this frame (objects with lines)
    gpu::Buffer line_candidates;   // LineCandidates + this frame's edges with an object-space line
    gpu::Buffer line_pieces;       // LinePiecesHeader + this frame's visible object-space line pieces
    uint32_t line_piece_capacity = 0;
    gpu::Buffer debug;             // DebugCounters + drawn bit mask, when counting
    gpu::Buffer visible_stipples;  // VisibleStipplesHeader + VisibleStipple per candidate, when recording
    uint32_t cpu_listed = 0;          // CPU paths: entries of this frame's list (work items or stipples)
    float line_width = 1.0f;          // line width this frame (thinned, §3.1): silhouettes, contours, borders
    float crease_width = 1.0f;        // crease lines' width this frame, thinned alike
    bool splatted = false;            // drawn by the compute splat this frame
};

// What copies of one static model share (an animated object has its own: the deformation rewrites it).
struct ObjectShape {
    explicit ObjectShape(const gpu::Context& context) : context(&context) {}
    ~ObjectShape();  // its texel views (the buffers free themselves)
    ObjectShape(const ObjectShape&) = delete;
    ObjectShape& operator=(const ObjectShape&) = delete;

    const gpu::Context* context;
    uint64_t key = 0;  // object_shape_key
    ObjectGeometry geometry;
    PolygonConstants polygons;
    // The edge table's placeholder, kept once the table is built: the descriptor sets of copies that draw no
    // lines still name it.
    gpu::Buffer retired_edges;
    VkBufferView retired_edge_texels = VK_NULL_HANDLE;
};

struct ObjectGpu {
    explicit ObjectGpu(std::shared_ptr<ObjectShape> shape_);
    ~ObjectGpu();
    ObjectGpu(const ObjectGpu&) = delete;
    ObjectGpu& operator=(const ObjectGpu&) = delete;

    std::shared_ptr<ObjectShape> shape;
    ObjectParams params;
    glm::mat4 model{1.0f};  // the scene's transform (object_to_world adds the up-axis rotation)
    ObjectGeometry& geometry;    // the shape's
    PolygonConstants& polygons;  // the shape's
    ObjectFrame frame;
    std::unique_ptr<ObjectAnimation> animation;  // null for a static object
    // This object's line buffers are made and its descriptor set names the shape's edge table
    // (ensure_line_buffers; a copy may find the table built by another).
    bool line_buffers_ready = false;

    // The object's descriptor set (render/descriptor_schema.hpp says which buffer each binding reads).
    const gpu::Context* context = nullptr;
    VkBuffer frame_uniforms = VK_NULL_HANDLE;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkDescriptorSet set = VK_NULL_HANDLE;
};

// The first half of creating an object: everything computed from the mesh and its stipples (packed
// candidates, polygon constants) and put in staging buffers. It uses no queue, so the viewer prepares it
// on its worker thread and the UI thread only records the copies (one submission).
struct ObjectUpload {
    uint32_t index_count = 0, triangle_count = 0, stipple_count = 0;
    bool open_surface = false;  // the mesh has border edges (border_edge_count): its back faces can be seen
    std::vector<uint32_t> first_stipple;
    PolygonConstants polygons;  // without its GPU buffer
    // The GPU's initial data, in this order: positions, normals, indices, stipples (StippleVertex),
    // polygon constants (TriangleInfo), densities (TriangleDraw, zero, with each first stipple).
    std::vector<gpu::StagedBuffer> staged;
    anim::Motion motion;             // an animated object's (empty for a static one)
    std::vector<float> full_areas;   // animated: per polygon, rest area x headroom (animated_full_areas)
    uint64_t shape_key = 0;          // object_shape_key of the mesh, stipples and seed it was made from (static)
};
// `motion`: an animated glTF's (the mesh is its rest mesh): the quantisation box holds every pose.
ObjectUpload prepare_object_upload(const gpu::Context& context, const Mesh& mesh, const StippleSet& stipples,
                                   uint64_t seed, const anim::Motion& motion = {});
// A hash of everything prepare_object_upload reads but the motion (the mesh's vertices, normals, indices
// and origin, the stipples and their polygons' selection values, the seed): equal for copies of one model
// with equal generation parameters, whatever path they came by.
uint64_t object_shape_key(const Mesh& mesh, const StippleSet& stipples, uint64_t seed);

// An object of `stipples` candidates on `mesh` that this device cannot hold is refused in one line saying
// what it needs, what there is and what to lower: before anything is staged (prepare_object_upload), and
// before its stipples are generated (render, tone and the viewer, with planned_stipple_count), instead of a
// failed allocation half way, a lost device or minutes of generation for nothing. `planned_before`: the
// bytes of a scene's objects checked before this one and not yet allocated; `copy`: a static copy of an
// object checked before, whose shape it shares (its own buffers only). Returns the bytes it needs.
uint64_t check_object_fits(const gpu::Context& context, const Mesh& mesh, size_t stipples, uint64_t planned_before = 0,
                           bool copy = false);
// The bytes check_object_fits plans for such an object (its own buffers only, for a copy).
uint64_t planned_object_bytes(const Mesh& mesh, size_t stipples, bool copy = false);
// check_object_fits for the stipples make_stipples would make for `model` (planned_stipple_count), before
// they are made.
uint64_t check_model_fits(const gpu::Context& context, const ObjectData& model, const GenerationParams& generation,
                          uint64_t planned_before = 0);
// Vector output's list of visible stipples (20 bytes a candidate) must fit one storage buffer: refused in
// one line otherwise (`lower`: what to lower, as the command takes it). Returns its bytes.
uint64_t check_visible_list_fits(const gpu::Context& context, uint64_t candidates,
                                 const std::string& lower = "lower --dmax or --max-stipples");

// `vec3_texels`: the texel views' layout, as the renderer's pipelines read it (kSpecMeshVec3Texels).
std::unique_ptr<ObjectGpu> create_object_gpu(const gpu::Context& context, VkDescriptorSetLayout set_layout,
                                             const gpu::Buffer& frame_uniforms, const ObjectUpload& upload,
                                             const glm::mat4& model, const ObjectParams& params, bool count_drawn,
                                             bool vec3_texels);
// A copy of a static object: the same shape (made by create_object_gpu with the same texel layout), its own
// parameters, transform and per-frame buffers.
std::unique_ptr<ObjectGpu> create_object_copy(const gpu::Context& context, VkDescriptorSetLayout set_layout,
                                              const gpu::Buffer& frame_uniforms, std::shared_ptr<ObjectShape> shape,
                                              const glm::mat4& model, const ObjectParams& params, bool count_drawn);

// A buffer that a compute pass fills with an indexed indirect draw and its indices (header first).
gpu::Buffer make_index_list_buffer(const gpu::Context& context, VkDeviceSize bytes);

// Builds the object's edge table and the buffers its lines use (facing bits, the Raskar-Cohen index
// list, the object-space line pieces) the first time it draws lines; the GPU must not be using the
// object (StippleRenderer::prepare's contract).
void ensure_line_buffers(ObjectGpu& object);

// A byte count as the refusals print it: "12.3 MiB".
std::string mebibytes(uint64_t bytes);

// Stipples of kRoundPointsAbovePx (shared_types.h) and below are square points (the rasteriser's, and the
// splat's copy of them); above, round dots.
inline bool draws_round_points(float point_size) { return point_size > gpu::kRoundPointsAbovePx; }
// The radius of the disc with a stipple's ink area: a dot of point size s inks s^2, a square of side s or a
// disc of the same area, so r = s / sqrt(pi). Vector output draws stipples as discs of this radius.
inline float stipple_ink_radius(float point_size) { return point_size / 1.7724539f; }
// The size a dot is drawn at, the object's uniform point size: a square's side, or a round dot's diameter,
// the disc of the square's area (as square dots enlarged into discs are, enlarged_square_extent). Until
// 2026-12-05 a round dot's diameter was the point size itself, and the tone fell by a fifth where the point
// size crossed 2.5 (spot: 54.3% of ink at 2.5, 48.2% at 2.51).
inline float drawn_point_size(float point_size) { return formulas::enlarged_square_extent(point_size); }
// The largest point size whose dots a device drawing points of at most `device_most` pixels draws at their
// size: squares up to 2.5 at their own, round dots 1.13 times larger.
inline float largest_point_size_drawn_within(float device_most) {
    if (device_most <= gpu::kRoundPointsAbovePx) return device_most;
    return std::max(gpu::kRoundPointsAbovePx, device_most / formulas::kSquareToDiscDiameter);
}

// Whether the object draws lines from its edge table this frame (any kind; the table is built).
bool draws_edge_lines(const ObjectGpu& object);
// Whether its depth pass also holds the polygons facing away: they can be seen through an opening of an
// open mesh (where they hide what lies behind them), or carry two-sided stipples.
bool depth_holds_back_faces(const ObjectGpu& object);

// The rotation about the object's bounding-sphere centre that turns its up axis (ObjectParams::up) to +y.
glm::mat4 up_axis_rotation(UpAxis up, glm::vec3 center);
// Object to world as drawn: the scene's transform after the up-axis rotation.
glm::mat4 object_to_world(const ObjectGpu& object);

// The object's line widths this frame in pixels (§3.1 thinning): the outline's (silhouette, contour and
// border lines) and the creases'.
struct LineWidths {
    float outline = 1.0f;
    float crease = 1.0f;
};

// The object's uniforms for this frame (view-dependent terms included); `widths` from object_line_widths.
gpu::ObjectUniforms make_object_uniforms(const ObjectGpu& object, const FrameView& view, LineWidths widths);

// The line widths this frame (§3.1 thinning), at most `max_width` (the device's limit for wide lines).
LineWidths object_line_widths(const ObjectGpu& object, const FrameView& view, float max_width);

// The radius of the object's bounding sphere on screen, pixels, as at the extent the stipples are chosen for
// (FrameView::detail_scale): what §3.1 thins the lines by.
float projected_radius_px(const ObjectGpu& object, const FrameView& view);

// The points' outline shift (stipple.vert, kSpecOutlineShift) is on for objects whose projected radius is
// under this many pixels (as projected_radius_px finds it: at print detail the dots grow with the image).
// The outline band, a pixel or two wide, is a share of the footprint that grows as the object shrinks: on the
// vertex path the horse lost 0.3% of its ink to it at a radius of 512 px (framed at 1280x1024), 0.5% at 256,
// 0.8% at 128, 1.9% at 64 and 4.5% at 32 (`stipple tone --fov 4 --frames 16 --arc 360`). The shift reads the
// depth words under every drawn dot, which cost the framed bunny's stipple pass about 40% on lavapipe; below
// the threshold an object draws a sixteenth of its stipples framed at 1280x1024 or fewer.
inline constexpr float kOutlineShiftBelowPx = 128.0f;

}  // namespace stipple
