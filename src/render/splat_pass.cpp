// The compute splat's frame (beyond the paper; shaders/splat.comp): the colour so far as words in a
// buffer (or the linear target's own pixels), the scene depth copied to words beside it
// (depth_pass.cpp), one indirect dispatch per object over the work items the density pass listed,
// and the words back into the colour image. Also the list of visible stipples it records for vector
// output (RendererOptions::record_visible).
#include <algorithm>
#include <cstring>

#include <glm/gtc/packing.hpp>

#include "core/error.hpp"
#include "core/printf_string.hpp"
#include "gpu/context.hpp"
#include "render/descriptor_schema.hpp"
#include "render/shared_types.hpp"
#include "render/stipple_renderer.hpp"

namespace stipple {

VkPipeline StippleRenderer::splat_pipeline(bool round_points, bool whole_dots, uint32_t list, bool varying_density) {
    STIPPLE_CHECK(list <= gpu::kSplatListRing, "a splat list is kSplatListDrawn, kSplatListVarying or kSplatListRing");
    return splat_pipelines_[(round_points ? 1 : 0) + (whole_dots ? 2 : 0) + 4 * list + (varying_density ? 12 : 0)].get();
}

void StippleRenderer::ensure_frame_buffers(const RenderTargets& targets) {
    const VkExtent2D extent = targets.extent;
    // A target's own words are bound again unless they are the ones bound (by serial: another target's
    // buffer may come at the same handle).
    const bool words = targets.color_words != VK_NULL_HANDLE;
    const bool same_words = words && targets.color_words_serial != 0 && targets.color_words_serial == splat_words_serial_;
    const bool resized = splat_extent_.width != extent.width || splat_extent_.height != extent.height;
    const VkDeviceSize pixels = VkDeviceSize(extent.width) * extent.height;
    if (pixels > context_.max_pixel_words())
        fail(printf_string("a %ux%u frame needs %.0f MiB of pixel words for the compute splat and the object-space "
                           "lines, more than this device's largest storage buffer or texel buffer holds (%.0f MiB): draw it in tiles "
                           "(stipple render does so itself), smaller, or with a points path (--density-path "
                           "vertex, indirect or cpu) and no object-space lines",
                           extent.width, extent.height, double(pixels * 4) / 1048576.0,
                           double(context_.max_pixel_words() * 4) / 1048576.0));
    // The large dots' cover sums, full size only while some object draws them (else a placeholder).
    const VkDeviceSize cover_bytes = splat_composes_dots() ? pixels * 4 : 4;
    const bool cover_changed = splat_cover_.size() != cover_bytes;
    if (!resized && !cover_changed && (words ? same_words : !splat_in_words_)) return;
    const auto usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    if (resized) {
        splat_background_ = gpu::Buffer(context_, pixels * 4, usage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                        gpu::MemoryUse::DeviceLocal);
        splat_color_ = gpu::Buffer(context_, pixels * 4, usage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                   gpu::MemoryUse::DeviceLocal);
        // Also copied out: into the depth image or read back, when the depth pass ran as compute.
        splat_depth_ = gpu::Buffer(context_, pixels * 4,
                                   usage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT,
                                   gpu::MemoryUse::DeviceLocal);
        if (splat_depth_texels_) vkDestroyBufferView(context_.device, splat_depth_texels_, nullptr);
        splat_depth_texels_ = gpu::create_texel_view(context_, splat_depth_.handle(), VK_FORMAT_R32_UINT);
        splat_extent_ = extent;
    }
    if (cover_changed) splat_cover_ = gpu::Buffer(context_, cover_bytes, usage, gpu::MemoryUse::DeviceLocal);
    splat_in_words_ = words;
    splat_words_serial_ = words ? targets.color_words_serial : 0;
    // In the order of splat_frame_bindings(): background, scene depth, colour, cover. The previous frame
    // has completed.
    const VkBuffer frame_buffers[] = {splat_background_.handle(), splat_depth_.handle(),
                                      words ? targets.color_words : splat_color_.handle(), splat_cover_.handle(),
                                      splat_depth_.handle()};
    const VkBufferView frame_views[] = {VK_NULL_HANDLE, VK_NULL_HANDLE, VK_NULL_HANDLE, VK_NULL_HANDLE, splat_depth_texels_};
    gpu::write_buffer_set(context_.device, image_set_, splat_frame_bindings(), frame_buffers, frame_views);
}

bool StippleRenderer::points_read_depth_words(VkExtent2D extent) const {
    return VkDeviceSize(extent.width) * extent.height <= context_.max_pixel_words();
}

void StippleRenderer::bind_placeholder_frame_buffers() {
    const auto usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    splat_background_ = gpu::Buffer(context_, 4, usage, gpu::MemoryUse::DeviceLocal);
    splat_color_ = gpu::Buffer(context_, 4, usage, gpu::MemoryUse::DeviceLocal);
    splat_depth_ = gpu::Buffer(context_, 4, usage | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT, gpu::MemoryUse::DeviceLocal);
    splat_cover_ = gpu::Buffer(context_, 4, usage, gpu::MemoryUse::DeviceLocal);
    if (splat_depth_texels_) vkDestroyBufferView(context_.device, splat_depth_texels_, nullptr);
    splat_depth_texels_ = gpu::create_texel_view(context_, splat_depth_.handle(), VK_FORMAT_R32_UINT);
    splat_extent_ = {};  // the next frame that fits makes its buffers again (ensure_frame_buffers)
    splat_in_words_ = false;
    splat_words_serial_ = 0;
    const VkBuffer frame_buffers[] = {splat_background_.handle(), splat_depth_.handle(), splat_color_.handle(),
                                      splat_cover_.handle(), splat_depth_.handle()};
    const VkBufferView frame_views[] = {VK_NULL_HANDLE, VK_NULL_HANDLE, VK_NULL_HANDLE, VK_NULL_HANDLE, splat_depth_texels_};
    gpu::write_buffer_set(context_.device, image_set_, splat_frame_bindings(), frame_buffers, frame_views);
}

// Whether a splat object draws large (round) dots, whose overlapping fractional ones compose (splat.comp).
bool StippleRenderer::splat_composes_dots() const {
    return std::any_of(objects_.begin(), objects_.end(), [&](const auto& object) {
        return uses_splat(*object) && (object->frame.uniforms.flags.x & gpu::kFlagRoundPoints) != 0u;
    });
}

// The scene depth is already in splat_depth_ (copy_scene_depth).
void StippleRenderer::record_splat(VkCommandBuffer cb, const RenderTargets& targets) {
    const VkDeviceSize pixels = VkDeviceSize(targets.extent.width) * targets.extent.height;
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {targets.extent.width, targets.extent.height, 1};

    // The colour so far: the background the splat mixes ink into, and the buffer it draws in. With
    // only paper under the splat (no toon surfaces, no stipples drawn as points) both are a fill.
    const bool paper_only = paper_under_splat();
    const uint32_t blue_first =
        color_format_ == VK_FORMAT_B8G8R8A8_UNORM || color_format_ == VK_FORMAT_B8G8R8A8_SRGB ? 1u : 0u;
    const glm::vec4 paper = blue_first ? glm::vec4(glm::vec3(view_.paper_color.b, view_.paper_color.g,
                                                             view_.paper_color.r), 1.0f)
                                       : glm::vec4(glm::vec3(view_.paper_color), 1.0f);
    const VkBuffer words = targets.color_words;
    if (words) {
        // The splat draws in the image's own pixels: GENERAL, where a linear image's memory is its pixels.
        // The copies and fills below reach it through the words buffer: an aliased barrier.
        gpu::aliased_image_barrier(cb, targets.color, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                   VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                   VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_CLEAR_BIT,
                                   VK_ACCESS_2_TRANSFER_READ_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT);
        if (paper_only) {
            vkCmdFillBuffer(cb, words, 0, pixels * 4, glm::packUnorm4x8(paper));
        } else {
            const VkBufferCopy whole{0, 0, pixels * 4};
            vkCmdCopyBuffer(cb, words, splat_background_.handle(), 1, &whole);
        }
    } else {
        gpu::image_barrier(cb, targets.color, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                           VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                           VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                           VK_ACCESS_2_TRANSFER_READ_BIT);
        if (paper_only) {
            vkCmdFillBuffer(cb, splat_color_.handle(), 0, pixels * 4, glm::packUnorm4x8(paper));
        } else {
            vkCmdCopyImageToBuffer(cb, targets.color, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, splat_background_.handle(),
                                   1, &region);
            gpu::buffer_barrier(cb, splat_background_.handle(), VK_PIPELINE_STAGE_2_COPY_BIT,
                                VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                                VK_ACCESS_2_TRANSFER_READ_BIT);
            const VkBufferCopy whole{0, 0, pixels * 4};
            vkCmdCopyBuffer(cb, splat_background_.handle(), splat_color_.handle(), 1, &whole);
        }
    }
    // Overlapping fractional large dots compose through their summed optical depth (splat.comp).
    if (splat_composes_dots()) vkCmdFillBuffer(cb, splat_cover_.handle(), 0, pixels * 4, 0u);
    gpu::memory_barrier(cb, VK_PIPELINE_STAGE_2_TRANSFER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);

    timer_.mark(cb, "splat_in");
    const uint32_t push[2] = {blue_first, paper_only ? 1u : 0u};
    vkCmdPushConstants(cb, layouts_.splat_pipeline, gpu::kPushConstantStages, 0, sizeof push, push);
    VkPipeline bound = VK_NULL_HANDLE;
    const bool whole_dots = view_.detail_scale > 1.0f;
    // Over one of the object's lists (kSplatList*), whose header is the dispatch.
    auto dispatch_over = [&](const ObjectGpu& object, uint32_t list, bool varying_density, const gpu::Buffer& items) {
        const bool round = (object.frame.uniforms.flags.x & gpu::kFlagRoundPoints) != 0u;
        const VkPipeline pipeline = splat_pipeline(round, whole_dots, list, varying_density);
        if (pipeline != bound) vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
        bound = pipeline;
        VkDescriptorSet sets[] = {object.set, image_set_};
        vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, layouts_.splat_pipeline, 0, 2, sets, 0,
                                nullptr);
        vkCmdDispatchIndirect(cb, items.handle(), 0);
    };
    // Objects in one pass, in any order: the same image. The polygons that draw; with GPU densities those
    // whose density varies across them apart, so that the others' dispatch has none of that code. (The CPU's
    // list holds both: its dispatch has it.)
    for (const auto& object : objects_) {
        if (!uses_splat(*object) || object->geometry.triangle_count == 0) continue;
        const bool apart = lists_varying_apart(*object);
        dispatch_over(*object, gpu::kSplatListDrawn, !apart, object->frame.drawn_polygons);
        if (apart) dispatch_over(*object, gpu::kSplatListVarying, true, object->frame.drawn_stipples);
    }
    // The ring pass: the work items those dispatches listed with a dot astride the outline (none at print
    // detail, whose whole dots stop at the outline). It inks pixels they may have inked: ordered after them.
    if (!whole_dots) {
        gpu::memory_barrier(cb, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                            VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT |
                                VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
        for (const auto& object : objects_)
            if (uses_splat(*object) && object->geometry.triangle_count != 0)
                dispatch_over(*object, gpu::kSplatListRing, true, object->frame.splat_ring);
    }
    timer_.mark(cb, "splat");

    if (words) {  // already in the image: back to an attachment for what follows (lines, a read-back)
        gpu::aliased_image_barrier(cb, targets.color, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
                                   VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                   VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                                   VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
                                   VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT |
                                       VK_ACCESS_2_TRANSFER_READ_BIT);
        return;
    }
    // Back into the colour image, and back to an attachment for what follows.
    gpu::memory_barrier(cb, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
    gpu::image_barrier(cb, targets.color, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                       VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    vkCmdCopyBufferToImage(cb, splat_color_.handle(), targets.color, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    gpu::image_barrier(cb, targets.color, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                       VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                       VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                       VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
}

void StippleRenderer::ensure_visible_list(ObjectGpu& object) {
    const VkDeviceSize bytes =
        sizeof(gpu::VisibleStipplesHeader) + sizeof(gpu::VisibleStipple) * VkDeviceSize(object.geometry.stipple_count);
    if (object.frame.visible_stipples.size() >= bytes) return;
    check_visible_list_fits(context_, object.geometry.stipple_count);
    object.frame.visible_stipples = gpu::Buffer(
        context_, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::DeviceLocal);
    write_object_descriptors(object);
}

std::vector<gpu::VisibleStipple> StippleRenderer::read_visible_stipples(size_t index) const {
    const ObjectGpu& object = *objects_.at(index);
    if (!options_.record_visible || !object.frame.splatted)
        fail("read_visible_stipples: object " + std::to_string(index) +
             " was not drawn by the splat with recording on (RendererOptions::record_visible, a splat path)");
    const std::vector<std::byte> bytes = gpu::read_buffer(context_, object.frame.visible_stipples);
    gpu::VisibleStipplesHeader header{};
    std::memcpy(&header, bytes.data(), sizeof header);
    STIPPLE_CHECK(header.count <= object.geometry.stipple_count, "more visible stipples than candidates");
    std::vector<gpu::VisibleStipple> visible(header.count);
    if (!visible.empty())  // memcpy from or to no storage is undefined even for 0 bytes
        std::memcpy(visible.data(), bytes.data() + sizeof header, sizeof(gpu::VisibleStipple) * visible.size());
    // The splat appends them in whatever order its lanes finish: in candidate order, the same command lists the
    // same stipples in the same order (the plot's chance-drawn least marks are drawn per dot in that order; a
    // tick plot's dot count varied from run to run).
    std::sort(visible.begin(), visible.end(),
              [](const gpu::VisibleStipple& a, const gpu::VisibleStipple& b) { return a.index < b.index; });
    return visible;
}

}  // namespace stipple
