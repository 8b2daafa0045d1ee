// Animation evaluation against poses worked out by hand from each generated rig's stated constants
// (src/anim/procedural_rigs.hpp): skins, node TRS, morph weights, the three interpolations, times
// between keys, before the first key and after the loop point.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "anim/deform_cpu.hpp"
#include "core/error.hpp"
#include "anim/pose.hpp"
#include "anim/procedural_rigs.hpp"
#include "anim/sampling.hpp"
#include "support/anim_files.hpp"

namespace stipple::anim {
namespace {

using test::load_rig;

constexpr double kPi = 3.14159265358979323846;

void expect_near(const glm::dvec3& actual, const glm::dvec3& expected, double tolerance, const std::string& what) {
    EXPECT_LE(glm::length(actual - expected), tolerance)
        << what << ": got (" << actual.x << ", " << actual.y << ", " << actual.z << "), expected (" << expected.x << ", "
        << expected.y << ", " << expected.z << ")";
}

glm::dmat3 rotation_about(const glm::dvec3& axis, double degrees) {
    return glm::dmat3(glm::rotate(glm::dmat4(1.0), degrees * kPi / 180.0, axis));
}

// ---------------------------------------------------------------- skin: the bending cylinder

// The elbow's angle under "Bend" (LINEAR slerp from 0 to 90 degrees and back: the angle is linear).
double bend_angle(double t) { return 90.0 * (1.0 - std::abs(t - 1.0)); }

// Linear blend skinning written out: the root does not move; the elbow turns about z around (0, 1, 0).
glm::dvec3 bent(const glm::dvec3& p, double degrees) {
    const double w = rigs::cylinder_elbow_weight(static_cast<float>(p.y));
    const glm::dvec3 elbow(0.0, 1.0, 0.0);
    return (1.0 - w) * p + w * (rotation_about({0, 0, 1}, degrees) * (p - elbow) + elbow);
}

TEST(AnimEvaluation, BendingCylinderFollowsLinearBlendSkinning) {
    const AnimatedModel model = load_rig(rigs::bending_cylinder(), "anim_eval_cylinder", "cylinder");
    ASSERT_EQ(find_animation(model, "Bend"), 0);
    // 0.5 and 1.25 lie between keys, 1 on one; 2.5 and 3.75 are past the 2 s loop point (0.5 and 1.75).
    for (double t : {0.5, 1.0, 1.25, 2.5, 3.75}) {
        const double loop_t = std::fmod(t, 2.0);
        const DeformedGeometry g = deform_cpu(model, evaluate_pose(model, 0, t));
        size_t rigid_tip = 0;
        for (size_t v = 0; v < model.vertex_count(); ++v) {
            const glm::dvec3 p(model.bind_positions[v]);
            expect_near(glm::dvec3(g.positions[v]), bent(p, bend_angle(loop_t)), 1e-5,
                        "t " + std::to_string(t) + " vertex " + std::to_string(v));
            if (rigs::cylinder_elbow_weight(float(p.y)) == 1.0f) {  // moves rigidly with the elbow
                ++rigid_tip;
                expect_near(glm::dvec3(g.normals[v]), rotation_about({0, 0, 1}, bend_angle(loop_t)) * glm::dvec3(model.bind_normals[v]),
                            1e-5, "normal at t " + std::to_string(t));
            }
        }
        EXPECT_GT(rigid_tip, 20u);
    }
}

TEST(AnimEvaluation, SkinnedMeshIgnoresItsNodeTransform) {
    rigs::CylinderOptions options;
    options.mesh_node_translation = glm::vec3(5.0f, 0.0f, 0.0f);
    const AnimatedModel model = load_rig(rigs::bending_cylinder(options), "anim_eval_ignored", "cylinder");
    const DeformedGeometry g = deform_cpu(model, evaluate_pose(model, 0, 0.5));
    for (size_t v = 0; v < model.vertex_count(); ++v) {
        // Neither the rest mesh nor the pose shows the node's offset (glTF: only joints move a skin); the
        // static loader alone would have placed it there (AnimLoading.RestMeshIsTheRestPose).
        EXPECT_FLOAT_EQ(model.rest.positions[v].x, model.bind_positions[v].x);
        expect_near(glm::dvec3(g.positions[v]), bent(glm::dvec3(model.bind_positions[v]), 45.0), 1e-5, "vertex " + std::to_string(v));
    }
}

TEST(AnimEvaluation, AnimationsChosenByNameOrIndex) {
    const AnimatedModel model = load_rig(rigs::bending_cylinder(), "anim_eval_choose", "cylinder");
    EXPECT_EQ(find_animation(model, "Lift"), 1);
    EXPECT_EQ(find_animation(model, "1"), 1);
    EXPECT_EQ(find_animation(model, "0"), 0);
    // "Lift" moves the root (and with it the elbow) up by t over 0..1: the whole tube rises rigidly.
    const DeformedGeometry g = deform_cpu(model, evaluate_pose(model, find_animation(model, "Lift"), 0.25));
    for (size_t v = 0; v < model.vertex_count(); ++v)
        expect_near(glm::dvec3(g.positions[v]), glm::dvec3(model.bind_positions[v]) + glm::dvec3(0, 0.25, 0), 1e-6, "vertex");
    try {
        find_animation(model, "Jump");
        ADD_FAILURE() << "an unknown animation was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("no animation 'Jump' (its animations: 0 'Bend', 1 'Lift')"), std::string::npos) << e.what();
    }
}

// ---------------------------------------------------------------- node TRS: the box

glm::dmat4 box_world(double t) {  // t within 0..2
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, -3));
    m = glm::translate(m, glm::dvec3(t, 0, 0));
    m = glm::rotate(m, 90.0 * t * kPi / 180.0, glm::dvec3(0, 1, 0));
    return glm::scale(m, glm::dvec3(1, 1 + t, 1));
}

