#include "render/deform_pass.hpp"

#include <vector>

#include "core/error.hpp"
#include "gpu/context.hpp"
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

DeformPass::DeformPass(const gpu::Context& context, VkPipelineLayout layout) : context_(context), layout_(layout) {
    pipeline_ = gpu::create_compute_pipeline(context, "polygon_constants.comp", layout);
}

DeformPass::~DeformPass() {
    if (pipeline_) vkDestroyPipeline(context_.device, pipeline_, nullptr);
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
    // The deformed vertices before the polygons read them.
    gpu::memory_barrier(cb, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
    vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    const uint32_t group = gpu::kDensityWorkgroupSize;
    for (const auto& object : objects) {
        if (!object->animation || object->geometry.triangle_count == 0) continue;
        vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &object->set, 0, nullptr);
        vkCmdDispatch(cb, (object->geometry.triangle_count + group - 1) / group, 1, 1);
    }
    // Deformed vertices and polygons before everything that draws or densifies from them.
    gpu::memory_barrier(cb, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT | VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT |
                            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
}

}  // namespace stipple
