// The depth pass as compute (render/depth_raster.hpp, shaders/depth_raster.comp), and the copy of its
// words into the depth image, with the coverage stencil, for the passes that test against the image.
#include "render/depth_raster.hpp"

#include <algorithm>

#include "gpu/pipelines.hpp"
#include "gpu/context.hpp"
#include "render/shared_types.hpp"
#include "render/stipple_renderer.hpp"

namespace stipple {

const char* depth_raster_name(DepthRaster mode) {
    switch (mode) {
        case DepthRaster::Compute: return "compute";
        case DepthRaster::Fixed: return "fixed";
        case DepthRaster::Auto: break;
    }
    return "auto";
}

std::optional<DepthRaster> parse_depth_raster(const std::string& name) {
    for (DepthRaster mode : {DepthRaster::Auto, DepthRaster::Compute, DepthRaster::Fixed})
        if (name == depth_raster_name(mode)) return mode;
    return std::nullopt;
}

bool depth_raster_by_compute(DepthRaster mode, const gpu::Context& context) {
    if (!context.features.int64 || mode == DepthRaster::Fixed) return false;
    return mode == DepthRaster::Compute || context.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
}

bool StippleRenderer::depth_by_compute_this_frame(const RenderTargets& targets) const {
    if (!depth_raster_by_compute(options_.depth_raster, context_) || !targets.splat_transfers) return false;
    if (options_.depth_raster == DepthRaster::Auto) {
        if (!depth_triangles_small_) return false;
        // The points pipeline tests the depth image and its stencil: copying the words into them costs
        // more than the compute pass saves (the horse on the indirect path: 3.6-3.8 ms of depth and
        // 8.7-8.9 of copy against 5.0-5.3 ms for the fixed-function pass, 30-33 fps against 43-48).
        if (std::any_of(objects_.begin(), objects_.end(), [&](const auto& o) { return draws_points(*o); })) return false;
    }
    return std::none_of(objects_.begin(), objects_.end(), [](const auto& o) { return o->params.toon; });
}

bool StippleRenderer::triangles_small_for_compute(const FrameView& view) const {
    double area = 0.0, triangles = 0.0;
    for (const auto& object : objects_) {
        if (object->geometry.index_count == 0) continue;
        const float px = mean_front_triangle_px(*object, object->frame.uniforms, view);
        if (px <= 0.0f) return false;  // the eye within its bounds: triangles large on screen
        area += double(px) * object->geometry.triangle_count;
        triangles += object->geometry.triangle_count;
    }
    if (triangles == 0.0) return false;
    const double frame_px = double(view.extent.width) * double(view.extent.height);
    return area / triangles < kDepthComputeBelowPx || area < kDepthComputeBelowFrame * frame_px;
}

void StippleRenderer::record_depth_raster(VkCommandBuffer cb, const RenderTargets& targets) {
    ensure_frame_buffers(targets);
    // Nothing drawn yet: the far plane everywhere (also what "no surface here" reads as).
    const uint32_t far_word = depth_format_ == VK_FORMAT_D24_UNORM_S8_UINT ? 0x00FFFFFFu : 0x3F800000u;  // or 1.0f
    vkCmdFillBuffer(cb, splat_depth_.handle(), 0, VK_WHOLE_SIZE, far_word);
    const gpu::RasterTriangles none_listed{0u, 1u, 1u, 0u, 0u, 0u, 0u, 0u};
    for (auto& object : objects_) {
        if (object->geometry.index_count == 0) continue;
        // The listed triangles share the fixed-function pass's list buffer (made by prepare).
        vkCmdUpdateBuffer(cb, object->frame.depth_triangles.handle(), 0, sizeof none_listed, &none_listed);
    }
    gpu::memory_barrier(cb, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    for (int large = 0; large < 2; ++large) {
        vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, depth_raster_pipelines_[large].get());
        for (auto& object : objects_) {
            if (object->geometry.index_count == 0) continue;
            VkDescriptorSet sets[] = {object->set, image_set_};
            vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, layouts_.splat_pipeline, 0, 2, sets, 0, nullptr);
            if (large)
                vkCmdDispatchIndirect(cb, object->frame.depth_triangles.handle(), 0);
            else
                gpu::dispatch_items(cb, context_, object->geometry.triangle_count, gpu::kDensityWorkgroupSize);
        }
        if (!large)  // the lists and the first pass's depths before the second pass
            gpu::memory_barrier(cb, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                                VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                                VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT |
                                    VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
    }
    // The splat, the line walk, the Raskar-Cohen lines and the points' outline shift read the words (as
    // texels); the copy into the depth image and the coverage pass may too.
    gpu::buffer_barrier(cb, splat_depth_.handle(), VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT |
                            VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT |
                            VK_ACCESS_2_TRANSFER_READ_BIT);
}

void StippleRenderer::copy_depth_words_to_image(VkCommandBuffer cb, const RenderTargets& targets) {
    const bool stencil = gpu::format_has_stencil(depth_format_);
    if (stencil) {  // the coverage stencil (CoverageStencil::Write) from the words, four pixels a word
        vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, depth_coverage_pipeline_.get());
        VkDescriptorSet sets[] = {objects_.front()->set, image_set_};
        vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, layouts_.splat_pipeline, 0, 2, sets, 0, nullptr);
        const uint32_t words = (targets.extent.width * targets.extent.height + 3) / 4;
        gpu::dispatch_items(cb, context_, words, gpu::kDensityWorkgroupSize);
        gpu::buffer_barrier(cb, splat_background_.handle(), VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                            VK_ACCESS_2_TRANSFER_READ_BIT);
    }
    const VkImageAspectFlags aspects = stencil ? gpu::kDepthStencilAspect : VkImageAspectFlags(VK_IMAGE_ASPECT_DEPTH_BIT);
    const VkImageLayout attachment =
        stencil ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL : VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    gpu::image_barrier(cb, targets.depth, aspects, attachment, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                       VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    VkBufferImageCopy regions[2]{};
    regions[0].imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};
    regions[0].imageExtent = {targets.extent.width, targets.extent.height, 1};
    vkCmdCopyBufferToImage(cb, splat_depth_.handle(), targets.depth, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &regions[0]);
    if (stencil) {
        regions[1] = regions[0];
        regions[1].imageSubresource.aspectMask = VK_IMAGE_ASPECT_STENCIL_BIT;
        vkCmdCopyBufferToImage(cb, splat_background_.handle(), targets.depth, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                               &regions[1]);
        // The splat fills its background later in the frame (a copy, or the compute shader).
        gpu::buffer_barrier(cb, splat_background_.handle(), VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                            VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                            VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    }
    gpu::image_barrier(cb, targets.depth, aspects, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, attachment,
                       VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                       VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
}

}  // namespace stipple