TEST(AnimEvaluation, NodeAnimatedBoxFollowsTranslationRotationScale) {
    const AnimatedModel model = load_rig(rigs::node_animated_box(), "anim_eval_box", "box");
    EXPECT_FLOAT_EQ(model.animations[0].duration, 2.0f);
    struct Case { double time; bool loop; double expected_t; };
    for (const Case c : {Case{0.5, true, 0.5}, Case{1.5, true, 1.5}, Case{2.0, false, 2.0}, Case{2.5, true, 0.5}, Case{7.0, false, 2.0}}) {
        const Pose pose = evaluate_pose(model, 0, c.time, c.loop);
        const glm::dmat4 world = box_world(c.expected_t);
        for (int col = 0; col < 4; ++col) expect_near(glm::dvec3(pose.world[1][col]), glm::dvec3(world[col]), 1e-6, "world column");
        const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(world)));
        const DeformedGeometry g = deform_cpu(model, pose);
        for (size_t v = 0; v < model.vertex_count(); ++v) {
            expect_near(glm::dvec3(g.positions[v]), glm::dvec3(world * glm::dvec4(glm::dvec3(model.bind_positions[v]), 1.0)), 1e-5,
                        "t " + std::to_string(c.time) + " vertex");
            expect_near(glm::dvec3(g.normals[v]), glm::normalize(normal_matrix * glm::dvec3(model.bind_normals[v])), 1e-5,
                        "t " + std::to_string(c.time) + " normal");
        }
    }
}

TEST(AnimEvaluation, RestPoseReproducesTheStaticMesh) {
    for (const auto& [name, builder] : {std::pair{"box", rigs::node_animated_box()}, std::pair{"cylinder", rigs::bending_cylinder()},
                                        std::pair{"plane", rigs::stretching_plane()}}) {
        const AnimatedModel model = load_rig(builder, std::string("anim_eval_rest_") + name, name);
        const DeformedGeometry g = deform_cpu(model, evaluate_pose(model, kRestPose, 0.0));
        for (size_t v = 0; v < model.vertex_count(); ++v) {
            expect_near(glm::dvec3(g.positions[v]), glm::dvec3(model.rest.positions[v]), 1e-6, std::string(name) + " position");
            expect_near(glm::dvec3(g.normals[v]), glm::dvec3(model.rest.normals[v]), 1e-5, std::string(name) + " normal");
        }
    }
}

// ---------------------------------------------------------------- morph targets: the quad

