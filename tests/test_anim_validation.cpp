// Bad animation data: each kind gets one line naming the file and the glTF field, never a crash or a
// silently wrong pose.
#include <gtest/gtest.h>

#include "anim/procedural_rigs.hpp"
#include "core/error.hpp"
#include "stipple/object_data.hpp"
#include "support/anim_files.hpp"

namespace stipple::anim {
namespace {

using nlohmann::json;

void expect_error(const GltfBuilder& builder, const std::string& name, const std::string& phrase) {
    const std::string path = test::write_rig(builder, "anim_bad_" + name, name);
    try {
        load_animated_model(path);
        ADD_FAILURE() << name << ": loaded without an error";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << "does not start with the file: " << message;
        EXPECT_NE(message.find(phrase), std::string::npos) << "expected '" << phrase << "' in: " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
    }
}

// The cylinder's vertex count (its JOINTS_0 and WEIGHTS_0 have one element per vertex).
size_t vertex_count(const GltfBuilder& b) {
    return b.doc["accessors"][b.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"].get<int>()]["count"].get<size_t>();
}

TEST(AnimValidation, SamplerInputAndOutputCountsDisagree) {
    GltfBuilder box = rigs::node_animated_box();  // sampler 1: the rotation, 3 keys
    box.doc["animations"][0]["samplers"][1]["output"] = box.add_floats({0, 0, 0, 1, 0, 0, 0, 1}, "VEC4");
    expect_error(box, "counts", "animations[0].samplers[1]: input has 3 keys, output 2");

    rigs::CylinderOptions cubic;
    cubic.interpolation = "CUBICSPLINE";
    GltfBuilder cylinder = rigs::bending_cylinder(cubic);
    cylinder.doc["animations"][0]["samplers"][0]["output"] = cylinder.add_floats({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}, "VEC4");
    expect_error(cylinder, "cubic_counts", "animations[0].samplers[0]: input has 3 keys, output 3 (expected 9: 3 for CUBICSPLINE per key)");

    GltfBuilder quad = rigs::morphed_quad();
    quad.doc["animations"][0]["samplers"][0]["output"] = quad.add_floats({0, 0, 1, 0.5f, 0}, "SCALAR");
    expect_error(quad, "weight_counts", "animations[0].samplers[0]: input has 3 keys, output 5 (expected 6: 2 morph weights per key)");
}

TEST(AnimValidation, DecreasingKeyTimes) {
    GltfBuilder box = rigs::node_animated_box();
    box.doc["animations"][0]["samplers"][1]["input"] = box.add_floats({0, 2, 1}, "SCALAR");
    expect_error(box, "times", "animations[0].samplers[1].input: key 2 (time 1) comes before key 1 (time 2); times must increase");
}

// glTF's key times strictly increase from 0 or later: a repeated time passed, and times all below 0 gave
// the animation a negative duration, standing still at its last key.
TEST(AnimValidation, RepeatedAndNegativeKeyTimes) {
    GltfBuilder repeated = rigs::node_animated_box();
    repeated.doc["animations"][0]["samplers"][1]["input"] = repeated.add_floats({0, 1, 1}, "SCALAR");
    expect_error(repeated, "repeated_times",
                 "animations[0].samplers[1].input: key 2 (time 1) is at the time of key 1 (time 1); times must increase");

    GltfBuilder negative = rigs::node_animated_box();
    const int accessor = negative.add_floats({-5, -3, -1}, "SCALAR");
    negative.doc["animations"][0]["samplers"][1]["input"] = accessor;
    expect_error(negative, "negative_times",
                 "animations[0].samplers[1].input: key 0 of accessor " + std::to_string(accessor) +
                     " is at time -5; glTF's key times start at 0 or later");
}

TEST(AnimValidation, JointIndexBeyondTheSkin) {
    GltfBuilder cylinder = rigs::bending_cylinder();
    std::vector<uint16_t> joints;
    for (size_t v = 0; v < vertex_count(cylinder); ++v) joints.insert(joints.end(), {uint16_t(v == 5 ? 2 : 0), 1, 0, 0});
    cylinder.doc["meshes"][0]["primitives"][0]["attributes"]["JOINTS_0"] = cylinder.add_uint16(joints, "VEC4");
    // Vertex 5 is in the bottom ring: its whole weight is on its first joint, now joint 2 of 2.
    expect_error(cylinder, "joint", "meshes[0].primitives[0].attributes.JOINTS_0: vertex 5 refers to joint 2, but skins[0] has 2 joints");
}

TEST(AnimValidation, WeightsThatSumToZero) {
    GltfBuilder cylinder = rigs::bending_cylinder();
    std::vector<float> weights;
    for (size_t v = 0; v < vertex_count(cylinder); ++v) weights.insert(weights.end(), {v == 3 ? 0.0f : 1.0f, 0, 0, 0});
    cylinder.doc["meshes"][0]["primitives"][0]["attributes"]["WEIGHTS_0"] = cylinder.add_floats(weights, "VEC4");
    expect_error(cylinder, "weights", "meshes[0].primitives[0].attributes.WEIGHTS_0: vertex 3's weights sum to zero");
}

TEST(AnimValidation, AccessorsOfTheWrongTypeForTheirUse) {
    GltfBuilder rotation = rigs::node_animated_box();
    const int vec3 = rotation.add_floats({0, 0, 0, 0, 1, 0, 0, 0, 1}, "VEC3");
    rotation.doc["animations"][0]["samplers"][1]["output"] = vec3;
    expect_error(rotation, "rotation_type",
                 "animations[0].samplers[1].output: accessor " + std::to_string(vec3) +
                     " is VEC3 of FLOAT, expected VEC4 of FLOAT or normalized BYTE, UNSIGNED_BYTE, SHORT, UNSIGNED_SHORT");

    GltfBuilder joints = rigs::bending_cylinder();
    const int floats = joints.add_floats(std::vector<float>(4 * vertex_count(joints), 0.0f), "VEC4");
    joints.doc["meshes"][0]["primitives"][0]["attributes"]["JOINTS_0"] = floats;
    expect_error(joints, "joints_type",
                 "meshes[0].primitives[0].attributes.JOINTS_0: accessor " + std::to_string(floats) +
                     " is VEC4 of FLOAT, expected VEC4 of UNSIGNED_BYTE, UNSIGNED_SHORT");

    GltfBuilder times = rigs::node_animated_box();
    const int shorts = times.add_uint16({0, 2}, "SCALAR");
    times.doc["animations"][0]["samplers"][0]["input"] = shorts;
    expect_error(times, "input_type",
                 "animations[0].samplers[0].input: accessor " + std::to_string(shorts) + " is SCALAR of UNSIGNED_SHORT, expected SCALAR of FLOAT");

    GltfBuilder bind = rigs::bending_cylinder();
    const int vec4 = bind.add_floats(std::vector<float>(8, 0.0f), "VEC4");
    bind.doc["skins"][0]["inverseBindMatrices"] = vec4;
    expect_error(bind, "bind_type", "skins[0].inverseBindMatrices: accessor " + std::to_string(vec4) + " is VEC4 of FLOAT, expected MAT4 of FLOAT");
}

TEST(AnimValidation, ChannelsThatCannotApply) {
    GltfBuilder no_targets = rigs::node_animated_box();
    no_targets.doc["animations"][0]["channels"].push_back({{"sampler", 0}, {"target", {{"node", 1}, {"path", "weights"}}}});
    expect_error(no_targets, "no_targets", "animations[0].channels[3]: node 1 has no morph targets to weight");

    GltfBuilder matrix = rigs::node_animated_box();
    matrix.doc["nodes"][1]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    expect_error(matrix, "matrix", "animations[0].channels[0]: node 1 has a matrix, which glTF does not allow to animate");

    GltfBuilder sampler = rigs::node_animated_box();
    sampler.doc["animations"][0]["channels"][2]["sampler"] = 5;
    expect_error(sampler, "sampler", "animations[0].channels[2].sampler: sampler 5 does not exist");

    // A rotation key of no length was drawn as no turn (a node's own such rotation was refused already).
    GltfBuilder zero_key = rigs::node_animated_box();
    zero_key.doc["animations"][0]["samplers"][1]["output"] = zero_key.add_floats({0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 1}, "VEC4");
    expect_error(zero_key, "zero_key", "animations[0].samplers[1].output: key 1 is (0, 0, 0, 0), not a rotation quaternion");

    GltfBuilder interpolation = rigs::node_animated_box();
    interpolation.doc["animations"][0]["samplers"][0]["interpolation"] = "BEZIER";
    expect_error(interpolation, "interpolation", "animations[0].samplers[0].interpolation: expected one of LINEAR, STEP, CUBICSPLINE, got 'BEZIER'");
}

TEST(AnimValidation, SkinsAndMorphWeightsThatDoNotFit) {
    GltfBuilder joints = rigs::bending_cylinder();
    joints.doc["skins"][0]["joints"] = {1, 99};
    expect_error(joints, "skin_joint", "skins[0].joints[1]: node 99 does not exist");

    // Both were drawn without a word (glTF forbids them: which bind matrix, which channel would win?).
    GltfBuilder twice = rigs::bending_cylinder();
    twice.doc["skins"][0]["joints"] = {1, 1};
    expect_error(twice, "skin_twice", "skins[0].joints[1]: node 1 is listed twice (glTF: a skin's joints are unique)");
    GltfBuilder driven = rigs::node_animated_box();
    driven.doc["animations"][0]["channels"].push_back(driven.doc["animations"][0]["channels"][0]);
    expect_error(driven, "driven_twice", "animations[0].channels[3].target: node 1's translation is driven by an earlier channel");

    GltfBuilder matrices = rigs::bending_cylinder();
    std::vector<float> one(16, 0.0f);
    one[0] = one[5] = one[10] = one[15] = 1.0f;
    matrices.doc["skins"][0]["inverseBindMatrices"] = matrices.add_floats(one, "MAT4");
    expect_error(matrices, "bind_count", "skins[0].inverseBindMatrices: 1 matrices for 2 joints");

    // A fourth row other than (0, 0, 0, 1), as all-zero matrices have: the skinned object vanished silently.
    GltfBuilder zeros = rigs::bending_cylinder();
    std::vector<float> two = one;
    two.insert(two.end(), 16, 0.0f);
    zeros.doc["skins"][0]["inverseBindMatrices"] = zeros.add_floats(two, "MAT4");
    expect_error(zeros, "bind_row", "skins[0].inverseBindMatrices: matrix 1's fourth row is (0, 0, 0, 0); glTF requires (0, 0, 0, 1)");

    // A singular matrix with the right fourth row (its y row all zeros): every vertex the joint moves went to one
    // plane, and the skinned object vanished silently.
    GltfBuilder singular = rigs::bending_cylinder();
    std::vector<float> flat = one;
    flat.insert(flat.end(), one.begin(), one.end());
    flat[16 + 5] = 0.0f;
    singular.doc["skins"][0]["inverseBindMatrices"] = singular.add_floats(flat, "MAT4");
    expect_error(singular, "bind_singular", "skins[0].inverseBindMatrices: matrix 1 is singular (its 3x3 part has determinant 0)");

    GltfBuilder weights = rigs::morphed_quad();
    weights.doc["nodes"][0]["weights"] = {0.25};
    expect_error(weights, "morph_weights", "nodes[0].weights: 1 weights for 2 morph targets");
}

// Keys far beyond any real model (3e38) moved the object to infinity and drew a blank frame with exit
// status 0. A key beyond +-1e18 is refused where it stands; keys in range that compose to a pose beyond it
// (a parent scaled 1e10 carrying a child translated 1e9) are refused when the drawing samples the poses.
TEST(AnimValidation, KeysAndPosesBeyondTheCoordinateRange) {
    GltfBuilder box = rigs::node_animated_box();  // sampler 0: the box's translation, keys (0,0,0), (2,0,0)
    box.doc["animations"][0]["samplers"][0]["output"] = box.add_floats({0, 0, 0, 3e38f, 0, 0}, "VEC3");
    expect_error(box, "huge_translation", "animations[0].samplers[0].output: element 1 holds 3e+38, beyond the +-1e+18");

    GltfBuilder quad = rigs::morphed_quad();  // sampler 0: two weights a key, three keys
    quad.doc["animations"][0]["samplers"][0]["output"] = quad.add_floats({0, 0, 1, 0, -2e18f, 1}, "SCALAR");
    expect_error(quad, "huge_weight", "animations[0].samplers[0].output: element 4 holds -2e+18");

    GltfBuilder composed = rigs::node_animated_box();
    composed.doc["nodes"][0]["scale"] = {1e10, 1e10, 1e10};
    composed.doc["animations"][0]["samplers"][0]["output"] = composed.add_floats({0, 0, 0, 1e9f, 0, 0}, "VEC3");
    const std::string path = test::write_rig(composed, "anim_bad_composed", "composed");
    EXPECT_NO_THROW(load_animated_model(path)) << "every key is in range";
    try {
        load_model_data(path);
        ADD_FAILURE() << "a pose 1e19 away was drawn";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), path + ": animation 0 'Move' moves the model beyond the +-1e+18 a coordinate may reach");
    }
    composed.doc["animations"][0]["samplers"][0]["output"] = composed.add_floats({0, 0, 0, 1e7f, 0, 0}, "VEC3");
    EXPECT_TRUE(load_model_data(test::write_rig(composed, "anim_bad_composed", "in_range")).motion) << "1e17 away is drawn";
}

// What glTF allows is not an error: one sampler driving a translation and a scale (both three floats a
// key), and weights animated on a node outside the drawn scene (they move nothing drawn). A sampler
// driving properties whose values differ in kind stays one.
TEST(AnimValidation, SharedSamplersAndNodesOutsideTheScene) {
    GltfBuilder box = rigs::node_animated_box();  // channels: translation (sampler 0), rotation (1), scale (2)
    box.doc["animations"][0]["channels"][2]["sampler"] = 0;
    const AnimatedModel shared = test::load_rig(box, "anim_shared_sampler", "box");
    ASSERT_EQ(shared.animations[0].channels.size(), 3u);
    EXPECT_EQ(shared.animations[0].channels[2].sampler, 0u);
    EXPECT_EQ(shared.animations[0].channels[2].path, ChannelPath::Scale);

    GltfBuilder mixed = rigs::node_animated_box();
    mixed.doc["animations"][0]["channels"][1]["sampler"] = 0;
    expect_error(mixed, "mixed_sampler",
                 "animations[0].channels[1]: sampler 0 also drives a property whose values it cannot hold (translations or "
                 "scales and rotations)");

    GltfBuilder quad = rigs::morphed_quad();
    const int hidden = quad.add("nodes", {{"name", "hidden"}, {"mesh", 0}});  // in no scene
    quad.doc["animations"][0]["channels"].push_back({{"sampler", 0}, {"target", {{"node", hidden}, {"path", "weights"}}}});
    const AnimatedModel outside = test::load_rig(quad, "anim_weights_outside", "quad");
    EXPECT_EQ(outside.animations[0].channels.size(), 1u) << "the hidden node's channel drives nothing drawn";

    GltfBuilder plain = rigs::node_animated_box();
    plain.doc["animations"][0]["channels"][0]["target"]["path"] = "weights";
    expect_error(plain, "weights_no_targets", "animations[0].channels[0]: node 1 has no morph targets to weight");
}

}  // namespace
}  // namespace stipple::anim
