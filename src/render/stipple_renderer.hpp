#pragma once
// Owns every object's GPU data and the stipple pipelines, and records a frame:
//   density (compute pass, or CPU upload; facing bits) -> depth pass (polygon offset) -> stipples
//   (points, or the compute splat) -> line edges (compute: Raskar-Cohen list, visible object-space
//   pieces) -> lines (wide lines, capsules).
// The same recording serves offscreen renders and the window's swapchain images. The depth pass lives
// in depth_pass.cpp, the compute splat in splat_pass.cpp, the line passes in line_passes.cpp.
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "gpu/gpu_timer.hpp"
#include "gpu/pipelines.hpp"
#include "gpu/resources.hpp"
#include "mesh/mesh.hpp"
#include "render/camera.hpp"
#include "render/deform_pass.hpp"
#include "render/depth_raster.hpp"
#include "render/depth_triangles.hpp"
#include "render/descriptor_schema.hpp"
#include "render/object_gpu.hpp"
#include "params/object_params.hpp"
#include "shared_types.h"
#include "stipple/stipple_set.hpp"

namespace stipple {

namespace gpu {
class Context;
}

struct FrameView {
    CameraMatrices camera;
    VkExtent2D extent{1280, 1024};
    glm::vec3 light_view{-0.45f, 0.55f, 0.70f};  // toward the light, view space (x right, y up, z to viewer)
    glm::vec3 ink_color{0.0f};  // of the objects without an ink of their own (ObjectParams::ink)
    glm::vec3 paper_color{1.0f};
    // Print: the image is drawn at this many times the resolution its stipples are chosen for. Densities
    // (§2.1-2.3) are computed as for an extent this much smaller, and stipples and lines are drawn this
    // much larger (stipples as discs of their ink area), so a poster is the screen image enlarged: the
    // same stipples, the same tone. 1 for everything else.
    float detail_scale = 1.0f;
    // Polygons wholly outside the view draw nothing (kFlagCullOutsideView; the image is the same). Off where
    // every drawn stipple of the densities must be counted wherever it lies: a print's tiles with --stats,
    // each tile counting the whole drawing's, and the tone survey's tally against its owed stipples.
    bool cull_outside_view = true;
};

// Images the frame is drawn into. Layouts on entry are ignored (contents are cleared); on exit the
// colour image is in COLOR_ATTACHMENT_OPTIMAL and the depth image in DEPTH_STENCIL_ATTACHMENT_OPTIMAL
// (or DEPTH_ATTACHMENT_OPTIMAL for a depth format without stencil). The depth image needs
// TRANSFER_SRC usage (the splat and the object-space lines read a copy of it) and TRANSFER_DST (the depth
// pass as compute copies its words into it). After a frame whose depth pass ran as compute
// (StippleRenderer::depth_words), the image holds the depth only if a pass tested against it.
struct RenderTargets {
    VkImage color = VK_NULL_HANDLE;
    VkImageView color_view = VK_NULL_HANDLE;
    VkImage depth = VK_NULL_HANDLE;
    VkImageView depth_view = VK_NULL_HANDLE;
    VkExtent2D extent{};
    // For the compute splat: colour and depth images with TRANSFER_SRC usage, the colour also with
    // TRANSFER_DST (8-bit RGBA or BGRA). Without them, splat objects are drawn by the vertex path.
    bool splat_transfers = false;
    // The colour image's pixels as a buffer of words, row after row (a linear image sharing its memory,
    // gpu::Image::linear_with_words), or null: the splat then draws in them instead of in a buffer of its
    // own that is copied into the image after.
    VkBuffer color_words = VK_NULL_HANDLE;
    // Names color_words for the lifetime of its buffer (gpu::Image::words_serial; 0: unnamed). A buffer made
    // after another was destroyed may get its handle, so the handle alone cannot tell the splat that
    // the words it bound are still these; with a serial it rebinds only for new ones, and frames can
    // be recorded back to back into one command buffer (OffscreenTarget::draw_queued).
    uint64_t color_words_serial = 0;
};

struct RendererOptions {
    bool count_drawn = false;  // record every drawn stipple (drawn_count, drawn_mask): tests, --stats
    // List the stipples the splat draws, with their window positions (read_visible_stipples): vector
    // output. Objects on the splat paths only (the export draws every object with one of them).
    bool record_visible = false;
    // Read every object's mesh one float (index) per texel even where the device reads three-component
    // texel buffers (the variant for devices that do not): tests.
    bool scalar_texels = false;
    // Whether an object's depth pass draws only the triangles that may cover a pixel centre (listed by a
    // compute pass, render/depth_triangles.hpp): the same image, less work where triangles are small.
    DepthCull depth_cull = DepthCull::Auto;
    // How the depth pass is rasterised (render/depth_raster.hpp): auto is by compute on a CPU device.
    DepthRaster depth_raster = DepthRaster::Auto;
};

struct FrameStats {
    uint64_t triangles = 0;
    uint64_t candidate_stipples = 0;
    int64_t drawn_stipples = -1;  // counted on the GPU; -1 unless RendererOptions::count_drawn
    double cpu_density_ms = 0.0;  // CPU time of the CPU density path this frame
    std::vector<std::pair<std::string, double>> gpu_ms;  // per pass, after collect()
};

class StippleRenderer {
public:
    StippleRenderer(const gpu::Context& context, VkFormat color_format, VkFormat depth_format,
                    RendererOptions options = {});
    ~StippleRenderer();
    StippleRenderer(const StippleRenderer&) = delete;
    StippleRenderer& operator=(const StippleRenderer&) = delete;

