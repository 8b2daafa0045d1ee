#include "render/deform_pass.hpp"

#include <vector>

#include "anim/deform_layout.hpp"
#include "core/error.hpp"
#include "gpu/context.hpp"
#include "gpu/descriptors.hpp"
#include "gpu/pipelines.hpp"
#include "render/object_gpu.hpp"

namespace stipple {

std::vector<float> animated_full_areas(const Mesh& mesh, const anim::Motion& motion) {
    STIPPLE_CHECK(motion.model && motion.headroom, "an animated object needs its model and its headroom");
    const anim::StretchHeadroom& headroom = *motion.headroom;
    STIPPLE_CHECK(motion.model->vertex_count() == mesh.vertex_count() && headroom.per_triangle.size() == mesh.triangle_count(),
                  "the animation is not of this mesh");
    std::vector<float> full_areas(mesh.triangle_count());
    for (size_t t = 0; t < full_areas.size(); ++t)
        full_areas[t] = float(triangle_area(mesh, t) * double(headroom.per_triangle[t]));
    return full_areas;
}

std::unique_ptr<ObjectAnimation> create_object_animation(const gpu::Context& context, ObjectGpu& object,
                                                         const anim::Motion& motion, std::span<const float> full_areas) {
    STIPPLE_CHECK(motion.model && motion.headroom && full_areas.size() == object.geometry.triangle_count,
                  "an animated object needs its model, its headroom and a full area per polygon");
    const anim::AnimatedModel& model = *motion.model;
    auto animation = std::make_unique<ObjectAnimation>();
    animation->motion = motion;
    object.polygons.full_areas = gpu::create_device_buffer(context, full_areas, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);

    animation->deformer = std::make_unique<anim::GpuDeformer>(context, model);
    animation->deformer->set_outputs(object.geometry.positions.handle(), object.geometry.normals.handle());
    anim::evaluate_pose(model, animation->animation, animation->seconds, animation->loop, animation->pose);
    return animation;
}

void check_animated_path(const ObjectGpu& object) {
    if (!object.animation || !density_on_cpu(object.params.density_path)) return;
    fail_file(object.animation->motion.model->source,
              std::string("the ") + density_path_name(object.params.density_path) +
                  " density path cannot draw an animated model (it computes densities on the CPU from the rest "
                  "pose): use vertex, indirect or splat");
}

PolygonBinding::~PolygonBinding() {
    if (pool) vkDestroyDescriptorPool(device, pool, nullptr);
}

namespace {

// The polygon pass's set: the deformed mesh as texels, and the polygons it writes.
constexpr gpu::DescriptorBinding kPolygonBindings[3] = {
    {gpu::kBindingPolygonPositions, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER},
    {gpu::kBindingPolygonIndices, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER},
    {gpu::kBindingPolygonInfos, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
};
static_assert(gpu::kBindingPolygonPositions == 0 && gpu::kBindingPolygonIndices == 1 && gpu::kBindingPolygonInfos == 2);

}  // namespace

DeformPass::DeformPass(const gpu::Context& context, bool vec3_texels) : context_(context), vec3_texels_(vec3_texels) {
    try {
        set_layout_ = gpu::create_set_layout(context, kPolygonBindings, VK_SHADER_STAGE_COMPUTE_BIT);
        layout_ = gpu::create_pipeline_layout(context, {&set_layout_, 1}, sizeof(gpu::PolygonConstantsPush));
        gpu::Specialization texels;
        texels.constants.push_back({gpu::kSpecPolygonVec3Texels, vec3_texels_ ? 1u : 0u});
        pipeline_.define_compute(context, "polygon_constants.comp", layout_, texels);
    } catch (...) {
        release();
        throw;
    }
}

DeformPass::~DeformPass() { release(); }

void DeformPass::release() {
    pipeline_.reset();
    if (layout_) vkDestroyPipelineLayout(context_.device, layout_, nullptr);
    if (set_layout_) vkDestroyDescriptorSetLayout(context_.device, set_layout_, nullptr);
}

void DeformPass::bind(ObjectGpu& object) const {
    auto binding = std::make_unique<PolygonBinding>();
    binding->device = context_.device;
    binding->pool = gpu::create_pool(context_, kPolygonBindings, 1);
    binding->set = gpu::allocate_set(context_, binding->pool, set_layout_);
    // The object's own texel views of its mesh (the stipple shaders read them too).
    const VkBuffer buffers[] = {object.geometry.positions.handle(), object.geometry.indices.handle(),
                                object.polygons.gpu.handle()};
    const VkBufferView views[] = {object.geometry.position_texels, object.geometry.index_texels, VK_NULL_HANDLE};
    gpu::write_buffer_set(context_.device, binding->set, kPolygonBindings, buffers, views);
    object.animation->polygons = std::move(binding);
}

void DeformPass::evaluate(std::span<const std::unique_ptr<ObjectGpu>> objects) {
    for (const auto& object : objects) {
        ObjectAnimation* a = object->animation.get();
        if (a) anim::evaluate_pose(*a->motion.model, a->animation, a->seconds, a->loop, a->pose);
    }
}

bool DeformPass::record_skinning(VkCommandBuffer cb, std::span<const std::unique_ptr<ObjectGpu>> objects) const {
    bool any = false;
    for (const auto& object : objects) {
        if (!object->animation || object->geometry.triangle_count == 0) continue;
        any = true;
        // The deformer orders itself after last frame's readers of the mesh (and, with one global
        // barrier, of the polygons record_polygons rewrites).
        object->animation->deformer->record(cb, object->animation->pose);
    }
    return any;
}

void DeformPass::record_polygons(VkCommandBuffer cb, std::span<const std::unique_ptr<ObjectGpu>> objects) const {
    // The deformed vertices before the polygons read them (as texels: a sampled read).
    gpu::memory_barrier(cb, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_READ_BIT);
    vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.get());
    const uint32_t group = gpu::kDensityWorkgroupSize;
    for (const auto& object : objects) {
        if (!object->animation || object->geometry.triangle_count == 0) continue;
        if (!object->animation->polygons) bind(*object);
        vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &object->animation->polygons->set, 0,
                                nullptr);
        gpu::PolygonConstantsPush push{};
        push.box_min = glm::vec4(object->polygons.box_min, 0.0f);
        push.box_size = glm::vec4(object->polygons.box_size, 0.0f);
        push.triangle_count = object->geometry.triangle_count;
        vkCmdPushConstants(cb, layout_, gpu::kPushConstantStages, 0, sizeof push, &push);
        gpu::dispatch_items(cb, context_, object->geometry.triangle_count, group);
    }
    // Deformed vertices and polygons before everything that draws or densifies from them.
    gpu::memory_barrier(cb, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT | VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT |
                            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT |
                            VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
}

}  // namespace stipple
