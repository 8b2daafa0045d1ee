// The depth pass (§2.1 hidden-stipple removal: the front faces pushed back by the polygon offset, and
// toon surfaces, §3.1), the compute pass that lists the triangles it needs on meshes finer than the
// pixels (render/depth_triangles.hpp), and the copy of its depth into words for the compute passes
// that test against it (the splat, the object-space lines).
#include <algorithm>
#include <array>
#include <span>
#include <cstring>

#include "core/error.hpp"
#include "gpu/pipelines.hpp"
#include "gpu/context.hpp"
#include "render/depth_triangles.hpp"
#include "render/shared_types.hpp"
#include "render/stipple_renderer.hpp"

namespace stipple {

void StippleRenderer::choose_depth_lists(const FrameView& view) {
    // The objects whose triangles are small enough to consider, and the smallest mean area among them.
    float smallest_px = 0.0f;
    for (auto& object : objects_) {
        if (!may_list_depth_triangles(*object)) continue;
        const float px = mean_front_triangle_px(*object, object->frame.uniforms, view);
        if (options_.depth_cull == DepthCull::On || (px > 0.0f && px < kDepthCullConsiderPx)) {
            object->frame.depth_listed = true;  // considered; the choice below may take it back
            smallest_px = smallest_px > 0.0f ? std::min(smallest_px, px) : px;
        }
    }
    bool list = options_.depth_cull == DepthCull::On;
    if (options_.depth_cull == DepthCull::Auto) list = depth_cull_.next_frame(smallest_px);
    for (auto& object : objects_) {
        object->frame.depth_listed = object->frame.depth_listed && list;
        if (object->frame.depth_listed) ensure_depth_triangles(*object);
    }
}

void StippleRenderer::record_depth_triangles(VkCommandBuffer cb) {
    const gpu::DepthTriangles empty{0u, 1u, gpu::kIndexListFirstIndex, 0, 0u, 0u, 0u, 0u};
    for (auto& object : objects_)
        if (object->frame.depth_listed)
            vkCmdUpdateBuffer(cb, object->frame.depth_triangles.handle(), 0, sizeof empty, &empty);
    gpu::memory_barrier(cb, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, depth_triangles_pipeline_.get());
    const uint32_t group = gpu::kDensityWorkgroupSize;
    for (auto& object : objects_) {
        if (!object->frame.depth_listed) continue;
        vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, layouts_.pipeline, 0, 1, &object->set, 0,
                                nullptr);
        gpu::dispatch_items(cb, context_, object->geometry.triangle_count, group);
    }
    gpu::memory_barrier(cb, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_INDEX_INPUT_BIT,
                        VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_INDEX_READ_BIT);
}

void StippleRenderer::record_depth(VkCommandBuffer cb) {
    VkPipeline bound = VK_NULL_HANDLE;
    // Toon objects last: their ink is written with the depth test, so an object without toon that lies
    // nearer must have its depth in the buffer first (drawn after, it hid the toon object's stipples but
    // not its ink: the order of a scene's objects showed through). Among toon objects the nearest wins.
    std::vector<const ObjectGpu*> order;
    for (const auto& object : objects_) order.push_back(object.get());
    std::stable_partition(order.begin(), order.end(), [](const ObjectGpu* object) { return !object->params.toon; });
    for (const ObjectGpu* object : order) {
        if (object->geometry.index_count == 0) continue;
        // Toon-mode objects shade their surface in the same pass (no extra pass when toon is off).
        const bool toon = object->params.toon;
        // Two-sided: every face at the paper's offset (each carries stipples). Open and one-sided: the front
        // faces, then the faces facing away pushed further back (kBackFaceBiasScale), which only hide.
        const bool two_sided = object->params.two_sided, back_faces = depth_holds_back_faces(*object);
        struct Draw {
            VkPipeline pipeline;
            float bias_scale;
        };
        std::array<Draw, 2> draws{};
        size_t draw_count = 0;
        if (two_sided) {
            draws[draw_count++] = {toon ? toon_two_sided_pipeline_.get() : depth_two_sided_pipeline_.get(), 1.0f};
        } else {
            draws[draw_count++] = {toon ? toon_pipeline_.get() : depth_pipeline_.get(), 1.0f};
            if (back_faces)
                draws[draw_count++] = {toon ? toon_back_faces_pipeline_.get() : depth_back_faces_pipeline_.get(), gpu::kBackFaceBiasScale};
        }
        VkBuffer buffers[] = {object->geometry.positions.handle(), object->geometry.normals.handle()};
        VkDeviceSize offsets[] = {0, 0};
        for (const Draw& draw : std::span(draws.data(), draw_count)) {
            if (draw.pipeline != bound) {
                vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, draw.pipeline);
                bound = draw.pipeline;
            }
            // Set for every draw: the bias is dynamic state, and the last draw may have scaled it.
            vkCmdSetDepthBias(cb, gpu::kDepthBiasConstant * draw.bias_scale, 0.0f, gpu::kDepthBiasSlopeFactor * draw.bias_scale);
            vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, layouts_.pipeline, 0, 1, &object->set, 0,
                                    nullptr);
            vkCmdBindVertexBuffers(cb, 0, toon ? 2 : 1, buffers, offsets);
            if (object->frame.depth_listed) {  // the triangles that may cover a pixel centre (depth_triangles.comp)
                vkCmdBindIndexBuffer(cb, object->frame.depth_triangles.handle(), 0, VK_INDEX_TYPE_UINT32);
                vkCmdDrawIndexedIndirect(cb, object->frame.depth_triangles.handle(), 0, 1, sizeof(gpu::DepthTriangles));
            } else {
                vkCmdBindIndexBuffer(cb, object->geometry.indices.handle(), 0, VK_INDEX_TYPE_UINT32);
                vkCmdDrawIndexed(cb, object->geometry.index_count, 1, 0, 0, 0);
            }
        }
    }
}

void StippleRenderer::copy_scene_depth(VkCommandBuffer cb, const RenderTargets& targets) {
    ensure_frame_buffers(targets);
    const bool stencil = gpu::format_has_stencil(depth_format_);
    const VkImageAspectFlags depth_aspect =
        stencil ? VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT : VK_IMAGE_ASPECT_DEPTH_BIT;
    const VkImageLayout depth_attachment =
        stencil ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL : VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    gpu::image_barrier(cb, targets.depth, depth_aspect, depth_attachment, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                       VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};
    region.imageExtent = {targets.extent.width, targets.extent.height, 1};
    vkCmdCopyImageToBuffer(cb, targets.depth, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, splat_depth_.handle(), 1, &region);
    gpu::image_barrier(cb, targets.depth, depth_aspect, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, depth_attachment,
                       VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                       VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                       VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
    // The compute passes that read it (splat, line edges) follow, as words and as texels, and the points'
    // outline shift (stipple.vert) reads the texels.
    gpu::buffer_barrier(cb, splat_depth_.handle(), VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
}

uint32_t StippleRenderer::read_depth_triangles(size_t index) const {
    const ObjectGpu& object = *objects_.at(index);
    if (!object.frame.depth_listed) return object.geometry.index_count / 3;
    const std::vector<std::byte> bytes = gpu::read_buffer(context_, object.frame.depth_triangles, sizeof(gpu::DepthTriangles));
    gpu::DepthTriangles header;
    std::memcpy(&header, bytes.data(), sizeof header);
    return header.index_count / 3;
}

}  // namespace stipple