    // `motion`: an animated model (its rest mesh is `mesh`, its stipples generated with its headroom);
    // the object then deforms every frame at the time set_animation gives (animation 0 at 0 s until then).
    size_t add_object(const Mesh& mesh, const StippleSet& stipples, const glm::mat4& model,
                      const ObjectParams& params, const anim::Motion& motion = {});
    // The same from the CPU half prepared beforehand (prepare_object_upload, e.g. on a worker thread).
    size_t add_object(const ObjectUpload& upload, const glm::mat4& model, const ObjectParams& params);
    // New mesh or stipples for an object, in place (waits for the GPU); its transform and parameters stay.
    void replace_object(size_t object, const ObjectUpload& upload);
    size_t object_count() const { return objects_.size(); }
    void remove_object(size_t object);  // waits for the GPU; later objects move down by one
    ObjectParams& params(size_t object);  // validated again at the next prepare()
    glm::mat4& model(size_t object);
    bool is_animated(size_t object) const { return objects_.at(object)->animation != nullptr; }
    // An animated object's pose for the next frames: `animation` (an index of its model's, or
    // anim::kRestPose) at `seconds`, wrapped into the animation when looping, else clamped.
    void set_animation(size_t object, int animation, double seconds, bool loop = true);

    // CPU part of a frame (uniforms, CPU-path densities). The GPU must have finished the previous frame.
    void prepare(const FrameView& view);
    void record(VkCommandBuffer cb, const RenderTargets& targets);
    // The end of a pass the caller recorded after record() into the same command buffer (the viewer's
    // panel), timed with the renderer's passes and listed in stats().gpu_ms under `pass`.
    void mark_pass(VkCommandBuffer cb, const char* pass) { timer_.mark(cb, pass); }
    // After the frame's submission has completed: GPU pass times and drawn counts into stats().
    void collect();
    const FrameStats& stats() const { return stats_; }
    bool counts_drawn() const { return options_.count_drawn; }
    // Which candidates were drawn in the last frame, one bit per stipple (count_drawn only).
    std::vector<uint32_t> drawn_mask(size_t object) const;
    // The last frame's per-polygon densities as the GPU holds them (read back; for tests and tools).
    std::vector<float> read_densities(size_t object) const;  // the last frame's
    std::vector<glm::vec2> read_density_bounds(size_t object) const;  // the last frame's (TriangleDraw least, most)
    // The triangles the last frame's depth pass drew of an object: those its list kept, or all of them
    // when it drew the whole mesh (render/depth_triangles.hpp). Read back: call after the frame completed.
    uint32_t read_depth_triangles(size_t object) const;
    // The last frame's depth as words (X8_D24 or float bits, one per pixel, top row first) when the depth
    // pass ran as compute (render/depth_raster.hpp); else null, and the depth image holds it. The depth
    // image is then filled only where a pass tests against it: read the depth back from here.
    const gpu::Buffer* depth_words() const { return depth_by_compute_ ? &splat_depth_ : nullptr; }
    // The stipples the last frame drew of an object and that inked a pixel (record_visible only; the
    // object must have been drawn by the splat). Throws stipple::Error otherwise.
    std::vector<gpu::VisibleStipple> read_visible_stipples(size_t object) const;
    const gpu::FrameUniforms& frame_uniforms() const { return frame_; }
    const ObjectGpu& object(size_t index) const { return *objects_.at(index); }
    const gpu::Context& context() const { return context_; }

