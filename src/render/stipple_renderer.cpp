#include "render/stipple_renderer.hpp"

#include <iterator>

#include <algorithm>
#include <chrono>
#include <cstring>

#include "core/error.hpp"
#include "gpu/context.hpp"
#include "render/shared_types.hpp"
#include "gpu/vk_check.hpp"
#include "render/descriptor_schema.hpp"
#include "render/path_buffers.hpp"
#include "render/density_cpu.hpp"

namespace stipple {

using gpu::Buffer;
using gpu::MemoryUse;

StippleRenderer::StippleRenderer(const gpu::Context& context, VkFormat color_format, VkFormat depth_format,
                                 RendererOptions options)
    : context_(context),
      options_(options),
      color_format_(color_format),
      depth_format_(depth_format),
      timer_(context) {
    try {
        layouts_ = create_render_layouts(context);
        define_pipelines(color_format, depth_format);
        deform_pass_ = std::make_unique<DeformPass>(context, mesh_vec3_texels());
        frame_uniforms_ = Buffer(context, sizeof(gpu::FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryUse::Upload);
    } catch (...) {
        release();
        throw;
    }
}

StippleRenderer::~StippleRenderer() { release(); }

void StippleRenderer::release() {
    vkDeviceWaitIdle(context_.device);
    objects_.clear();
    deform_pass_.reset();
    // The lazily made pipelines go with their members (gpu::LazyPipeline), after this wait for the device.
    if (image_pool_) vkDestroyDescriptorPool(context_.device, image_pool_, nullptr);
    if (splat_depth_texels_) vkDestroyBufferView(context_.device, splat_depth_texels_, nullptr);
    splat_depth_texels_ = VK_NULL_HANDLE;
    destroy_render_layouts(context_, layouts_);
}

void StippleRenderer::define_pipelines(VkFormat color_format, VkFormat depth_format) {
    gpu::GraphicsPipelineDesc depth;
    depth.vertex_shader = "depth.vert";
    depth.vertex_bindings = {{0, sizeof(glm::vec3), VK_VERTEX_INPUT_RATE_VERTEX}};
    depth.vertex_attributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0}};
    depth.depth_bias = true;
    // Front faces only, as in the paper ("even with back-face culling") and in Raskar-Cohen's method
    // ("rendering front-facing polygons into the depth buffer"): on a closed surface the back faces
    // are always behind front ones, and skipping them halves the software rasteriser's fill.
    depth.cull_mode = VK_CULL_MODE_BACK_BIT;
    depth.stencil = gpu::CoverageStencil::Write;
    depth.color_write = false;  // depth only; the colour attachment stays bound for the one rendering scope
    depth.color_format = color_format;
    depth.depth_format = depth_format;
    depth_pipeline_.define_graphics(context_, depth, layouts_.pipeline);
    // Two-sided objects: their faces facing away carry stipples too, at the same polygon offset.
    gpu::GraphicsPipelineDesc depth_two_sided = depth;
    depth_two_sided.cull_mode = VK_CULL_MODE_NONE;
    depth_two_sided_pipeline_.define_graphics(context_, depth_two_sided, layouts_.pipeline);
    // An open one-sided object's faces facing away (depth_holds_back_faces), seen through its openings: drawn
    // after its front faces with kBackFaceBiasScale, they only hide what lies behind them.
    gpu::GraphicsPipelineDesc depth_back_faces = depth;
    depth_back_faces.cull_mode = VK_CULL_MODE_FRONT_BIT;
    depth_back_faces_pipeline_.define_graphics(context_, depth_back_faces, layouts_.pipeline);

