// The frame's lines, drawn from each object's edge table (render/silhouette_edges.hpp):
//   line edges (compute, after the depth pass): per edge, from its polygons' facing bits, the §3.1
//     Raskar-Cohen index list and the list of contours, borders and creases (shaders/line_edges.comp);
//     then per listed edge, its visible pieces, found by walking it against the depth pass
//     (shaders/line_walk.comp);
//   lines (one rendering scope): Raskar-Cohen wide lines behind the front faces' depth (the depth
//     image, or the depth words when the depth pass ran as compute: silhouette_words.frag), and the
//     object-space pieces as capsules (shaders/line_pieces.*), which need no depth test: the pieces
//     are already the visible parts, so a line is never nibbled by the surface it lies on.
#include <algorithm>
#include <cstring>
#include <tuple>

#include "core/error.hpp"
#include "gpu/pipelines.hpp"
#include "gpu/context.hpp"
#include "render/shared_types.hpp"
#include "render/stipple_renderer.hpp"

namespace stipple {

void StippleRenderer::define_line_pipelines(const gpu::GraphicsPipelineDesc& depth) {
    // Raskar-Cohen: edges with a face facing away as wide lines; the front faces' depth lets only the
    // silhouette through.
    gpu::GraphicsPipelineDesc lines;
    lines.vertex_shader = "depth.vert";
    lines.fragment_shader = "silhouette.frag";
    lines.topology = VK_PRIMITIVE_TOPOLOGY_LINE_LIST;
    lines.vertex_bindings = depth.vertex_bindings;
    lines.vertex_attributes = depth.vertex_attributes;
    lines.depth_write = false;
    lines.depth_compare = VK_COMPARE_OP_LESS_OR_EQUAL;
    lines.dynamic_line_width = true;
    lines.stencil = gpu::CoverageStencil::None;  // outlines lie half outside the surface
    lines.color_format = color_format_;
    lines.depth_format = depth_format_;
    silhouette_pipeline_.define_graphics(context_, lines, layouts_.pipeline);
    // The same against the depth words, when the depth pass ran as compute (no depth image then).
    gpu::GraphicsPipelineDesc lines_on_words = lines;
    lines_on_words.fragment_shader = "silhouette_words.frag";
    lines_on_words.depth_test = false;
    lines_on_words.specialization = {{{gpu::kSpecDepthUnorm24, depth_format_ == VK_FORMAT_D24_UNORM_S8_UINT ? 1u : 0u}}};
    silhouette_words_pipeline_.define_graphics(context_, lines_on_words, layouts_.splat_pipeline);
    // Their round caps: an end of each edge as a point of the line's width (silhouette_caps.vert, kSpecLineCaps).
    for (auto [desc, caps, layout] : {std::tuple{lines, &silhouette_caps_pipeline_, layouts_.pipeline},
                                      std::tuple{lines_on_words, &silhouette_words_caps_pipeline_, layouts_.splat_pipeline}}) {
        desc.vertex_shader = "silhouette_caps.vert";
        desc.vertex_bindings.clear();  // the ends are read from the index list and the mesh's texels
        desc.vertex_attributes.clear();
        desc.topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
        desc.dynamic_line_width = false;
        desc.specialization.constants.push_back({gpu::kSpecLineCaps, 1u});
        desc.specialization.constants.push_back({gpu::kSpecMeshVec3Texels, mesh_vec3_texels() ? 1u : 0u});
        caps->define_graphics(context_, desc, layout);
    }

    gpu::GraphicsPipelineDesc pieces;
    pieces.vertex_shader = "line_pieces.vert";
    pieces.fragment_shader = "line_pieces.frag";
    pieces.depth_test = false;  // the pieces are the visible parts (line_edges.comp tested them)
    pieces.depth_write = false;
    pieces.color_format = color_format_;
    pieces.depth_format = depth_format_;
    line_pieces_pipeline_.define_graphics(context_, pieces, layouts_.pipeline);

    line_edges_pipeline_.define_compute(context_, "line_edges.comp", layouts_.pipeline);
    // Reads the depth pass's words from the splat's frame set (set 1), hence the splat's layout.
    const uint32_t unorm24 = depth_format_ == VK_FORMAT_D24_UNORM_S8_UINT ? 1u : 0u;
    line_walk_pipeline_.define_compute(context_, "line_walk.comp", layouts_.splat_pipeline,
                                                       {{{gpu::kSpecDepthUnorm24, unorm24},
                                                         {gpu::kSpecMeshVec3Texels, mesh_vec3_texels() ? 1u : 0u}}});
}

void StippleRenderer::record_line_edges(VkCommandBuffer cb) {
    bool any_walk = false;
    for (const auto& object : objects_) {
        if (!draws_edge_lines(*object)) continue;
        // One instance, no indices yet; the indices follow the header (shared_types.h: why not a bind offset).
        const gpu::SilhouetteLines empty{0u, 1u, gpu::kIndexListFirstIndex, 0, 0u, 0u, 0u, 0u};
        vkCmdUpdateBuffer(cb, object->frame.silhouette_lines.handle(), 0, sizeof empty, &empty);
        if (!draws_object_space_lines(object->params)) continue;
        any_walk = true;
        const gpu::LineCandidates no_edges{0u, 1u, 1u, 0u};  // no groups yet (y and z are 1)
        vkCmdUpdateBuffer(cb, object->frame.line_candidates.handle(), 0, sizeof no_edges, &no_edges);
        const gpu::LinePiecesHeader no_pieces{0u, 1u, 0u, 0u, object->frame.line_piece_capacity, 0u, 0u, 0u};
        vkCmdUpdateBuffer(cb, object->frame.line_pieces.handle(), 0, sizeof no_pieces, &no_pieces);
    }
    gpu::memory_barrier(cb, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, line_edges_pipeline_.get());
    const uint32_t group = gpu::kDensityWorkgroupSize;
    for (const auto& object : objects_) {
        if (!draws_edge_lines(*object)) continue;
        vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, layouts_.pipeline, 0, 1, &object->set, 0, nullptr);
        gpu::dispatch_items(cb, context_, object->geometry.silhouette_edge_count, group);
    }
    if (any_walk) {  // the listed edges, walked against the depth pass (copied by copy_scene_depth)
        gpu::memory_barrier(cb, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                            VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
        vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, line_walk_pipeline_.get());
        for (const auto& object : objects_) {
            if (!draws_edge_lines(*object) || !draws_object_space_lines(object->params)) continue;
            VkDescriptorSet sets[] = {object->set, image_set_};
            vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, layouts_.splat_pipeline, 0, 2, sets, 0,
                                    nullptr);
            vkCmdDispatchIndirect(cb, object->frame.line_candidates.handle(), 0);
        }
    }
    gpu::memory_barrier(cb, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_INDEX_INPUT_BIT |
                            VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT,
                        VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_INDEX_READ_BIT |
                            VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
}

