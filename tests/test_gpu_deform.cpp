// The deformation kernel (shaders/deform.comp) against the CPU reference: positions within 1e-5 of
// the model's size at several times (between keys, on keys, past the loop point) for every generated
// rig, the fox and the animated morph cube.
#include <gtest/gtest.h>

#include <cstring>

#include "anim/deform_cpu.hpp"
#include "anim/gpu_deform.hpp"
#include "anim/procedural_rigs.hpp"
#include "gpu/context.hpp"
#include "gpu/resources.hpp"
#include "support/anim_files.hpp"
#include "support/gpu_test.hpp"

namespace stipple::anim {
namespace {

std::vector<glm::vec3> read_vec3(const gpu::Context& context, const gpu::Buffer& buffer, size_t count) {
    const std::vector<std::byte> bytes = gpu::read_buffer(context, buffer);
    std::vector<glm::vec3> out(count);
    std::memcpy(out.data(), bytes.data(), count * sizeof(glm::vec3));
    return out;
}

class GpuDeform : public test::GpuTest {
protected:
    // Deforms on the GPU and reads back what the kernel wrote (to its own outputs or to `external`).
    DeformedGeometry run(GpuDeformer& deformer, const Pose& pose, const gpu::Buffer* external = nullptr) {
        VkCommandBuffer cb = context->begin_one_shot();
        deformer.record(cb, pose);
        gpu::memory_barrier(cb, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                            VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
        context->submit_and_wait(cb);
        DeformedGeometry g;
        const size_t n = deformer.vertex_count();
        g.positions = read_vec3(*context, external ? external[0] : deformer.positions(), n);
        g.normals = read_vec3(*context, external ? external[1] : deformer.normals(), n);
        return g;
    }

    // Every animation of `model` (and the rest pose) at `times`: GPU against CPU.
    void expect_matches(const AnimatedModel& model, const std::string& name, std::vector<double> times) {
        GpuDeformer deformer(*context, model);
        const Bounds bounds = compute_bounds(model.rest);
        const double size = glm::length(bounds.max - bounds.min);
        double worst_position = 0.0, worst_normal = 0.0;
        for (int animation = kRestPose; animation < static_cast<int>(model.animations.size()); ++animation) {
            for (double t : times) {
                const Pose pose = evaluate_pose(model, animation, t);
                const DeformedGeometry cpu = deform_cpu(model, pose);
                const DeformedGeometry gpu = run(deformer, pose);
                for (size_t v = 0; v < model.vertex_count(); ++v) {
                    worst_position = std::max(worst_position, double(glm::length(gpu.positions[v] - cpu.positions[v])));
                    worst_normal = std::max(worst_normal, double(glm::length(gpu.normals[v] - cpu.normals[v])));
                }
                if (animation == kRestPose) break;  // time does not matter
            }
        }
        std::printf("%s: %zu vertices, worst position error %.3g of the size %.3g (%.2g), worst normal error %.3g\n", name.c_str(),
                    model.vertex_count(), worst_position, size, worst_position / size, worst_normal);
        EXPECT_LE(worst_position, 1e-5 * size) << name;
        EXPECT_LE(worst_normal, 1e-5) << name;
    }
};

const std::vector<double> kTimes = {0.0, 0.37, 1.0, 1.5, 2.5, 3.7};

TEST_F(GpuDeform, GeneratedRigsMatchTheCpuReference) {
    rigs::CylinderOptions cubic;
    cubic.interpolation = "CUBICSPLINE";
    const std::pair<std::string, GltfBuilder> rigs_to_test[] = {
        {"cylinder", rigs::bending_cylinder()},
        {"cylinder_cubic", rigs::bending_cylinder(cubic)},
        {"box", rigs::node_animated_box()},
        {"quad", rigs::morphed_quad()},
        {"step", rigs::interpolation_sample("STEP")},
        {"linear", rigs::interpolation_sample("LINEAR")},
        {"cubic", rigs::interpolation_sample("CUBICSPLINE")},
        {"plane", rigs::stretching_plane()},
        {"eight", rigs::eight_joint_sheet()},
    };
    for (const auto& [name, builder] : rigs_to_test)
        expect_matches(test::load_rig(builder, "gpu_deform_" + name, name), name, kTimes);
}

TEST_F(GpuDeform, ReadsOnlyTheInfluencesTheModelUses) {
    // The kernel is specialised for the busiest vertex's number of used pairs, which pack first: a
    // wrong count or packing would leave influences out (and the comparisons above would fail).
    const AnimatedModel cylinder = test::load_rig(rigs::bending_cylinder(), "gpu_deform_used_cylinder", "cylinder");
    const AnimatedModel box = test::load_rig(rigs::node_animated_box(), "gpu_deform_used_box", "box");
    const AnimatedModel eight = test::load_rig(rigs::eight_joint_sheet(), "gpu_deform_used_eight", "eight");
    EXPECT_EQ(most_used_influences(cylinder), 2u);
    EXPECT_EQ(most_used_influences(box), 1u);
    EXPECT_EQ(most_used_influences(eight), 8u);
    for (const AnimatedModel* model : {&cylinder, &eight}) {
        const std::vector<gpu::DeformVertex> packed = pack_deform_vertices(*model);
        for (size_t v = 0; v < packed.size(); ++v) {
            const float w[8] = {packed[v].weights0.x, packed[v].weights0.y, packed[v].weights0.z, packed[v].weights0.w,
                                packed[v].weights1.x, packed[v].weights1.y, packed[v].weights1.z, packed[v].weights1.w};
            for (int i = 1; i < 8; ++i)
                if (w[i] != 0.0f) {
                    ASSERT_NE(w[i - 1], 0.0f) << "vertex " << v << ": a used pair after an unused one";
                }
        }
    }
}

TEST_F(GpuDeform, FoxMatchesTheCpuReference) {
    const std::string fox = test::shared_model("fox.glb");
    if (fox.empty()) GTEST_SKIP() << "../shared/models/fox.glb not present";
    expect_matches(load_animated_model(fox), "fox", {0.0, 0.1, 0.37, 0.71, 1.3, 2.9, 5.2});
}

TEST_F(GpuDeform, AnimatedMorphCubeMatchesTheCpuReference) {
    const std::string cube = test::shared_model("AnimatedMorphCube.gltf");
    if (cube.empty()) GTEST_SKIP() << "../shared/models/AnimatedMorphCube.gltf not present";
    expect_matches(load_animated_model(cube), "AnimatedMorphCube", {0.0, 0.37, 1.0, 2.05, 3.3, 4.5});
}

TEST_F(GpuDeform, WritesIntoOtherBuffers) {
    // The renderer hands its own positions buffer to the pass: the kernel must write there.
    const AnimatedModel model = test::load_rig(rigs::bending_cylinder(), "gpu_deform_external", "cylinder");
    GpuDeformer deformer(*context, model);
    const VkDeviceSize bytes = model.vertex_count() * sizeof(glm::vec3);
    const gpu::Buffer external[2] = {
        gpu::Buffer(*context, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryUse::DeviceLocal),
        gpu::Buffer(*context, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryUse::DeviceLocal)};
    deformer.set_outputs(external[0].handle(), external[1].handle());
    const Pose pose = evaluate_pose(model, 0, 0.6);
    const DeformedGeometry gpu = run(deformer, pose, external);
    const DeformedGeometry cpu = deform_cpu(model, pose);
    for (size_t v = 0; v < model.vertex_count(); ++v) EXPECT_LE(glm::length(gpu.positions[v] - cpu.positions[v]), 1e-5f);
    // A second pose overwrites the first (the palette is re-sent with each recording).
    const Pose later = evaluate_pose(model, 0, 1.0);
    const DeformedGeometry gpu_later = run(deformer, later, external);
    const DeformedGeometry cpu_later = deform_cpu(model, later);
    for (size_t v = 0; v < model.vertex_count(); ++v) EXPECT_LE(glm::length(gpu_later.positions[v] - cpu_later.positions[v]), 1e-5f);
}

}  // namespace
}  // namespace stipple::anim