    gpu::GraphicsPipelineDesc stipple;
    stipple.vertex_shader = "stipple.vert";
    stipple.fragment_shader = "stipple.frag";
    const uint32_t vec3_texels = mesh_vec3_texels() ? 1u : 0u;
    stipple.specialization.constants = {{gpu::kSpecCountDrawn, options_.count_drawn ? 1u : 0u},
                                        {gpu::kSpecMeshVec3Texels, vec3_texels},
                                        {gpu::kSpecDepthUnorm24, depth_format == VK_FORMAT_D24_UNORM_S8_UINT ? 1u : 0u}};
    stipple.topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
    stipple.vertex_bindings = {{0, sizeof(gpu::StippleVertex), VK_VERTEX_INPUT_RATE_VERTEX}};
    stipple.vertex_attributes = {{0, 0, VK_FORMAT_R16G16_UNORM, offsetof(gpu::StippleVertex, barycentric)},
                                 {1, 0, VK_FORMAT_R32_UINT, offsetof(gpu::StippleVertex, triangle)}};
    stipple.depth_write = false;  // stipples never occlude each other
    stipple.depth_compare = VK_COMPARE_OP_LESS_OR_EQUAL;
    stipple.stencil = gpu::CoverageStencil::Test;  // never ink beside the object
    stipple.blend = true;
    stipple.color_format = color_format;
    stipple.depth_format = depth_format;
    for (uint32_t index = 0; index < 4; ++index) {  // round: large dots, pulled onto their own slanted surface
        const uint32_t round = index & 1u, outline = index >> 1;
        gpu::GraphicsPipelineDesc variant = stipple;
        variant.specialization.constants.push_back({gpu::kSpecRoundPoints, round});
        variant.specialization.constants.push_back({gpu::kSpecOutlineShift, outline});
        stipple_pipelines_[index].define_graphics(context_, variant, layouts_.splat_pipeline);
        gpu::GraphicsPipelineDesc vertex_path = variant;  // the vertex path's two draws
        vertex_path.specialization.constants.push_back({gpu::kSpecGradientListed, 1u});
        stipple_gradient_listed_pipelines_[index].define_graphics(context_, vertex_path, layouts_.splat_pipeline);
        vertex_path.specialization.constants.push_back({gpu::kSpecGradientChunks, 1u});
        stipple_chunk_pipelines_[index].define_graphics(context_, vertex_path, layouts_.splat_pipeline);
        variant.specialization.constants.push_back({gpu::kSpecDrawnList, 1u});
        stipple_list_pipelines_[index].define_graphics(context_, variant, layouts_.splat_pipeline);
    }

    gpu::GraphicsPipelineDesc toon = depth;
    toon.vertex_shader = "toon.vert";
    toon.fragment_shader = "toon.frag";
    toon.vertex_bindings.push_back({1, sizeof(glm::vec3), VK_VERTEX_INPUT_RATE_VERTEX});
    toon.vertex_attributes.push_back({1, 1, VK_FORMAT_R32G32B32_SFLOAT, 0});
    toon.color_write = true;  // opaque: the nearest surface's toon ink wins with the depth test
    toon_pipeline_.define_graphics(context_, toon, layouts_.pipeline);
    toon.cull_mode = VK_CULL_MODE_NONE;  // toon.frag flips the normal of faces seen from behind
    toon_two_sided_pipeline_.define_graphics(context_, toon, layouts_.pipeline);
    toon.cull_mode = VK_CULL_MODE_FRONT_BIT;  // an open one-sided object's faces facing away (depth_back_faces)
    toon_back_faces_pipeline_.define_graphics(context_, toon, layouts_.pipeline);

    for (uint32_t facing : {0u, 1u}) {  // [1]: the variants that write the facing bits (objects with lines)
        // The corners of polygons large on screen are read as the stipple shaders read them.
        density_pipelines_[facing].define_compute(
            context_, "density.comp", layouts_.pipeline,
            {{{gpu::kSpecFacingBits, facing}, {gpu::kSpecMeshVec3Texels, vec3_texels}}});
        density_list_pipelines_[facing].define_compute(
            context_, "density.comp", layouts_.pipeline,
            {{{gpu::kSpecListDrawn, 1u}, {gpu::kSpecFacingBits, facing}, {gpu::kSpecMeshVec3Texels, vec3_texels}}});
    }
    for (uint32_t list : {0u, 1u, 2u, 3u})  // [2]: the vertex path's chunks; [3]: the splat's varying polygons apart
        gradient_pipelines_[list].define_compute(
            context_, "density.comp", layouts_.pipeline,
            {{{gpu::kSpecGradientPass, 1u},
              {gpu::kSpecListDrawn, list == 1 || list == 3 ? 1u : 0u},
              {gpu::kSpecListGradientChunks, list == 2 ? 1u : 0u},
              {gpu::kSpecListVaryingApart, list == 3 ? 1u : 0u},
              {gpu::kSpecMeshVec3Texels, vec3_texels}}});
    facing_pipeline_.define_compute(context_, "density.comp", layouts_.pipeline,
                                                    {{{gpu::kSpecFacingOnly, 1u}, {gpu::kSpecMeshVec3Texels, vec3_texels}}});
    define_line_pipelines(depth);