// Vertex `v` of the quad (file order 0..3) placed by weights (w0, w1) and the node's translation.
glm::dvec3 quad_vertex(int v, double w0, double w1) {
    const glm::dvec3 base[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    return base[v] + glm::dvec3(0, 0, v == 2 ? w0 : 0.0) + glm::dvec3(0, 0, 0.5 * w1) + glm::dvec3(1, 2, 3);
}

void expect_quad(const AnimatedModel& model, const Pose& pose, double w0, double w1, const std::string& what) {
    ASSERT_EQ(pose.morph_weights.size(), 2u);
    EXPECT_NEAR(pose.morph_weights[0], w0, 1e-6) << what;
    EXPECT_NEAR(pose.morph_weights[1], w1, 1e-6) << what;
    const DeformedGeometry g = deform_cpu(model, pose);
    for (size_t v = 0; v < model.vertex_count(); ++v) {
        const glm::vec3 b = model.bind_positions[v];  // identifies the file vertex whatever the draw order
        const int file_vertex = b.x == 0 ? (b.y == 0 ? 0 : 3) : (b.y == 0 ? 1 : 2);
        expect_near(glm::dvec3(g.positions[v]), quad_vertex(file_vertex, w0, w1), 1e-6, what + " vertex");
        expect_near(glm::dvec3(g.normals[v]), glm::normalize(glm::dvec3(0.5 * w0, 0, 1)), 1e-6, what + " normal");
    }
}

TEST(AnimEvaluation, MorphedQuadWeights) {
    const AnimatedModel model = load_rig(rigs::morphed_quad(), "anim_eval_quad", "quad");
    expect_quad(model, evaluate_pose(model, kRestPose, 0.0), 0.25, 0.0, "rest (the node's weights win)");
    expect_quad(model, evaluate_pose(model, 0, 0.5), 0.5, 0.25, "t 0.5");
    expect_quad(model, evaluate_pose(model, 0, 1.5), 0.5, 0.75, "t 1.5");
    expect_quad(model, evaluate_pose(model, 0, 2.5), 0.5, 0.25, "t 2.5 (looped)");
    expect_quad(model, evaluate_pose(model, 0, 2.5, false), 0.0, 1.0, "t 2.5 (held)");
}

TEST(AnimEvaluation, MeshWeightsWhenTheNodeHasNone) {
    GltfBuilder builder = rigs::morphed_quad();
    builder.doc["nodes"][0].erase("weights");
    const AnimatedModel model = load_rig(builder, "anim_eval_quad_mesh_weights", "quad");
    expect_quad(model, evaluate_pose(model, kRestPose, 0.0), 0.5, 0.5, "rest (the mesh's weights)");
}

// ---------------------------------------------------------------- the three interpolations

struct Expected {
    double time;
    glm::dvec3 translation;
    double y_degrees;  // rotation about +y
};

void expect_keys(const std::string& interpolation, const std::vector<Expected>& cases) {
    const AnimatedModel model = load_rig(rigs::interpolation_sample(interpolation), "anim_eval_" + interpolation, interpolation);
    ASSERT_FLOAT_EQ(model.animations[0].duration, 4.0f);
    for (const Expected& e : cases) {
        const Pose pose = evaluate_pose(model, 0, e.time);
        const glm::dmat4 expected = glm::translate(glm::dmat4(1.0), e.translation) *
                                    glm::dmat4(rotation_about({0, 1, 0}, e.y_degrees));
        const std::string what = interpolation + " at t " + std::to_string(e.time);
        for (int col = 0; col < 4; ++col) expect_near(glm::dvec3(pose.world[0][col]), glm::dvec3(expected[col]), 1e-6, what);
        const DeformedGeometry g = deform_cpu(model, pose);
        for (size_t v = 0; v < model.vertex_count(); ++v)
            expect_near(glm::dvec3(g.positions[v]), glm::dvec3(expected * glm::dvec4(glm::dvec3(model.bind_positions[v]), 1.0)), 1e-5,
                        what + " vertex");
    }
}

// Keys at t = 1, 2, 4: translations (0,0,0), (1,2,0), (3,0,-1); rotations 0, 90, 170 degrees about y
// (the last stored as -q). Before t = 1 the first key holds; t = 5.5 loops to 1.5.
TEST(AnimEvaluation, StepHoldsEachKey) {
    expect_keys("STEP", {{0.5, {0, 0, 0}, 0}, {1.5, {0, 0, 0}, 0}, {3.0, {1, 2, 0}, 90}, {3.999, {1, 2, 0}, 90},
                         {5.5, {0, 0, 0}, 0}});
}

// A STEP animation sampled at its own key rate shows key k at frame k: the file's key times are floats, and
// float(k / 24) lies above k / 24 for some k (1, 2, 4 and 8 of the first ten), where the key before was shown.
TEST(AnimEvaluation, StepShowsEachKeyAtItsOwnTime) {
    for (const int rate : {24, 25, 30, 60}) {
        Sampler sampler;
        sampler.interpolation = Interpolation::Step;
        sampler.components = 3;
        for (int k = 0; k < 100; ++k) {
            sampler.times.push_back(float(double(k) / rate));
            sampler.values.insert(sampler.values.end(), {float(k), 0.0f, 0.0f});
        }
        int wrong = 0;
        for (int k = 0; k < 100; ++k) {
            double out[3];
            sample(sampler, double(k) / rate, false, out);
            wrong += out[0] != double(k);
            sample(sampler, (double(k) + 0.5) / rate, false, out);  // half way: still key k
            wrong += out[0] != double(k);
        }
        EXPECT_EQ(wrong, 0) << rate << " keys a second";
    }
}

TEST(AnimEvaluation, LinearInterpolatesAndSlerpsTheShortArc) {
    // Half way from 90 to 170 degrees is 130 (the long way round, from 90 to -190, would give -50).
    expect_keys("LINEAR", {{0.5, {0, 0, 0}, 0}, {1.5, {0.5, 1, 0}, 45}, {3.0, {2, 1, -0.5}, 130}, {3.5, {2.5, 0.5, -0.75}, 150},
                           {5.5, {0.5, 1, 0}, 45}});
}

TEST(AnimEvaluation, CubicSplineUsesTangentsScaledByTheKeyInterval) {
    // p(s) = (2s^3-3s^2+1) v0 + (s^3-2s^2+s) dt b0 + (-2s^3+3s^2) v1 + (s^3-s^2) dt a1, at s = 1/2:
    // 0.5 v0 + 0.125 dt b0 + 0.5 v1 - 0.125 dt a1.
    //   t 1.5 (dt 1): 0.125 (1,0,0) + 0.5 (1,2,0) - 0.125 (0,1,0) = (0.625, 0.875, 0)
    //   t 3   (dt 2): 0.5 (1,2,0) + 0.25 (0,0,2) + 0.5 (3,0,-1) - 0.25 (1,1,1) = (1.75, 0.75, -0.25)
    // Rotations (zero tangents) blend the stored quaternions component by component, then normalise:
    // between 90 degrees and the stored -q(170) = q(-190) the half-way rotation is -50 degrees.
    expect_keys("CUBICSPLINE", {{0.5, {0, 0, 0}, 0}, {1.5, {0.625, 0.875, 0}, 45}, {3.0, {1.75, 0.75, -0.25}, -50},
                                {4.0, {0, 0, 0}, 0} /* 4 loops to 0 */, {5.5, {0.625, 0.875, 0}, 45}});
}

// ---------------------------------------------------------------- eight influences

TEST(AnimEvaluation, EightInfluencesPerVertex) {
    const AnimatedModel model = load_rig(rigs::eight_joint_sheet(), "anim_eval_eight", "eight");
    size_t with_eight = 0;
    for (const Influences& inf : model.influences) with_eight += inf.weight[7] > 0.0f;
    EXPECT_EQ(with_eight, model.vertex_count());
    for (double t : {0.3, 0.8}) {
        const DeformedGeometry g = deform_cpu(model, evaluate_pose(model, 0, t));
        for (size_t v = 0; v < model.vertex_count(); ++v) {
            const glm::dvec3 p(model.bind_positions[v]);
            double rise = 0.0;
            for (int k = 0; k < 8; ++k) rise += rigs::eight_joint_weight(float(p.x), k) * 0.1 * k * t;
            expect_near(glm::dvec3(g.positions[v]), p + glm::dvec3(0, rise, 0), 1e-6, "vertex");
        }
    }
}

}  // namespace
}  // namespace stipple::anim
