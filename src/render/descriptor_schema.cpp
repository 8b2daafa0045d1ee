#include "render/descriptor_schema.hpp"

#include <vector>

#include "gpu/context.hpp"
#include "render/object_gpu.hpp"

namespace stipple {

namespace {

constexpr VkDescriptorType kUniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
constexpr VkDescriptorType kTexels = VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
constexpr VkShaderStageFlags kAllStages =
    VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT;

using O = ObjectGpu;
const ObjectBinding kObjectBindings[] = {
    {{gpu::kBindingFrame, kUniform}, [](const O& o) { return o.frame_uniforms; }},
    {{gpu::kBindingObject, kUniform}, [](const O& o) { return o.frame.object_uniforms.handle(); }},
    {{gpu::kBindingTriangleDraw, kStorage}, [](const O& o) { return o.frame.triangle_draw.handle(); }},
    {{gpu::kBindingTriangleInfo, kStorage}, [](const O& o) { return o.polygons.gpu.handle(); }},
    {{gpu::kBindingDrawnStipples, kStorage}, [](const O& o) { return o.frame.drawn_stipples.handle(); }},
    {{gpu::kBindingDebug, kStorage}, [](const O& o) { return o.frame.debug.handle(); }},
    {{gpu::kBindingDrawnPolygons, kStorage}, [](const O& o) { return o.frame.drawn_polygons.handle(); }},
    {{gpu::kBindingSplatRing, kStorage}, [](const O& o) { return o.frame.splat_ring.handle(); }},
    {{gpu::kBindingMeshPositions, kTexels}, [](const O& o) { return o.geometry.positions.handle(); },
     [](const O& o) { return o.geometry.position_texels; }},
    {{gpu::kBindingMeshIndices, kTexels}, [](const O& o) { return o.geometry.indices.handle(); },
     [](const O& o) { return o.geometry.index_texels; }},
    {{gpu::kBindingSilhouetteEdges, kTexels}, [](const O& o) { return o.geometry.silhouette_edges.handle(); },
     [](const O& o) { return o.geometry.silhouette_edge_texels; }},
    {{gpu::kBindingSilhouetteLines, kStorage}, [](const O& o) { return o.frame.silhouette_lines.handle(); }},
    {{gpu::kBindingVisibleStipples, kStorage}, [](const O& o) { return o.frame.visible_stipples.handle(); }},
    {{gpu::kBindingFacing, kStorage}, [](const O& o) { return o.frame.facing.handle(); }},
    {{gpu::kBindingLinePieces, kStorage}, [](const O& o) { return o.frame.line_pieces.handle(); }},
    {{gpu::kBindingLineCandidates, kStorage}, [](const O& o) { return o.frame.line_candidates.handle(); }},
    {{gpu::kBindingFullAreas, kStorage}, [](const O& o) { return o.polygons.full_areas.handle(); }},
    {{gpu::kBindingTriangleDrawTexels, kTexels}, [](const O& o) { return o.frame.triangle_draw.handle(); },
     [](const O& o) { return o.frame.triangle_draw_texels; }},
    {{gpu::kBindingDepthTriangles, kStorage}, [](const O& o) { return o.frame.depth_triangles.handle(); }},
    {{gpu::kBindingGradientPolygons, kStorage}, [](const O& o) { return o.frame.gradient_polygons.handle(); }},
    {{gpu::kBindingTriangleInfoTexels, kTexels}, [](const O& o) { return o.polygons.gpu.handle(); },
     [](const O& o) { return o.polygons.texels; }},
    {{gpu::kBindingStippleTexels, kTexels}, [](const O& o) { return o.geometry.stipples.handle(); },
     [](const O& o) { return o.geometry.stipple_texels; }},
};

const gpu::DescriptorBinding kSplatFrameBindings[] = {
    {gpu::kBindingSplatBackground, kStorage},
    {gpu::kBindingSceneDepth, kStorage},
    {gpu::kBindingColorBuffer, kStorage},
    {gpu::kBindingSplatCover, kStorage},
    {gpu::kBindingSceneDepthTexels, kTexels},
};

std::vector<gpu::DescriptorBinding> object_descriptor_bindings() {
    std::vector<gpu::DescriptorBinding> bindings;
    for (const ObjectBinding& b : kObjectBindings) bindings.push_back(b.binding);
    return bindings;
}

}  // namespace

std::span<const ObjectBinding> object_bindings() { return kObjectBindings; }
std::span<const gpu::DescriptorBinding> splat_frame_bindings() { return kSplatFrameBindings; }

RenderLayouts create_render_layouts(const gpu::Context& context) {
    RenderLayouts layouts;
    layouts.object_set = gpu::create_set_layout(context, object_descriptor_bindings(), kAllStages);
    // Also the fragment stage: the Raskar-Cohen lines test the depth words when the depth pass ran as
    // compute (shaders/silhouette_words.frag); and the vertex stage: the points' outline shift (stipple.vert).
    layouts.splat_frame_set = gpu::create_set_layout(
        context, kSplatFrameBindings, VK_SHADER_STAGE_COMPUTE_BIT | VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_VERTEX_BIT);
    layouts.pipeline = gpu::create_pipeline_layout(context, std::span(&layouts.object_set, 1), kPushConstantBytes);
    const VkDescriptorSetLayout splat_sets[] = {layouts.object_set, layouts.splat_frame_set};
    layouts.splat_pipeline = gpu::create_pipeline_layout(context, splat_sets, kPushConstantBytes);
    return layouts;
}

void destroy_render_layouts(const gpu::Context& context, RenderLayouts& layouts) {
    for (VkPipelineLayout layout : {layouts.pipeline, layouts.splat_pipeline})
        if (layout) vkDestroyPipelineLayout(context.device, layout, nullptr);
    for (VkDescriptorSetLayout layout : {layouts.object_set, layouts.splat_frame_set})
        if (layout) vkDestroyDescriptorSetLayout(context.device, layout, nullptr);
    layouts = {};
}

void create_object_descriptors(const gpu::Context& context, VkDescriptorSetLayout layout, ObjectGpu& object) {
    object.pool = gpu::create_pool(context, object_descriptor_bindings(), 1);
    object.set = gpu::allocate_set(context, object.pool, layout);
    write_object_descriptors(object);
}

void write_object_descriptors(const ObjectGpu& object) {
    std::vector<VkBuffer> buffers;
    std::vector<VkBufferView> views;
    for (const ObjectBinding& b : kObjectBindings) {
        buffers.push_back(b.buffer(object));
        views.push_back(b.view ? b.view(object) : VK_NULL_HANDLE);
    }
    gpu::write_buffer_set(object.context->device, object.set, object_descriptor_bindings(), buffers, views);
}

}  // namespace stipple