    const uint32_t count = options_.count_drawn ? 1u : 0u;
    const uint32_t unorm24 = depth_format == VK_FORMAT_D24_UNORM_S8_UINT ? 1u : 0u;
    const uint32_t record = options_.record_visible ? 1u : 0u;
    // The splat's variants (splat_pipeline): [round dots + 2 * print detail's whole dots + 4 * the list + 12 *
    // the density across polygons]; most runs bind three (the work list, the varying polygons', the ring).
    for (uint32_t variant = 0; variant < std::size(splat_pipelines_); ++variant)
        splat_pipelines_[variant].define_compute(context_, "splat.comp", layouts_.splat_pipeline,
                                                 {{{gpu::kSpecCountDrawn, count},
                                                   {gpu::kSpecDepthUnorm24, unorm24},
                                                   {gpu::kSpecRecordVisible, record},
                                                   {gpu::kSpecMeshVec3Texels, vec3_texels},
                                                   {gpu::kSpecRoundPoints, variant & 1u},
                                                   {gpu::kSpecWholeDot, (variant >> 1) & 1u},
                                                   {gpu::kSpecSplatList, (variant % 12) / 4},
                                                   {gpu::kSpecVaryingDensity, variant / 12}}});
    image_pool_ = gpu::create_pool(context_, splat_frame_bindings(), 1);
    image_set_ = gpu::allocate_set(context_, image_pool_, layouts_.splat_frame_set);
    drawn_stipples_pipeline_.define_compute(context_, "drawn_stipples.comp", layouts_.pipeline);
    depth_triangles_pipeline_.define_compute(context_, "depth_triangles.comp", layouts_.pipeline,
                                                             {{{gpu::kSpecMeshVec3Texels, vec3_texels}}});
    if (context_.features.int64) {  // the depth pass as compute (render/depth_raster.hpp)
        for (uint32_t large = 0; large < 2; ++large)
            depth_raster_pipelines_[large].define_compute(
                context_, "depth_raster.comp", layouts_.splat_pipeline,
                {{{gpu::kSpecDepthUnorm24, unorm24}, {gpu::kSpecMeshVec3Texels, vec3_texels}, {gpu::kSpecRasterLarge, large}}});
        depth_coverage_pipeline_.define_compute(context_, "depth_coverage.comp", layouts_.splat_pipeline,
                                                                {{{gpu::kSpecDepthUnorm24, unorm24}}});
    }
}

bool StippleRenderer::mesh_vec3_texels() const { return context_.features.vec3_texels && !options_.scalar_texels; }

size_t StippleRenderer::add_object(const Mesh& mesh, const StippleSet& stipples, const glm::mat4& model,
                                   const ObjectParams& params, const anim::Motion& motion) {
    // A copy of a static object already here needs nothing prepared (the key is hashed again in the
    // preparation otherwise: only where there is a shape it could match).
    if (!motion && !shapes_.empty()) {
        if (std::shared_ptr<ObjectShape> shape = find_shape(object_shape_key(mesh, stipples, params.generation.seed),
                                                            mesh.indices.size(), stipples.size())) {
            objects_.push_back(create_object_copy(context_, layouts_.object_set, frame_uniforms_, std::move(shape), model,
                                                  params, options_.count_drawn));
            return objects_.size() - 1;
        }
    }
    return add_object(prepare_object_upload(context_, mesh, stipples, params.generation.seed, motion), model, params);
}

size_t StippleRenderer::add_object(const ObjectUpload& upload, const glm::mat4& model, const ObjectParams& params) {
    objects_.push_back(make_object(upload, model, params));
    return objects_.size() - 1;
}

