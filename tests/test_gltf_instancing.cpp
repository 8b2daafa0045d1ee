// EXT_mesh_gpu_instancing: a node drawing its mesh once per instance (node world x TRANSLATION x ROTATION x
// SCALE), in the static loader and the animated one alike, with the attributes' quantized forms and
// the broken files named in one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "anim/animated_model.hpp"
#include "anim/deform_cpu.hpp"
#include "anim/gltf_builder.hpp"
#include "anim/pose.hpp"
#include "anim/procedural_rigs.hpp"
#include "core/error.hpp"
#include "mesh/load_mesh.hpp"
#include "support/run_command.hpp"

namespace stipple {
namespace {

using json = nlohmann::json;

// The three instances every test places: (translation, rotation about +z in degrees, uniform scale).
struct Instance {
    glm::dvec3 translation;
    double degrees;
    double scale;
};
const std::array<Instance, 3> kInstances = {{{{0, 0, 0}, 0, 1}, {{5, 0, 0}, 90, 1}, {{0, 5, 0}, 0, 2}}};
const glm::dvec3 kNodeTranslation(0, 0, -3);
const glm::dvec3 kTriangle[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

glm::dmat4 instance_matrix(const Instance& i) {
    return glm::translate(glm::dmat4(1.0), i.translation) * glm::rotate(glm::dmat4(1.0), glm::radians(i.degrees), {0, 0, 1}) *
           glm::scale(glm::dmat4(1.0), glm::dvec3(i.scale));
}

glm::quat instance_rotation(const Instance& i) { return glm::angleAxis(float(glm::radians(i.degrees)), glm::vec3(0, 0, 1)); }

// One triangle in node 0 (translated by kNodeTranslation), instanced three times. `quantized`: the
// translations as plain unsigned bytes and the rotations as normalized shorts (KHR_mesh_quantization).
anim::GltfBuilder instanced_triangle(bool quantized) {
    anim::GltfBuilder b;
    std::vector<float> positions;
    for (const glm::dvec3& p : kTriangle) positions.insert(positions.end(), {float(p.x), float(p.y), float(p.z)});
    const int position = b.add_floats(positions, "VEC3");
    b.add("meshes", {{"primitives", json::array({{{"attributes", {{"POSITION", position}}}}})}});
    json attributes;
    std::vector<float> scales;
    for (const Instance& i : kInstances) scales.insert(scales.end(), {float(i.scale), float(i.scale), float(i.scale)});
    attributes["SCALE"] = b.add_floats(scales, "VEC3");
    if (quantized) {
        std::vector<uint8_t> t;
        std::vector<int16_t> r;
        for (const Instance& i : kInstances) {
            t.insert(t.end(), {uint8_t(i.translation.x), uint8_t(i.translation.y), uint8_t(i.translation.z)});
            const glm::quat q = instance_rotation(i);
            for (float c : {q.x, q.y, q.z, q.w}) r.push_back(int16_t(std::lround(c * 32767.0f)));
        }
        attributes["TRANSLATION"] = b.add_uint8(t, "VEC3");
        attributes["ROTATION"] = b.add_int16(r, "VEC4", true);
        b.doc["extensionsUsed"] = {"EXT_mesh_gpu_instancing", "KHR_mesh_quantization"};
        b.doc["extensionsRequired"] = {"EXT_mesh_gpu_instancing", "KHR_mesh_quantization"};
    } else {
        std::vector<float> t, r;
        for (const Instance& i : kInstances) {
            t.insert(t.end(), {float(i.translation.x), float(i.translation.y), float(i.translation.z)});
            const glm::quat q = instance_rotation(i);
            r.insert(r.end(), {q.x, q.y, q.z, q.w});
        }
        attributes["TRANSLATION"] = b.add_floats(t, "VEC3");
        attributes["ROTATION"] = b.add_floats(r, "VEC4");
        b.doc["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
    }
    b.add("nodes", {{"mesh", 0},
                    {"translation", {kNodeTranslation.x, kNodeTranslation.y, kNodeTranslation.z}},
                    {"extensions", {{"EXT_mesh_gpu_instancing", {{"attributes", attributes}}}}}});
    b.add("scenes", {{"nodes", {0}}});
    return b;
}

// Node 0's translation animated from kNodeTranslation to kNodeTranslation + (0, 0, 2) over one second.
void add_slide(anim::GltfBuilder& b) {
    const int times = b.add_floats({0, 1}, "SCALAR");
    const int values = b.add_floats({0, 0, -3, 0, 0, -1}, "VEC3");
    b.add("animations", {{"name", "Slide"},
                         {"samplers", json::array({{{"input", times}, {"output", values}, {"interpolation", "LINEAR"}}})},
                         {"channels", json::array({{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}})}});
}

// Triangle k of the mesh is instance k, its corners where node x instance puts the file's (in either
// winding: loading may turn a part's faces).
void expect_instances_placed(const Mesh& mesh, double tolerance) {
    ASSERT_EQ(mesh.triangle_count(), kInstances.size());
    for (size_t k = 0; k < kInstances.size(); ++k) {
        const glm::dmat4 m = glm::translate(glm::dmat4(1.0), kNodeTranslation) * instance_matrix(kInstances[k]);
        for (const glm::dvec3& corner : kTriangle) {
            const glm::dvec3 expected(m * glm::dvec4(corner, 1.0));
            double nearest = 1e30;
            for (int c = 0; c < 3; ++c)
                nearest = std::min(nearest, glm::length(glm::dvec3(mesh.positions[mesh.indices[3 * k + c]]) - expected));
            EXPECT_LT(nearest, tolerance) << "instance " << k;
        }
    }
}

TEST(GltfInstancing, EveryInstanceIsDrawnWhereItsTransformPutsIt) {
    const Mesh plain = load_mesh_from_bytes("instanced.glb", instanced_triangle(false).glb());
    expect_instances_placed(plain, 1e-5);
    EXPECT_EQ(plain.decoded, "EXT_mesh_gpu_instancing (3 instances of 1 node)");  // `stipple info` says so
    // Quantized: bytes for the translations, normalized shorts for the rotations (1/32767 a component).
    const Mesh quantized = load_mesh_from_bytes("quantized.glb", instanced_triangle(true).glb());
    expect_instances_placed(quantized, 1e-3);
    EXPECT_EQ(quantized.decoded, "KHR_mesh_quantization, EXT_mesh_gpu_instancing (3 instances of 1 node)");
}

TEST(GltfInstancing, BrokenInstancingIsNamedInOneLine) {
    struct Case {
        const char* name;
        void (*edit)(json& doc, anim::GltfBuilder& b);
        const char* message;
    };
    const Case cases[] = {
        {"counts_differ",
         [](json& d, anim::GltfBuilder& b) {
             d["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["SCALE"] =
                 b.add_floats({1, 1, 1, 1, 1, 1}, "VEC3");
         },
         "nodes[0].extensions.EXT_mesh_gpu_instancing.attributes.SCALE: 2 instances, but ROTATION has 3"},
        {"rotation_not_vec4",
         [](json& d, anim::GltfBuilder& b) {
             d["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["ROTATION"] =
                 b.add_floats({0, 0, 0, 0, 0, 0, 0, 0, 0}, "VEC3");
         },
         "nodes[0].extensions.EXT_mesh_gpu_instancing.attributes.ROTATION: accessor"},
        {"accessor_missing",
         [](json& d, anim::GltfBuilder&) { d["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["SCALE"] = 99; },
         "nodes[0].extensions.EXT_mesh_gpu_instancing.attributes.SCALE: accessor 99 does not exist"},
        {"no_attributes",
         [](json& d, anim::GltfBuilder&) { d["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"].erase("attributes"); },
         "nodes[0].extensions.EXT_mesh_gpu_instancing.attributes"},
        {"empty_attributes",
         [](json& d, anim::GltfBuilder&) { d["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"] = json::object(); },
         "nodes[0].extensions.EXT_mesh_gpu_instancing.attributes: empty (no instance is defined)"},
        {"no_mesh", [](json& d, anim::GltfBuilder&) { d["nodes"][0].erase("mesh"); },
         "nodes[0].extensions.EXT_mesh_gpu_instancing: the node has no mesh to instance"},
        {"no_instance",
         [](json& d, anim::GltfBuilder&) {
             d["accessors"].push_back({{"componentType", 5126}, {"count", 0}, {"type", "VEC3"}});
             d["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"] = {{"TRANSLATION", d["accessors"].size() - 1}};
         },
         "nodes[0].extensions.EXT_mesh_gpu_instancing.attributes.TRANSLATION: 0 instances"},
        {"an_own_attribute_counts_too",
         [](json& d, anim::GltfBuilder& b) {
             d["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["_ID"] = b.add_floats({0, 1, 2, 3, 4}, "SCALAR");
         },
         "nodes[0].extensions.EXT_mesh_gpu_instancing.attributes._ID: 5 instances, but TRANSLATION has 3"},
        // 150M instances declared in a few bytes (an accessor without data reads as zeros): refused before
        // anything is read or copied.
        {"too_many",
         [](json& d, anim::GltfBuilder&) {
             d["accessors"].push_back({{"componentType", 5126}, {"count", 150000000}, {"type", "VEC3"}});
             d["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"] = {{"TRANSLATION", d["accessors"].size() - 1}};
         },
         "nodes[0].extensions.EXT_mesh_gpu_instancing: 150000000 instances of a mesh of 3 vertices, more than the limit of "
         "200000000 vertices"},
        {"zero_rotation",
         [](json& d, anim::GltfBuilder& b) {
             d["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["ROTATION"] =
                 b.add_floats({0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 1}, "VEC4");
         },
         "nodes[0].extensions.EXT_mesh_gpu_instancing.attributes.ROTATION: instance 1 is a zero quaternion"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        anim::GltfBuilder b = instanced_triangle(false);
        c.edit(b.doc, b);
        const std::string name = std::string(c.name) + ".glb";
        try {
            load_mesh_from_bytes(name, b.glb());
            ADD_FAILURE() << "loaded";
        } catch (const Error& e) {
            const std::string message = e.what();
            EXPECT_EQ(message.rfind(name + ": " + c.message, 0), 0u) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        }
    }
}

// Within the count limits but not within memory (accessors without data read as zeros, as many as they say):
// on a machine of 1 GiB, 10 million instances of a triangle, and a primitive of 3 million zero positions with a
// sparse triangle, loaded for 2.4 GiB and 270 MiB until 2026-12-07, and 66 million instances for about 16 GiB.
TEST(GltfInstancing, ZerosThatWouldNotFitInMemoryAreRefusedBeforeTheyAreMade) {
    test::ScopedEnv limit("STIPPLE_HOST_MEMORY_LIMIT", "1G");
    auto refusal = [](const std::string& name, const anim::GltfBuilder& b) {
        try {
            load_mesh_from_bytes(name, b.glb());
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("loaded");
    };
    anim::GltfBuilder instanced = instanced_triangle(false);
    instanced.doc["accessors"].push_back({{"componentType", 5126}, {"count", 10000000}, {"type", "VEC3"}});
    instanced.doc["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"] = {
        {"TRANSLATION", instanced.doc["accessors"].size() - 1}};
    EXPECT_EQ(refusal("instances.glb", instanced),
              "instances.glb: nodes[0].extensions.EXT_mesh_gpu_instancing: 30000000 vertices need about 3.7 GiB to load, "
              "more than a model may take on this machine: 512.0 MiB, half its 1.0 GiB of memory");
    anim::GltfBuilder zeros;
    zeros.add("meshes", {{"primitives", json::array({{{"attributes", {{"POSITION", 0}}}}})}});
    zeros.doc["accessors"] = json::array({{{"componentType", 5126}, {"count", 30000000}, {"type", "VEC3"}}});
    zeros.add("nodes", {{"mesh", 0}});
    EXPECT_EQ(refusal("zeros.glb", zeros).rfind("zeros.glb: mesh 0 primitive 0 POSITION (accessor 0): 30000000 elements "
                                                "without a buffer view (zeros) would take 343.3 MiB", 0), 0u)
        << refusal("zeros.glb", zeros);
    // What fits still loads: a thousand instances of zeros are a thousand copies at the origin, one kept.
    anim::GltfBuilder few = instanced_triangle(false);
    few.doc["accessors"].push_back({{"componentType", 5126}, {"count", 1000}, {"type", "VEC3"}});
    few.doc["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"] = {{"TRANSLATION", few.doc["accessors"].size() - 1}};
    EXPECT_EQ(load_mesh_from_bytes("few.glb", few.glb()).triangle_count(), 1u);
}

TEST(GltfInstancing, InstancesMoveWithTheirAnimatedNode) {
    // The node's translation animated from kNodeTranslation to kNodeTranslation + (0, 0, 2) over one
    // second: every instance follows it, each placed by its own transform.
    anim::GltfBuilder b = instanced_triangle(false);
    add_slide(b);
    const std::string bytes = b.glb();
    const anim::AnimatedModel model = anim::load_animated_model_from_bytes("slide.glb", bytes);
    const Mesh drawn = load_mesh_from_bytes("slide.glb", bytes);
    ASSERT_EQ(model.rest.triangle_count(), kInstances.size());
    for (double t : {0.0, 0.5, 1.0}) {
        const anim::DeformedGeometry posed = anim::deform_cpu(model, anim::evaluate_pose(model, 0, t, false));
        // Every vertex moved by the node's slide, (0, 0, 2t), from where the static loader put it.
        std::vector<glm::vec3> expected = model.rest.positions;
        for (glm::vec3& p : expected) p += glm::vec3(0.0f, 0.0f, float(2.0 * t));
        ASSERT_EQ(posed.positions.size(), expected.size());
        for (size_t v = 0; v < expected.size(); ++v)
            EXPECT_LT(glm::length(posed.positions[v] - expected[v]), 1e-5f) << "t " << t << " vertex " << v;
    }
    // The rest mesh is the static loader's (as the drawing order has it: the same set of corners).
    EXPECT_EQ(drawn.triangle_count(), model.rest.triangle_count());
}

// Attributes of the application's own (an _ID) count instances like the transforms; alone, they place every
// instance at the node's transform.
TEST(GltfInstancing, AnAttributeOfTheApplicationsOwnCountsInstances) {
    anim::GltfBuilder b = instanced_triangle(false);
    b.doc["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["_ID"] = b.add_floats({7, 8, 9}, "SCALAR");
    expect_instances_placed(load_mesh_from_bytes("with_id.glb", b.glb()), 1e-5);
    b.doc["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"] = {{"_ID", b.add_floats({7, 8, 9}, "SCALAR")}};
    const Mesh alone = load_mesh_from_bytes("id_only.glb", b.glb());
    EXPECT_EQ(alone.decoded, "EXT_mesh_gpu_instancing (3 instances of 1 node)");
    // Three copies in one place: loading keeps one of the repeated faces.
    ASSERT_EQ(alone.triangle_count(), 1u);
    for (const glm::dvec3& corner : kTriangle) {
        double nearest = 1e30;
        for (int c = 0; c < 3; ++c)
            nearest = std::min(nearest, glm::length(glm::dvec3(alone.positions[alone.indices[c]]) - (corner + kNodeTranslation)));
        EXPECT_LT(nearest, 1e-6);
    }
}

// A mesh of two primitives instanced on an animated node: the animated loader lays the copies out as the
// static one does (primitive by primitive, each at every instance), so its rest mesh is the drawn one.
TEST(GltfInstancing, CopiesOfSeveralPrimitivesAnimateInTheStaticOrder) {
    anim::GltfBuilder b = instanced_triangle(false);
    const int second = b.add_floats({0, 0, 1, 1, 0, 1, 0, 1, 1}, "VEC3");  // the triangle again, 1 higher in z
    b.doc["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", second}}}});
    add_slide(b);
    const std::string bytes = b.glb();
    const Mesh drawn = load_mesh_from_bytes("two_primitives.glb", bytes);
    const anim::AnimatedModel model = anim::load_animated_model_from_bytes("two_primitives.glb", bytes);
    EXPECT_EQ(drawn.triangle_count(), 2 * kInstances.size());
    EXPECT_EQ(model.rest.triangle_count(), drawn.triangle_count());
    const anim::DeformedGeometry posed = anim::deform_cpu(model, anim::evaluate_pose(model, 0, 1.0, false));
    ASSERT_EQ(posed.positions.size(), model.rest.positions.size());
    for (size_t v = 0; v < posed.positions.size(); ++v)
        EXPECT_LT(glm::length(posed.positions[v] - (model.rest.positions[v] + glm::vec3(0, 0, 2))), 1e-5f) << v;
}

TEST(GltfInstancing, SkinnedInstancesLoadStaticButAreNotAnimated) {
    anim::GltfBuilder b = anim::rigs::bending_cylinder({2, 6});
    const int translations = b.add_floats({0, 0, 0, 3, 0, 0}, "VEC3");
    b.doc["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"] = {{"attributes", {{"TRANSLATION", translations}}}};
    b.doc["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
    const std::string bytes = b.glb();
    const Mesh once = load_mesh_from_bytes("cylinder.glb", anim::rigs::bending_cylinder({2, 6}).glb());
    EXPECT_EQ(load_mesh_from_bytes("cylinder.glb", bytes).triangle_count(), 2 * once.triangle_count());
    try {
        anim::load_animated_model_from_bytes("cylinder.glb", bytes);
        ADD_FAILURE() << "loaded";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(),
                     "cylinder.glb: nodes[0].extensions.EXT_mesh_gpu_instancing: instances of a skinned mesh cannot be animated");
    }
}

}  // namespace
}  // namespace stipple