    // The last frame's visible object-space line pieces (contours, borders, creases) of one object, in
    // pixels of that frame (origin at the top-left corner, y down); the pieces of one line share their
    // endpoints. Read back: call after the frame has completed. app::visible_line_segments gives them
    // as the export consumes them.
    struct LinePieces {
        std::vector<gpu::LinePiece> pieces;  // as stored (with the edge each lies on)
        uint32_t appended = 0;               // pieces found; more than pieces.size() when the buffer overflowed
    };
    LinePieces read_line_pieces(size_t object) const;

private:
    // The mesh texel views' layout (shaders/stipple_position.h, kSpecMeshVec3Texels).
    bool mesh_vec3_texels() const;
    void define_pipelines(VkFormat color_format, VkFormat depth_format);
    // Destroys what the constructor made; also when it throws midway (a shader missing, found when its
    // pipeline is defined), since a destructor does not run then and the device would be destroyed with them alive.
    void release();
    void define_line_pipelines(const gpu::GraphicsPipelineDesc& depth);
    void record_density(VkCommandBuffer cb);
    void record_stipples(VkCommandBuffer cb);
    // clear: the depth pass's scope (depth and stencil cleared; the colour too unless clear_color is false).
    void begin_rendering(VkCommandBuffer cb, const RenderTargets& targets, bool clear, bool clear_color = true) const;
    bool uses_splat(const ObjectGpu& object) const;
    // Whether the density pass cuts the object's drawn stipples into work items: the splat draws them, and
    // the indirect path lists its stipples from them.
    bool lists_work_items(const ObjectGpu& object) const;
    // Whether the gradient pass lists the chunks of the object's polygons whose density changes across
    // them (GradientChunks): the vertex path, whose draw of every candidate leaves those polygons to a
    // second, instanced draw (kSpecGradientListed, kSpecGradientChunks).
    bool lists_gradient_chunks(const ObjectGpu& object) const;
    // Whether the gradient pass lists the work items of the object's polygons whose density varies apart
    // (the splat with GPU densities, which draws them in a dispatch of their own: kSpecListVaryingApart).
    bool lists_varying_apart(const ObjectGpu& object) const;
    bool draws_points(const ObjectGpu& object) const;  // has stipples drawn by the points pipeline
    bool paper_under_splat() const;  // no toon surface and no points under the splat: it paints the paper itself
    // depth_pass.cpp
    void choose_depth_lists(const FrameView& view);   // which objects' depth passes draw a list this frame
    void record_depth_triangles(VkCommandBuffer cb);  // the depth pass's lists (objects that draw one)
    void record_depth(VkCommandBuffer cb);
    void copy_scene_depth(VkCommandBuffer cb, const RenderTargets& targets);
    // depth_raster.cpp
    bool depth_by_compute_this_frame(const RenderTargets& targets) const;
    bool triangles_small_for_compute(const FrameView& view) const;  // DepthRaster::Auto's test
    void record_depth_raster(VkCommandBuffer cb, const RenderTargets& targets);
    void copy_depth_words_to_image(VkCommandBuffer cb, const RenderTargets& targets);  // with the coverage stencil
    // splat_pass.cpp
    void ensure_frame_buffers(const RenderTargets& targets);
    // Whether the stipple pass's points read the depth words (their outline shift, kSpecOutlineShift): the
    // frame's words fit in one buffer. Before any frame has made the splat's buffers, placeholders of a word are
    // bound in their place (the stipple pipelines have set 1).
    bool points_read_depth_words(VkExtent2D extent) const;
    void bind_placeholder_frame_buffers();
    bool splat_composes_dots() const;
    void record_splat(VkCommandBuffer cb, const RenderTargets& targets);
    // list: kSplatList*; varying_density: the variant with the density across a polygon (kSpecVaryingDensity).
    VkPipeline splat_pipeline(bool round_points, bool whole_dots, uint32_t list, bool varying_density);
    void ensure_visible_list(ObjectGpu& object);  // record_visible: room for every candidate
    // line_passes.cpp
    void record_line_edges(VkCommandBuffer cb);
    void record_lines(VkCommandBuffer cb);