std::unique_ptr<ObjectGpu> StippleRenderer::make_object(const ObjectUpload& upload, const glm::mat4& model,
                                                        const ObjectParams& params) {
    if (!upload.motion)
        if (std::shared_ptr<ObjectShape> shape = find_shape(upload.shape_key, upload.index_count, upload.stipple_count))
            return create_object_copy(context_, layouts_.object_set, frame_uniforms_, std::move(shape), model, params,
                                      options_.count_drawn);
    std::unique_ptr<ObjectGpu> object = create_object_gpu(context_, layouts_.object_set, frame_uniforms_, upload, model,
                                                          params, options_.count_drawn, mesh_vec3_texels());
    if (!upload.motion) {
        std::erase_if(shapes_, [](const auto& entry) { return entry.second.expired(); });  // shapes whose objects are gone
        shapes_[upload.shape_key] = object->shape;
    }
    return object;
}

std::shared_ptr<ObjectShape> StippleRenderer::find_shape(uint64_t key, size_t indices, size_t stipples) {
    const auto found = shapes_.find(key);
    if (found == shapes_.end()) return nullptr;
    std::shared_ptr<ObjectShape> shape = found->second.lock();
    // A hash collision between different objects would share wrongly: the counts at least must agree.
    if (shape && (shape->geometry.index_count != indices || shape->geometry.stipple_count != stipples)) return nullptr;
    return shape;
}


void StippleRenderer::replace_object(size_t object, const ObjectUpload& upload) {
    STIPPLE_CHECK(object < objects_.size(), "replace_object: no such object");
    const ObjectParams params = objects_[object]->params;
    const glm::mat4 model = objects_[object]->model;
    auto replacement = make_object(upload, model, params);
    VK_CHECK(vkDeviceWaitIdle(context_.device));  // the old object's buffers may be in use
    objects_[object] = std::move(replacement);
}

void StippleRenderer::remove_object(size_t object) {
    STIPPLE_CHECK(object < objects_.size(), "remove_object: no such object");
    VK_CHECK(vkDeviceWaitIdle(context_.device));
    objects_.erase(objects_.begin() + std::ptrdiff_t(object));
}

ObjectParams& StippleRenderer::params(size_t object) { return objects_.at(object)->params; }
glm::mat4& StippleRenderer::model(size_t object) { return objects_.at(object)->model; }

void StippleRenderer::set_animation(size_t object, int animation, double seconds, bool loop) {
    ObjectAnimation* a = objects_.at(object)->animation.get();
    STIPPLE_CHECK(a, "set_animation: the object is not animated");
    STIPPLE_CHECK(animation == anim::kRestPose ||
                      (animation >= 0 && size_t(animation) < a->motion.model->animations.size()),
                  "set_animation: no such animation");
    a->animation = animation;
    a->seconds = seconds;
    a->loop = loop;
}

void StippleRenderer::prepare(const FrameView& view) {
    view_ = view;
    frame_ = {};
    frame_.view_proj = view.camera.proj * view.camera.view;
    frame_.view = view.camera.view;
    frame_.light_view = glm::vec4(glm::normalize(view.light_view), 0.0f);
    frame_.paper_color = glm::vec4(view.paper_color, 1.0f);
    frame_.viewport = glm::vec4(view.extent.width, view.extent.height, 1.0f / view.extent.width,
                                1.0f / view.extent.height);
    // Pixels per unit at unit distance, for the densities: as at the extent the stipples are chosen for.
    frame_.projection = glm::vec4(view.camera.proj[1][1] * 0.5f * float(view.extent.height) / view.detail_scale,
                                  view.camera.near_plane, view.camera.orthographic ? 1.0f : 0.0f, view.detail_scale);
    std::memcpy(frame_uniforms_.mapped(), &frame_, sizeof(frame_));
    frame_uniforms_.flush();

    stats_ = {};
    auto cpu_start = std::chrono::steady_clock::now();
    for (auto& object : objects_) {
        validate_params(object->params);
        check_animated_path(*object);
        ensure_path_buffers(*object, object->params.density_path);
        if (draws_edge_lines(object->params)) ensure_line_buffers(*object);  // before the uniforms, which count the edges
        if (options_.record_visible) ensure_visible_list(*object);
        const LineWidths widths = object_line_widths(*object, view, context_.features.max_line_width);
        object->frame.line_width = widths.outline;
        object->frame.crease_width = widths.crease;
        object->frame.uniforms = make_object_uniforms(*object, view, widths);
        object->frame.outline_shift =
            points_read_depth_words(view.extent) && projected_radius_px(*object, view) < kOutlineShiftBelowPx;
        std::memcpy(object->frame.object_uniforms.mapped(), &object->frame.uniforms, sizeof(object->frame.uniforms));
        object->frame.object_uniforms.flush();
        object->frame.depth_listed = false;
        if (density_on_cpu(object->params.density_path)) run_cpu_density(*object, frame_, context_.max_groups_x());
        stats_.triangles += object->geometry.triangle_count;
        stats_.candidate_stipples += object->geometry.stipple_count;
    }
    stats_.cpu_density_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cpu_start).count();
    choose_depth_lists(view);
    // The depth pass as compute lists its large triangles in the depth lists' buffers: made here, before
    // a frame binds the objects' sets (record decides by the targets, which it alone sees).
    depth_triangles_small_ = triangles_small_for_compute(view);
    if (depth_raster_by_compute(options_.depth_raster, context_))
        for (auto& object : objects_)
            if (object->geometry.index_count > 0) ensure_depth_triangles(*object);
    DeformPass::evaluate(objects_);
}