void StippleRenderer::record_lines(VkCommandBuffer cb) {
    VkPipeline bound = VK_NULL_HANDLE;
    for (const auto& object : objects_) {
        if (!draws_edge_lines(*object)) continue;
        vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, layouts_.pipeline, 0, 1, &object->set, 0,
                                nullptr);
        if (object->params.silhouette_lines) {
            const VkPipeline pipeline = depth_by_compute_ ? silhouette_words_pipeline_.get() : silhouette_pipeline_.get();
            if (bound != pipeline) vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
            bound = pipeline;
            if (depth_by_compute_) {  // the depth words too (set 1)
                VkDescriptorSet sets[] = {object->set, image_set_};
                vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, layouts_.splat_pipeline, 0, 2, sets, 0,
                                        nullptr);
            }
            VkDeviceSize offset = 0;
            VkBuffer vb = object->geometry.positions.handle();
            vkCmdSetLineWidth(cb, object->frame.line_width);
            vkCmdBindVertexBuffers(cb, 0, 1, &vb, &offset);
            vkCmdBindIndexBuffer(cb, object->frame.silhouette_lines.handle(), 0, VK_INDEX_TYPE_UINT32);
            vkCmdDrawIndexedIndirect(cb, object->frame.silhouette_lines.handle(), 0, 1, sizeof(gpu::SilhouetteLines));
            if (object->frame.line_width > gpu::kLineCapsAbovePx && context_.features.large_points) {
                bound = depth_by_compute_ ? silhouette_words_caps_pipeline_.get() : silhouette_caps_pipeline_.get();
                vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, bound);
                // The list's header as a draw of as many vertices as it holds indices, from its first
                // (VkDrawIndirectCommand's four words are the indexed command's first four).
                vkCmdDrawIndirect(cb, object->frame.silhouette_lines.handle(), 0, 1, sizeof(VkDrawIndirectCommand));
            }
        }
        if (draws_object_space_lines(object->params)) {
            if (bound != line_pieces_pipeline_.get()) vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, line_pieces_pipeline_.get());
            bound = line_pieces_pipeline_.get();
            vkCmdDrawIndirect(cb, object->frame.line_pieces.handle(), 0, 1, sizeof(gpu::LinePiecesHeader));
        }
    }
}

StippleRenderer::LinePieces StippleRenderer::read_line_pieces(size_t object) const {
    const ObjectGpu& o = *objects_.at(object);
    LinePieces result;
    if (!draws_edge_lines(o) || !draws_object_space_lines(o.params)) return result;
    std::vector<std::byte> bytes = gpu::read_buffer(context_, o.frame.line_pieces);
    gpu::LinePiecesHeader header;
    std::memcpy(&header, bytes.data(), sizeof header);
    result.appended = header.vertex_count / 6;
    const size_t stored = std::min<size_t>(result.appended, o.frame.line_piece_capacity);
    result.pieces.resize(stored);
    if (stored > 0)  // memcpy to no storage is undefined even for 0 bytes
        std::memcpy(result.pieces.data(), bytes.data() + sizeof header, stored * sizeof(gpu::LinePiece));
    // Appended in whatever order the lanes finish: by edge, then along it, the same frame lists the same pieces in
    // the same order (what vector output chains them from).
    std::sort(result.pieces.begin(), result.pieces.end(), [](const gpu::LinePiece& a, const gpu::LinePiece& b) {
        return std::tie(a.edge, a.kind, a.ax, a.ay, a.bx, a.by) < std::tie(b.edge, b.kind, b.ax, b.ay, b.bx, b.by);
    });
    return result;
}

}  // namespace stipple