    const gpu::Context& context_;
    RendererOptions options_;
    VkFormat color_format_;
    VkFormat depth_format_;
    RenderLayouts layouts_;  // the object set, the splat frame set and their pipeline layouts
    std::unique_ptr<DeformPass> deform_pass_;  // animated objects' deformation, before the density
    gpu::LazyPipeline depth_pipeline_;
    // [round + 2 * outline]: the variants for large dots (kSpecRoundPoints) and those that move the dots astride
    // the outline onto the surface (kSpecOutlineShift, objects small on screen: ObjectFrame::outline_shift).
    gpu::LazyPipeline stipple_pipelines_[4];       // every candidate; the vertex shader culls (§3.2)
    gpu::LazyPipeline stipple_list_pipelines_[4];  // the survivors' list (indirect and cpu paths)
    // The vertex path's: every candidate but those of the polygons whose density changes across them,
    // then those, a chunk an instance.
    gpu::LazyPipeline stipple_gradient_listed_pipelines_[4];
    gpu::LazyPipeline stipple_chunk_pipelines_[4];
    // [1]: the variants that also write the facing bits (objects with lines; kSpecFacingBits)
    gpu::LazyPipeline density_pipelines_[2];
    gpu::LazyPipeline density_list_pipelines_[2];  // also list the polygons that draw, for the splat
    // The density pass's gradient pass over the polygons large on screen: [1] also lists their work items,
    // [2] the chunks of those whose density changes across them (the vertex path's second draw), [3] their
    // work items apart from the work list (the splat's varying dispatch).
    gpu::LazyPipeline gradient_pipelines_[4];
    gpu::LazyPipeline drawn_stipples_pipeline_;  // the indirect path's survivors' list
    gpu::LazyPipeline depth_triangles_pipeline_;  // the triangles the depth pass draws
    // The depth pass as compute: [0] every triangle, the small ones drawn; [1] the listed ones (kSpecRasterLarge).
    gpu::LazyPipeline depth_raster_pipelines_[2];
    gpu::LazyPipeline depth_coverage_pipeline_;  // the coverage stencil from its words
    bool depth_by_compute_ = false;  // this frame's depth pass ran as compute
    bool depth_triangles_small_ = false;  // the prepared view's triangles are small enough for it (auto)
    gpu::LazyPipeline depth_two_sided_pipeline_;  // the depth pass with the faces facing away too
    gpu::LazyPipeline toon_pipeline_;        // depth pass of toon-mode objects (§3.1)
    gpu::LazyPipeline toon_two_sided_pipeline_;
    gpu::LazyPipeline depth_back_faces_pipeline_;  // an open one-sided object's faces facing away
    gpu::LazyPipeline toon_back_faces_pipeline_;
    gpu::LazyPipeline facing_pipeline_;      // facing bits alone (objects with CPU densities and lines)
    gpu::LazyPipeline silhouette_pipeline_;  // Raskar-Cohen back-face lines (§3.1)
    gpu::LazyPipeline silhouette_words_pipeline_;  // the same tested against the depth words
    gpu::LazyPipeline silhouette_caps_pipeline_;        // their round caps, as points (kSpecLineCaps)
    gpu::LazyPipeline silhouette_words_caps_pipeline_;  // the same against the depth words
    gpu::LazyPipeline line_edges_pipeline_;  // this frame's lines from the edge table
    gpu::LazyPipeline line_walk_pipeline_;   // the visible pieces of the object-space lines
    gpu::LazyPipeline line_pieces_pipeline_;  // object-space line pieces as capsules
    // Compute splat: its layout (object set + frame images), pipelines, and frame images.
    // Draws the densities of the GPU's pass or the CPU's: [round dots + 2 * print detail's whole dots
    // + 4 * the list + 12 * the density across polygons] (kSpecRoundPoints, kSpecWholeDot, kSpecSplatList,
    // kSpecVaryingDensity), each made when a frame first needs it (splat_pipeline).
    gpu::LazyPipeline splat_pipelines_[24];
    VkDescriptorPool image_pool_ = VK_NULL_HANDLE;
    VkDescriptorSet image_set_ = VK_NULL_HANDLE;
    gpu::Buffer splat_background_;  // the frame's colour before the splat, which mixes ink into it
    gpu::Buffer splat_color_;       // the frame's colour while the splat draws into it (targets without words)
    gpu::Buffer splat_cover_;       // large fractional dots' summed optical depth per pixel (splat.comp), or 4 bytes
    gpu::Buffer splat_depth_;       // the depth pass's depth, for the splat's and the object-space lines' tests
    VkBufferView splat_depth_texels_ = VK_NULL_HANDLE;  // its words as R32_UINT texels (kBindingSceneDepthTexels)
    VkExtent2D splat_extent_{};
    uint64_t splat_words_serial_ = 0;  // RenderTargets::color_words_serial of the words bound (0: none or unnamed)
    bool splat_in_words_ = false;  // the splat's colour binding holds a target's words (RenderTargets::color_words)
    bool splat_targets_ = false;  // this frame's targets support the splat
    gpu::Buffer frame_uniforms_;
    gpu::FrameUniforms frame_{};
    gpu::GpuTimer timer_;
    DepthCullChooser depth_cull_;  // --depth-cull auto's choice, from the frames' GPU times
    std::vector<std::unique_ptr<ObjectGpu>> objects_;
    // The shapes of the static objects by key (object_shape_key): a copy of one shares it.
    std::unordered_map<uint64_t, std::weak_ptr<ObjectShape>> shapes_;
    // Null where none is alive (or a live one's counts differ: a hash collision).
    std::shared_ptr<ObjectShape> find_shape(uint64_t key, size_t indices, size_t stipples);
    std::unique_ptr<ObjectGpu> make_object(const ObjectUpload& upload, const glm::mat4& model, const ObjectParams& params);
    FrameView view_;
    FrameStats stats_;
};

}  // namespace stipple