void StippleRenderer::record_stipples(VkCommandBuffer cb) {
    VkPipeline bound = VK_NULL_HANDLE;
    for (const auto& object : objects_) {
        if (object->geometry.stipple_count == 0 || uses_splat(*object)) continue;
        // The indirect and cpu paths draw their list of survivors, in one draw of as many points as
        // the list holds; the others every candidate, culled by the vertex shader.
        const bool listed = object->params.density_path == DensityPath::Indirect ||
                            object->params.density_path == DensityPath::Cpu;
        const size_t round = (object->frame.uniforms.flags.x & gpu::kFlagRoundPoints) != 0u ? 1 : 0;
        const size_t variant = round + (object->frame.outline_shift ? 2 : 0);
        const bool gradient_listed = lists_gradient_chunks(*object);
        const VkPipeline pipeline = listed            ? stipple_list_pipelines_[variant].get()
                                    : gradient_listed ? stipple_gradient_listed_pipelines_[variant].get()
                                                      : stipple_pipelines_[variant].get();
        auto use = [&](VkPipeline p) {
            if (p != bound) vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, p);
            bound = p;
        };
        use(pipeline);
        VkDeviceSize offset = 0;
        VkBuffer vb = object->geometry.stipples.handle();
        // Set 1: the depth words, for the dots astride the outline (stipple.vert, kSpecOutlineShift).
        const VkDescriptorSet sets[] = {object->set, image_set_};
        vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, layouts_.splat_pipeline, 0, 2, sets, 0, nullptr);
        vkCmdBindVertexBuffers(cb, 0, 1, &vb, &offset);
        if (listed) {
            vkCmdDrawIndirect(cb, object->frame.drawn_stipples.handle(), 0, 1, sizeof(gpu::DrawCommand));
        } else {  // vertex; splat and cpu-splat on targets without the splat's transfers
            vkCmdDraw(cb, object->geometry.stipple_count, 1, 0, 0);
            if (gradient_listed) {  // the polygons whose density changes across them, a chunk an instance
                use(stipple_chunk_pipelines_[variant].get());
                vkCmdDrawIndirect(cb, object->frame.drawn_stipples.handle(), 0, 1, sizeof(gpu::DrawCommand));
            }
        }
    }
}

