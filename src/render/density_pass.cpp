// The density pass (§2.2 shading, §2.3 distance enhancement and polygon selection; shaders/density.comp)
// and what each path needs of it: the clears of the lists it writes, the densities the CPU paths upload
// instead, the gradient pass over the polygons large on screen, and the indirect path's list of the
// stipples that draw. Also which path an object takes (splat, work items, gradient chunks).
#include <algorithm>

#include "gpu/pipelines.hpp"
#include "gpu/context.hpp"
#include "render/path_buffers.hpp"
#include "render/shared_types.hpp"
#include "render/stipple_renderer.hpp"

namespace stipple {

bool StippleRenderer::uses_splat(const ObjectGpu& object) const {
    return draws_by_splat(object.params.density_path) && splat_targets_;
}

bool StippleRenderer::lists_work_items(const ObjectGpu& object) const {
    return uses_splat(object) || object.params.density_path == DensityPath::Indirect;
}

bool StippleRenderer::lists_gradient_chunks(const ObjectGpu& object) const {
    return object.params.density_path == DensityPath::Vertex;
}

bool StippleRenderer::lists_varying_apart(const ObjectGpu& object) const {
    return uses_splat(object) && !density_on_cpu(object.params.density_path);
}

bool StippleRenderer::paper_under_splat() const {
    return std::none_of(objects_.begin(), objects_.end(), [&](const auto& o) { return o->params.toon || draws_points(*o); });
}

bool StippleRenderer::draws_points(const ObjectGpu& object) const {
    return object.geometry.stipple_count > 0 && !uses_splat(object);
}

void StippleRenderer::record_density(VkCommandBuffer cb) {
    const uint32_t group = gpu::kDensityWorkgroupSize;
    auto bind = [&](const ObjectGpu& object, VkPipeline pipeline) {
        vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
        vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, layouts_.pipeline, 0, 1, &object.set, 0,
                                nullptr);
    };
    auto dispatch = [&](const ObjectGpu& object, VkPipeline pipeline) {
        bind(object, pipeline);
        gpu::dispatch_items(cb, context_, object.geometry.triangle_count, group);
    };
    // Over a list a pass wrote, whose header is the dispatch (DrawnPolygons).
    auto dispatch_over = [&](const ObjectGpu& object, VkPipeline pipeline, const gpu::Buffer& list) {
        bind(object, pipeline);
        vkCmdDispatchIndirect(cb, list.handle(), 0);
    };
    // Densities: the compute pass (vertex, indirect and splat paths) or the CPU's upload; clears first.
    bool any_indirect = false;
    bool any_pass = false;
    bool any_facing = false;  // CPU densities with lines: the density pass's facing bits alone
    for (auto& object : objects_) {
        if (object->geometry.triangle_count == 0) continue;
        if (options_.count_drawn) vkCmdFillBuffer(cb, object->frame.debug.handle(), 0, VK_WHOLE_SIZE, 0);
        if (options_.record_visible)
            vkCmdFillBuffer(cb, object->frame.visible_stipples.handle(), 0, sizeof(gpu::VisibleStipplesHeader), 0);
        if (draws_edge_lines(*object))  // the density pass or-s each subgroup's facing bits into it
            vkCmdFillBuffer(cb, object->frame.facing.handle(), 0, VK_WHOLE_SIZE, 0);
        const bool splat = uses_splat(*object);
        object->frame.splatted = splat;
        const gpu::DrawnPolygons empty{0u, 1u, 1u, 0u};  // an empty list: no groups yet (y and z are 1)
        // No dot astride the outline yet (the splat's ring pass), whoever computes the densities.
        if (splat) vkCmdUpdateBuffer(cb, object->frame.splat_ring.handle(), 0, sizeof empty, &empty);
        if (density_on_cpu(object->params.density_path)) {  // the densities, then the list the CPU wrote
            const bool points = object->params.density_path == DensityPath::Cpu;
            const VkDeviceSize header = points ? sizeof(gpu::DrawCommand) : sizeof(gpu::DrawnPolygons);
            VkBufferCopy regions[2] = {{0, 0, staged_list_offset(*object)},
                                       {staged_list_offset(*object), 0, header + sizeof(uint32_t) * object->frame.cpu_listed}};
            vkCmdCopyBuffer(cb, object->frame.draw_staging.handle(), object->frame.triangle_draw.handle(), 1, &regions[0]);
            if (points)
                vkCmdCopyBuffer(cb, object->frame.draw_staging.handle(), object->frame.drawn_stipples.handle(), 1, &regions[1]);
            else if (splat)
                vkCmdCopyBuffer(cb, object->frame.draw_staging.handle(), object->frame.drawn_polygons.handle(), 1, &regions[1]);
            any_facing = any_facing || draws_edge_lines(*object);
            continue;
        }
        any_pass = true;
        if (object->params.density_path == DensityPath::Indirect) {  // an empty list: no points yet
            const gpu::DrawCommand no_points{0u, 1u, 0u, 0u};
            vkCmdUpdateBuffer(cb, object->frame.drawn_stipples.handle(), 0, sizeof no_points, &no_points);
            any_indirect = true;
        }
        if (lists_gradient_chunks(*object)) {  // no chunks yet: kGradientChunk vertices, no instance
            const gpu::DrawCommand no_chunks{gpu::kGradientChunk, 0u, 0u, 0u};
            vkCmdUpdateBuffer(cb, object->frame.drawn_stipples.handle(), 0, sizeof no_chunks, &no_chunks);
        }
        if (lists_work_items(*object))
            vkCmdUpdateBuffer(cb, object->frame.drawn_polygons.handle(), 0, sizeof empty, &empty);
        if (lists_varying_apart(*object))  // the varying polygons' work items
            vkCmdUpdateBuffer(cb, object->frame.drawn_stipples.handle(), 0, sizeof empty, &empty);
        vkCmdUpdateBuffer(cb, object->frame.gradient_polygons.handle(), 0, sizeof empty, &empty);
    }
    if (any_pass || any_facing) {
        // After the copies and fills above, also for the facing-only variant: it binds the densities the
        // CPU just copied, and a shader that can write a buffer is ordered after its transfers.
        // The pass reads the first stipples through the densities' texel view (a sampled read).
        gpu::memory_barrier(cb, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                            VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT |
                                VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
        for (auto& object : objects_) {
            if (object->geometry.triangle_count == 0) continue;
            if (!density_on_cpu(object->params.density_path)) {
                const size_t facing = draws_edge_lines(*object) ? 1 : 0;
                dispatch(*object, lists_work_items(*object) ? density_list_pipelines_[facing].get() : density_pipelines_[facing].get());
            }
            else if (draws_edge_lines(*object))
                dispatch(*object, facing_pipeline_.get());  // the lines' facing bits
        }
    }
    // The gradient pass over the polygons each density pass listed as large on screen (density.comp): the
    // bounds of the density across them and, for the paths that list work items, theirs.
    if (any_pass) {
        gpu::memory_barrier(cb, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                            VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT |
                                VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
        for (auto& object : objects_) {
            if (object->geometry.triangle_count == 0 || density_on_cpu(object->params.density_path)) continue;
            const size_t gradient = lists_varying_apart(*object) ? 3
                                    : lists_work_items(*object)  ? 1
                                    : lists_gradient_chunks(*object) ? 2
                                                                     : 0;
            dispatch_over(*object, gradient_pipelines_[gradient].get(), object->frame.gradient_polygons);
        }
    }
    // Indirect path: the list of the stipples that draw, from the densities just written (read through
    // their texel view: a sampled read), one invocation per work item of the density pass (runs of at
    // most kSplatChunk stipples, as the splat takes them: lavapipe ends every loop of an invocation after
    // 65535 iterations, and one invocation per polygon lost the stipples of polygons drawing more).
    if (any_indirect) {
        gpu::memory_barrier(cb, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_CLEAR_BIT,
                            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT,
                            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                            VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT |
                                VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
        for (auto& object : objects_) {
            if (object->geometry.triangle_count == 0 || object->params.density_path != DensityPath::Indirect) continue;
            dispatch_over(*object, drawn_stipples_pipeline_.get(), object->frame.drawn_polygons);
        }
    }
    gpu::memory_barrier(cb, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT |
                            VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT |
                            VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
}

}  // namespace stipple