void StippleRenderer::record(VkCommandBuffer cb, const RenderTargets& targets) {
    const bool packed_color = color_format_ == VK_FORMAT_R8G8B8A8_UNORM || color_format_ == VK_FORMAT_B8G8R8A8_UNORM ||
                              color_format_ == VK_FORMAT_R8G8B8A8_SRGB || color_format_ == VK_FORMAT_B8G8R8A8_SRGB;
    splat_targets_ = packed_color && targets.splat_transfers;
    timer_.begin_frame(cb);
    if (deform_pass_->record_skinning(cb, objects_)) {  // animated objects (render/deform_pass.hpp)
        timer_.mark(cb, "skinning");
        deform_pass_->record_polygons(cb, objects_);
        timer_.mark(cb, "polygons");
    }
    record_density(cb);
    timer_.mark(cb, "density");
    depth_by_compute_ = depth_by_compute_this_frame(targets);
    if (depth_by_compute_)  // no fixed-function pass to list triangles for (the lists' buffers are reused)
        for (auto& object : objects_) object->frame.depth_listed = false;
    if (std::any_of(objects_.begin(), objects_.end(), [](const auto& o) { return o->frame.depth_listed; })) {
        record_depth_triangles(cb);
        timer_.mark(cb, "depth_list");
    }
    const bool any_lines =
        std::any_of(objects_.begin(), objects_.end(), [&](const auto& o) { return draws_edge_lines(*o); });
    const bool any_splat = std::any_of(objects_.begin(), objects_.end(), [&](const auto& o) { return uses_splat(*o); });
    const bool any_object_space_lines = std::any_of(objects_.begin(), objects_.end(), [&](const auto& o) {
        return draws_edge_lines(*o) && draws_object_space_lines(o->params);
    });

    gpu::image_barrier(cb, targets.color, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                       VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                       VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_NONE,
                       VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                       VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT);
    const bool stencil = gpu::format_has_stencil(depth_format_);
    const VkImageLayout depth_layout =
        stencil ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL : VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    gpu::image_barrier(cb, targets.depth,
                       stencil ? VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT : VK_IMAGE_ASPECT_DEPTH_BIT,
                       VK_IMAGE_LAYOUT_UNDEFINED, depth_layout,
                       VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_NONE,
                       VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                       VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT);

    // One rendering scope per pass: a software rasteriser bins a whole scope and rasterises it at its
    // end, so timestamps between passes inside one scope would not measure the passes.
    // When the splat writes every pixel afterwards (its image holds the paper wherever no ink falls),
    // the colour need not be cleared first: 0.35 ms of a software GPU's frame at 1280x1024.
    const bool splat_covers_image = any_splat && paper_under_splat();
    const bool any_points =
        std::any_of(objects_.begin(), objects_.end(), [&](const auto& o) { return draws_points(*o); });
    const bool any_outline_shift = std::any_of(objects_.begin(), objects_.end(), [&](const auto& o) {
        return draws_points(*o) && o->frame.outline_shift;
    });
    if (depth_by_compute_) {
        // §2.1 by compute, into the words; the depth image gets them where a pass tests against it.
        record_depth_raster(cb, targets);
        timer_.mark(cb, "depth");
        if (!splat_covers_image || any_points) {  // clears the colour (and the depth)
            begin_rendering(cb, targets, true, !splat_covers_image);
            vkCmdEndRendering(cb);
        }
        if (any_points) {  // the points test the depth image and its coverage stencil (the lines, the words)
            copy_depth_words_to_image(cb, targets);
            timer_.mark(cb, "depth_copy");
        }
    } else {
        begin_rendering(cb, targets, true, !splat_covers_image);
        record_depth(cb);  // §2.1: polygons pushed back by the polygon offset (and toon surfaces, §3.1)
        vkCmdEndRendering(cb);
        timer_.mark(cb, "depth");
        // The depth as words in a buffer, for the compute passes to test against and the points' outline shift.
        if (any_splat || any_object_space_lines || any_outline_shift) {
            copy_scene_depth(cb, targets);
            timer_.mark(cb, "depth_copy");
        }
    }
    if (any_points) {
        // Set 1 holds the depth words where a points object moves its dots off the outline (made above), else
        // whatever an earlier frame bound there, or placeholders before any (only the outline variant reads
        // them). Kept, not replaced by placeholders: a frame of the splat after would make them again.
        if (!splat_depth_texels_) bind_placeholder_frame_buffers();
        begin_rendering(cb, targets, false);
        record_stipples(cb);
        vkCmdEndRendering(cb);
        timer_.mark(cb, "stipples");
    }
    if (any_splat) {
        record_splat(cb, targets);
        timer_.mark(cb, "splat_out");
    }
    if (any_lines) {  // extra pipelines cost nothing when off: not even a pass is recorded
        record_line_edges(cb);  // after the depth pass: the object-space lines are tested against it
        timer_.mark(cb, "edges");
        begin_rendering(cb, targets, false);
        record_lines(cb);
        vkCmdEndRendering(cb);
        timer_.mark(cb, "lines");
    }
    // collect() and drawn_mask() read the counters through their mapping once the frame's fence signals; a
    // fence alone does not make device writes visible to the host (lavapipe's coherent memory hides it).
    if (options_.count_drawn)
        gpu::memory_barrier(cb,
                            VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT |
                                VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

void StippleRenderer::begin_rendering(VkCommandBuffer cb, const RenderTargets& targets, bool clear,
                                      bool clear_color) const {
    if (!clear) {  // the previous pass's writes before this one's reads and writes
        gpu::memory_barrier(cb,
                            VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                            VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                            VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT |
                                VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                            VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT |
                                VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                                VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
    }
    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    color.imageView = targets.color_view;
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = !clear ? VK_ATTACHMENT_LOAD_OP_LOAD
                          : (clear_color ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_DONT_CARE);
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.clearValue.color = {{view_.paper_color.r, view_.paper_color.g, view_.paper_color.b, 1.0f}};
    const bool stencil = gpu::format_has_stencil(depth_format_);
    VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depth.imageView = targets.depth_view;
    depth.imageLayout =
        stencil ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL : VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depth.loadOp = clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
    depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    depth.clearValue.depthStencil = {1.0f, 0};
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, targets.extent};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &color;
    rendering.pDepthAttachment = &depth;
    rendering.pStencilAttachment = stencil ? &depth : nullptr;  // one image: the same attachment info
    vkCmdBeginRendering(cb, &rendering);

    // Negative height: y up in NDC as in OpenGL, so counter-clockwise stays front-facing.
    VkViewport viewport{0.0f, float(targets.extent.height), float(targets.extent.width),
                        -float(targets.extent.height), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, targets.extent};
    vkCmdSetViewport(cb, 0, 1, &viewport);
    vkCmdSetScissor(cb, 0, 1, &scissor);
}

void StippleRenderer::collect() {
    stats_.gpu_ms = timer_.read();
    double depth_ms = 0.0;  // what the depth lists change: the depth pass and the lists' own
    for (const auto& [pass, ms] : stats_.gpu_ms)
        if (pass == "depth" || pass == "depth_list") depth_ms += ms;
    if (depth_ms > 0.0 && !depth_by_compute_) depth_cull_.frame_done(depth_ms);
    if (!options_.count_drawn) return;
    stats_.drawn_stipples = 0;
    for (const auto& object : objects_) {
        object->frame.debug.invalidate();
        stats_.drawn_stipples += static_cast<const gpu::DebugCounters*>(object->frame.debug.mapped())->drawn;
    }
}

std::vector<uint32_t> StippleRenderer::drawn_mask(size_t object) const {
    STIPPLE_CHECK(options_.count_drawn, "drawn_mask needs RendererOptions::count_drawn");
    const ObjectGpu& o = *objects_.at(object);
    o.frame.debug.invalidate();
    const auto* words = reinterpret_cast<const uint32_t*>(static_cast<const std::byte*>(o.frame.debug.mapped()) +
                                                         sizeof(gpu::DebugCounters));
    return std::vector<uint32_t>(words, words + (o.geometry.stipple_count + 31) / 32);
}

std::vector<float> StippleRenderer::read_densities(size_t object) const {
    std::vector<std::byte> bytes = gpu::read_buffer(context_, objects_.at(object)->frame.triangle_draw);
    std::vector<float> densities(bytes.size() / sizeof(gpu::TriangleDraw));
    for (size_t t = 0; t < densities.size(); ++t)
        std::memcpy(&densities[t], bytes.data() + t * sizeof(gpu::TriangleDraw), sizeof(float));
    return densities;
}

std::vector<glm::vec2> StippleRenderer::read_density_bounds(size_t object) const {
    std::vector<std::byte> bytes = gpu::read_buffer(context_, objects_.at(object)->frame.triangle_draw);
    std::vector<glm::vec2> bounds(bytes.size() / sizeof(gpu::TriangleDraw));
    for (size_t t = 0; t < bounds.size(); ++t)
        std::memcpy(&bounds[t], bytes.data() + t * sizeof(gpu::TriangleDraw) + offsetof(gpu::TriangleDraw, least),
                    sizeof(glm::vec2));
    return bounds;
}

}  // namespace stipple

