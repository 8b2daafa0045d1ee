// Loading animated glTF: the rest mesh is exactly the static loader's drawing mesh (so stipples stay
// valid), and skins, morph targets, animations and the encodings glTF allows for them are read right.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <tuple>
#include <filesystem>

#include <nlohmann/json.hpp>
#include <glm/geometric.hpp>

#include "anim/deform_cpu.hpp"
#include "anim/describe.hpp"
#include "anim/gltf_probe.hpp"
#include "anim/pose.hpp"
#include "anim/procedural_rigs.hpp"
#include "core/error.hpp"
#include "mesh/load_mesh.hpp"
#include "mesh/loader_util.hpp"
#include "support/anim_files.hpp"
#include "stipple/object_data.hpp"
#include "support/test_paths.hpp"

namespace stipple::anim {
namespace {

using test::load_rig;
using test::write_rig;

void expect_rest_is_drawing_mesh(const std::string& path) {
    const AnimatedModel model = load_animated_model(path);
    const Mesh drawn = load_mesh_for_drawing(path);
    ASSERT_EQ(model.rest.indices, drawn.indices) << path;
    ASSERT_EQ(model.rest.positions, drawn.positions) << path;
    ASSERT_EQ(model.rest.normals, drawn.normals) << path;
    EXPECT_EQ(model.bind_positions.size(), drawn.vertex_count());
    EXPECT_EQ(model.influences.size(), drawn.vertex_count());
    EXPECT_EQ(model.morph_refs.size(), drawn.vertex_count());
    for (const Influences& inf : model.influences) {
        double sum = 0.0;
        for (uint32_t i = 0; i < kMaxInfluences; ++i) {
            sum += inf.weight[i];
            EXPECT_LT(inf.slot[i], model.palette.size());
        }
        EXPECT_NEAR(sum, 1.0, 1e-6) << path;
    }
}

TEST(AnimLoading, RestMeshIsTheStaticDrawingMesh) {
    expect_rest_is_drawing_mesh(write_rig(rigs::bending_cylinder(), "anim_load_cylinder", "cylinder"));
    expect_rest_is_drawing_mesh(write_rig(rigs::node_animated_box(), "anim_load_box", "box"));
    expect_rest_is_drawing_mesh(write_rig(rigs::interpolation_sample("LINEAR"), "anim_load_keys", "keys"));
    expect_rest_is_drawing_mesh(write_rig(rigs::stretching_plane(), "anim_load_plane", "plane"));
    expect_rest_is_drawing_mesh(write_rig(rigs::eight_joint_sheet(), "anim_load_eight", "eight"));
}

// A mesh's triangles as corner positions, each starting at its least corner (which keeps its winding),
// sorted: equal for two meshes of the same faces in any vertex and triangle order.
std::vector<std::array<float, 9>> wound_triangles(const Mesh& mesh) {
    std::vector<std::array<float, 9>> out;
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
        std::array<glm::vec3, 3> c;
        for (int k = 0; k < 3; ++k) c[k] = mesh.positions[mesh.indices[3 * t + k]];
        auto less = [](const glm::vec3& a, const glm::vec3& b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); };
        const int first = int(std::min_element(c.begin(), c.end(), less) - c.begin());
        std::array<float, 9> tri;
        for (int k = 0; k < 3; ++k)
            for (int i = 0; i < 3; ++i) tri[3 * k + i] = c[(first + k) % 3][i];
        out.push_back(tri);
    }
    std::sort(out.begin(), out.end());
    return out;
}

// The rest mesh is what the file draws when nothing moves: its skins and default morph weights applied,
// where the static loader only places each primitive by its node.
TEST(AnimLoading, RestMeshIsTheRestPose) {
    // The quad's node weights (0.25, 0) lift its vertex (1, 1, 0) by 0.25 at rest: every triangle and
    // normal as the static loader has them, that vertex moved.
    const std::string quad = write_rig(rigs::morphed_quad(), "anim_load_quad", "quad");
    const AnimatedModel morphed = load_animated_model(quad);
    const Mesh drawn = load_mesh_for_drawing(quad);
    ASSERT_EQ(morphed.rest.indices, drawn.indices);
    const DeformedGeometry rest = deform_cpu(morphed, evaluate_pose(morphed, kRestPose, 0.0));
    EXPECT_EQ(morphed.rest.positions, rest.positions);
    EXPECT_EQ(morphed.rest.normals, rest.normals);
    int lifted = 0;
    for (size_t v = 0; v < drawn.vertex_count(); ++v) {
        const glm::vec3 expected = drawn.positions[v] + (drawn.positions[v] == glm::vec3(2, 3, 3) ? glm::vec3(0, 0, 0.25f) : glm::vec3(0));
        lifted += expected != drawn.positions[v];
        EXPECT_EQ(morphed.rest.positions[v], expected) << "vertex " << v;
    }
    EXPECT_EQ(lifted, 1);

    // A skinned tube under a node that scales it by 2 and mirrors it: glTF ignores that node, so the rest
    // mesh is the tube under an identity node, and its faces still face out (the static loader re-wound
    // them for the mirror).
    auto tube = rigs::bending_cylinder();
    const AnimatedModel plain = load_animated_model(write_rig(tube, "anim_load_tube", "plain"));
    tube.doc["nodes"][0]["scale"] = {-2.0, 2.0, 2.0};
    const AnimatedModel mirrored = load_animated_model(write_rig(tube, "anim_load_tube_mirror", "mirrored"));
    EXPECT_NE(load_mesh_for_drawing(write_rig(tube, "anim_load_tube_mirror", "mirrored")).positions, mirrored.rest.positions);
    // The same triangles, wound the same way (the draw order, chosen on the static placement, may differ).
    EXPECT_EQ(wound_triangles(plain.rest), wound_triangles(mirrored.rest));
    for (const AnimatedModel* model : {&plain, &mirrored}) {
        size_t outward = 0;
        for (size_t t = 0; t < model->rest.triangle_count(); ++t) {
            const glm::vec3 a = model->rest.positions[model->rest.indices[3 * t]];
            const glm::vec3 b = model->rest.positions[model->rest.indices[3 * t + 1]];
            const glm::vec3 c = model->rest.positions[model->rest.indices[3 * t + 2]];
            const glm::vec3 centre = (a + b + c) / 3.0f;
            // Away from the tube's axis on its side, along it on the caps.
            const glm::vec3 out = std::abs(centre.y - 1.0f) > 0.999f ? glm::vec3(0, centre.y - 1.0f, 0) : glm::vec3(centre.x, 0, centre.z);
            outward += glm::dot(glm::cross(b - a, c - a), out) > 0.0f;
        }
        EXPECT_EQ(outward, model->rest.triangle_count()) << (model == &plain ? "plain" : "mirrored");
    }

    // A rest pose that collapses faces (the root joint at scale 0: a part hidden until the animation grows
    // it) would give them no stipples ever: such a file keeps the static placement's mesh.
    auto hidden = rigs::bending_cylinder();
    hidden.doc["nodes"][0]["scale"] = {2.0, 2.0, 2.0};
    hidden.doc["nodes"][1]["scale"] = {0.0, 0.0, 0.0};
    const std::string hidden_path = write_rig(hidden, "anim_load_tube_hidden", "hidden");
    EXPECT_EQ(load_animated_model(hidden_path).rest.positions, load_mesh_for_drawing(hidden_path).positions);
}

// A curved sheet made two-sided by a reversed copy of its triangles on the same vertices, without
// normals, as a .glb; with `animated`, its node turns about y over a second.
std::string two_sided_sheet(bool animated, const std::string& folder) {
    GltfBuilder b;
    std::vector<float> positions;
    std::vector<uint16_t> indices;
    const int n = 6;
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x) {
            const float u = float(x) / n - 0.5f, v = float(y) / n - 0.5f;
            positions.insert(positions.end(), {u, v, 0.4f * u * u});
        }
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const uint16_t a = uint16_t(y * (n + 1) + x), c = uint16_t(a + n + 2), d = uint16_t(a + n + 1);
            indices.insert(indices.end(), {a, uint16_t(a + 1), c, a, c, d});
        }
    const size_t one_side = indices.size();
    for (size_t t = 0; t < one_side; t += 3) indices.insert(indices.end(), {indices[t], indices[t + 2], indices[t + 1]});
    const int p = b.add_floats(positions, "VEC3");
    const int i = b.add_uint16(indices, "SCALAR");
    b.add("meshes", {{"primitives", nlohmann::json::array({{{"attributes", {{"POSITION", p}}}, {"indices", i}}})}});
    b.add("nodes", {{"mesh", 0}});
    b.add("scenes", {{"nodes", nlohmann::json::array({0})}});
    b.doc["scene"] = 0;
    if (animated) {
        const int times = b.add_floats({0.0f, 1.0f}, "SCALAR");
        const int turns = b.add_floats({0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.7071068f, 0.0f, 0.7071068f}, "VEC4");
        b.add("animations", {{"samplers", nlohmann::json::array({{{"input", times}, {"output", turns}}})},
                             {"channels", nlohmann::json::array({{{"sampler", 0}, {"target", {{"node", 0}, {"path", "rotation"}}}}})}});
    }
    return write_rig(b, folder, animated ? "sheet_animated" : "sheet");
}

// The loader computes a glTF primitive's missing normals itself; they used to count as the file's, so a
// two-sided sheet on shared vertices kept normals that cancelled, and the winding repair then turned its
// back faces to them (it drew nothing from behind, until 2026-12-04). Computed normals are now the
// loader's, the shared vertices are split as for OBJ, and the animated loader, whose skin and morph data
// are per vertex of the file, loads the same sheet without the split (it failed with "the animation
// data has 49 vertices, the static mesh 98").
TEST(AnimLoading, ATwoSidedSheetWithoutNormalsLoadsStaticAndAnimated) {
    const Mesh sheet = load_mesh(two_sided_sheet(false, "anim_two_sided_sheet"));
    ASSERT_EQ(sheet.triangle_count(), 144u);
    EXPECT_TRUE(sheet.normals_computed);
    EXPECT_EQ(sheet.winding.parts_turned_to_normals, 0u);
    EXPECT_EQ(sheet.vertex_count(), 98u);  // every vertex split: its sides each have their own
    size_t facing_back = 0;
    for (size_t t = 0; t < sheet.triangle_count(); ++t) {
        const glm::vec3 a = sheet.positions[sheet.indices[3 * t]], b = sheet.positions[sheet.indices[3 * t + 1]],
                        c = sheet.positions[sheet.indices[3 * t + 2]];
        const glm::vec3 face = glm::normalize(glm::cross(b - a, c - a));
        facing_back += face.z < 0.0f;
        for (int k = 0; k < 3; ++k)
            EXPECT_GT(glm::dot(sheet.normals[sheet.indices[3 * t + k]], face), 0.9f) << "triangle " << t << " corner " << k;
    }
    EXPECT_EQ(facing_back, 72u) << "half the triangles face each way, as in the file";
    const AnimatedModel animated = load_animated_model(two_sided_sheet(true, "anim_two_sided_sheet_animated"));
    EXPECT_TRUE(animated.is_animated());
    EXPECT_EQ(animated.rest.triangle_count(), 144u);
    EXPECT_EQ(animated.rest.vertex_count(), 49u) << "the file's vertices, unsplit";
}

TEST(AnimLoading, StaticGltfLoadsWithNothingToAnimate) {
    // The project's default scene: a static glTF; every vertex follows its (unanimated) node.
    const std::string blobby = test::source_path("assets/blobby.glb");
    expect_rest_is_drawing_mesh(blobby);
    const AnimatedModel model = load_animated_model(blobby);
    EXPECT_FALSE(model.is_animated());
    EXPECT_TRUE(describe_lines(describe_animation(model)).empty());
    const DeformedGeometry g = deform_cpu(model, evaluate_pose(model, kRestPose, 0.0));
    const Bounds bounds = compute_bounds(model.rest);
    for (size_t v = 0; v < model.vertex_count(); ++v)
        EXPECT_LE(glm::length(g.positions[v] - model.rest.positions[v]), 1e-6f * glm::length(bounds.max - bounds.min));
}

TEST(AnimLoading, DrawOrderCarriesTheStreams) {
    // The cylinder's vertices are reordered for drawing; each one must keep its own bind position and
    // weights (here the rest mesh is the bind pose, so positions agree vertex by vertex, and the
    // elbow's weight is a function of the height).
    const uint32_t rings = 30, segments = 40;
    const AnimatedModel model = load_rig(rigs::bending_cylinder({.rings = rings, .segments = segments}), "anim_load_order", "cylinder");
    const uint32_t elbow_slot = model.skins[0].first_slot + 1;
    size_t moved = 0;
    for (size_t v = 0; v < model.vertex_count(); ++v) {
        const glm::vec3 p = model.bind_positions[v];
        EXPECT_EQ(p, model.rest.positions[v]);
        float elbow = 0.0f;
        for (uint32_t i = 0; i < kMaxInfluences; ++i) elbow += model.influences[v].slot[i] == elbow_slot ? model.influences[v].weight[i] : 0.0f;
        EXPECT_NEAR(elbow, rigs::cylinder_elbow_weight(p.y), 1e-6);
        if (glm::length(glm::vec2(p.x, p.z)) < 0.1f) continue;  // a cap's centre
        const long ring = std::lround(p.y * rings / 2.0f);
        const long segment = (std::lround(std::atan2(p.z, p.x) / (2.0 * 3.14159265358979) * segments) + segments) % segments;
        moved += static_cast<size_t>(ring * segments + segment) != v;  // its place in the file
    }
    EXPECT_GT(moved, model.vertex_count() / 2) << "the draw order hardly moved the vertices, so this test shows little";
}

TEST(AnimLoading, FoxSkinAndAnimations) {
    const std::string fox = test::shared_model("fox.glb");
    if (fox.empty()) GTEST_SKIP() << "../shared/models/fox.glb not present";
    expect_rest_is_drawing_mesh(fox);
    const AnimatedModel model = load_animated_model(fox);
    EXPECT_EQ(model.vertex_count(), 1728u);
    EXPECT_EQ(model.rest.triangle_count(), 576u);
    ASSERT_EQ(model.skins.size(), 1u);
    EXPECT_EQ(model.skins[0].joints.size(), 24u);
    ASSERT_EQ(model.animations.size(), 3u);
    EXPECT_EQ(find_animation(model, "Survey"), 0);
    EXPECT_EQ(find_animation(model, "Walk"), 1);
    EXPECT_EQ(find_animation(model, "Run"), 2);
    for (const Animation& a : model.animations) {
        EXPECT_EQ(a.channels.size(), 21u);
        EXPECT_GT(a.duration, 0.5f);
    }
    for (const Influences& inf : model.influences)
        for (uint32_t i = 0; i < kMaxInfluences; ++i)
            if (inf.weight[i] > 0.0f) {
                EXPECT_LT(inf.slot[i], model.skins[0].first_slot + 24);
            }
    // Its joints' rest transforms are the bind pose: the rest pose is the static mesh.
    const Bounds bounds = compute_bounds(model.rest);
    const double size = glm::length(bounds.max - bounds.min);
    const DeformedGeometry rest = deform_cpu(model, evaluate_pose(model, kRestPose, 0.0));
    for (size_t v = 0; v < model.vertex_count(); ++v) EXPECT_LE(glm::length(rest.positions[v] - model.rest.positions[v]), 1e-6 * size);
    // The walk moves the fox: its feet (the lowest vertices) are somewhere else half a cycle later.
    const int walk = find_animation(model, "Walk");
    const DeformedGeometry a = deform_cpu(model, evaluate_pose(model, walk, 0.0));
    const DeformedGeometry b = deform_cpu(model, evaluate_pose(model, walk, model.animations[walk].duration / 2));
    double largest = 0.0;
    for (size_t v = 0; v < model.vertex_count(); ++v) largest = std::max(largest, double(glm::length(a.positions[v] - b.positions[v])));
    EXPECT_GT(largest, 0.05 * size);
    const std::vector<std::string> lines = describe_lines(describe_animation(model));
    ASSERT_EQ(lines.size(), 4u);
    EXPECT_EQ(lines[1].rfind("animation 1 'Walk': ", 0), 0u) << lines[1];
    EXPECT_NE(lines[1].find("21 channels (LINEAR)"), std::string::npos) << lines[1];
    EXPECT_EQ(lines[3], "skin 0: 24 joints");
}

TEST(AnimLoading, AnimatedMorphCube) {
    const std::string cube = test::shared_model("AnimatedMorphCube.gltf");
    if (cube.empty()) GTEST_SKIP() << "../shared/models/AnimatedMorphCube.gltf not present";
    expect_rest_is_drawing_mesh(cube);
    const AnimatedModel model = load_animated_model(cube);
    ASSERT_EQ(model.morph_sets.size(), 1u);
    EXPECT_EQ(model.morph_sets[0].target_names, (std::vector<std::string>{"thin", "angle"}));
    ASSERT_EQ(model.animations.size(), 1u);
    EXPECT_EQ(model.animations[0].channels[0].path, ChannelPath::Weights);
    EXPECT_NEAR(model.animations[0].duration, 4.2, 1e-3);
    for (const MorphRef& ref : model.morph_refs) EXPECT_EQ(ref.count, 2u);
    const std::vector<std::string> lines = describe_lines(describe_animation(model));
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[1], "morph targets of mesh 'Cube': 2 ('thin', 'angle')");
    // Some time in the loop, the weights deform the cube away from its rest shape.
    double largest = 0.0;
    for (double t = 0.0; t < 4.2; t += 0.3) {
        const DeformedGeometry g = deform_cpu(model, evaluate_pose(model, 0, t));
        for (size_t v = 0; v < model.vertex_count(); ++v)
            largest = std::max(largest, double(glm::length(g.positions[v] - model.rest.positions[v])));
    }
    EXPECT_GT(largest, 0.5);  // the cube is 2 units wide (scale 100 of +-0.01); its targets move it by ~2
}

TEST(AnimLoading, DescribesTheQuadsTargetsByName) {
    const AnimatedModel model = load_rig(rigs::morphed_quad(), "anim_load_describe", "quad");
    const AnimationDescription d = describe_animation(model);
    ASSERT_EQ(d.morphs.size(), 1u);
    EXPECT_EQ(d.morphs[0].node_name, "sheet");
    const std::vector<std::string> lines = describe_lines(d);
    EXPECT_EQ(lines, (std::vector<std::string>{"animation 0 'Morph': 2.000 s, 1 channel (LINEAR)",
                                               "morph targets of mesh 'sheet': 2 ('lift', 'raise')"}));
}

// Channels that move no drawn vertex are dropped, so a file whose animations drive only such nodes is
// still (drawn by every path, one frame for a sequence) instead of "animated" with nothing moving; a
// channel on an ancestor of a drawn node, or on a joint the vertices follow, moves the drawing.
TEST(AnimLoading, ChannelsThatMoveNothingDrawnAreDropped) {
    // The box's channels moved to a node with no mesh beside it.
    auto box = rigs::node_animated_box();
    const int empty = box.add("nodes", {{"name", "empty"}});
    box.doc["scenes"][0]["nodes"].push_back(empty);
    for (auto& c : box.doc["animations"][0]["channels"]) c["target"]["node"] = empty;
    const AnimatedModel idle = load_rig(box, "anim_load_idle", "empty_node");
    EXPECT_FALSE(idle.is_animated());
    ASSERT_EQ(idle.animations.size(), 1u);
    EXPECT_EQ(idle.animations[0].channels.size(), 0u);
    EXPECT_EQ(idle.animations[0].idle_channels, 3u);
    EXPECT_FLOAT_EQ(idle.animations[0].duration, 2.0f) << "the loop stays the file's";
    EXPECT_EQ(describe_lines(describe_animation(idle))[0], "animation 0 'Move': 2.000 s, 0 channels, and 3 that move nothing drawn");
    EXPECT_FALSE(load_model_data(write_rig(box, "anim_load_idle", "empty_node")).motion);

    // The same channels on the box's parent: its transform places the box.
    for (auto& c : box.doc["animations"][0]["channels"]) c["target"]["node"] = 0;
    const AnimatedModel parent = load_rig(box, "anim_load_idle", "parent_node");
    EXPECT_TRUE(parent.is_animated());
    EXPECT_EQ(parent.animations[0].channels.size(), 3u);
    EXPECT_EQ(parent.animations[0].idle_channels, 0u);

    // The tube's joints animated while its node uses no skin: its vertices follow its own node.
    auto tube = rigs::bending_cylinder();
    EXPECT_TRUE(load_rig(tube, "anim_load_idle", "skinned").is_animated());
    tube.doc["nodes"][0].erase("skin");
    const AnimatedModel unskinned = load_rig(tube, "anim_load_idle", "unskinned");
    EXPECT_FALSE(unskinned.is_animated());
    EXPECT_EQ(unskinned.animations[0].idle_channels + unskinned.animations[1].idle_channels, 2u);
}

// glTF allows rotations as normalized integers and morph targets as sparse accessors: both must give
// the same pose as the plain float files.
TEST(AnimLoading, NormalizedRotationsAndSparseTargets) {
    GltfBuilder box = rigs::node_animated_box();
    std::vector<uint8_t> shorts;  // 0, 90 and 180 degrees about y as normalized signed shorts (x, y, z, w)
    const double s = std::sqrt(0.5);
    for (double v : {0.0, 0.0, 0.0, 1.0, 0.0, s, 0.0, s, 0.0, 1.0, 0.0, 0.0}) {
        const int16_t q = static_cast<int16_t>(std::lround(v * 32767.0));
        shorts.push_back(uint8_t(q & 0xFF));
        shorts.push_back(uint8_t(uint16_t(q) >> 8));
    }
    const int accessor = box.add_uint8(shorts, "VEC4");  // bytes of the shorts; retyped below
    box.doc["accessors"][accessor]["componentType"] = 5122;
    box.doc["accessors"][accessor]["count"] = 3;
    box.doc["accessors"][accessor]["normalized"] = true;
    box.doc["animations"][0]["samplers"][1]["output"] = accessor;
    const AnimatedModel plain = load_rig(rigs::node_animated_box(), "anim_load_plain_box", "box");
    const AnimatedModel packed = load_rig(box, "anim_load_short_box", "box");
    const Pose a = evaluate_pose(plain, 0, 0.7), b = evaluate_pose(packed, 0, 0.7);
    for (int c = 0; c < 4; ++c) EXPECT_LE(glm::length(a.world[1][c] - b.world[1][c]), 1e-4);

    GltfBuilder quad = rigs::morphed_quad();
    // Target 0's POSITION as a sparse accessor: zeros except vertex 2, which rises by 1.
    const int indices = quad.add_uint16({2}, "SCALAR");
    const int values = quad.add_floats({0, 0, 1}, "VEC3");
    const int sparse = quad.add("accessors", {{"componentType", 5126}, {"count", 4}, {"type", "VEC3"},
                                              {"sparse", {{"count", 1},
                                                          {"indices", {{"bufferView", quad.doc["accessors"][indices]["bufferView"]}, {"componentType", 5123}}},
                                                          {"values", {{"bufferView", quad.doc["accessors"][values]["bufferView"]}}}}}});
    quad.doc["meshes"][0]["primitives"][0]["targets"][0]["POSITION"] = sparse;
    const AnimatedModel dense_quad = load_rig(rigs::morphed_quad(), "anim_load_dense_quad", "quad");
    const AnimatedModel sparse_quad = load_rig(quad, "anim_load_sparse_quad", "quad");
    const DeformedGeometry g0 = deform_cpu(dense_quad, evaluate_pose(dense_quad, 0, 0.6));
    const DeformedGeometry g1 = deform_cpu(sparse_quad, evaluate_pose(sparse_quad, 0, 0.6));
    EXPECT_EQ(g0.positions, g1.positions);
}

TEST(AnimLoading, OnlyGltfFilesAnimate) {
    const std::string path = (test::temp_dir("anim_load_obj") / "tri.obj").string();
    FILE* f = std::fopen(path.c_str(), "w");
    std::fputs("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", f);
    std::fclose(f);
    try {
        load_animated_model(path);
        ADD_FAILURE() << "an OBJ file loaded as an animated model";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), path + ": animation needs a glTF file (.gltf or .glb)");
    }
}

TEST(AnimLoading, ProbeTellsAnimatedFilesBeforeLoading) {
    // What decides whether a model is loaded by the animated loader or only by the static one.
    EXPECT_TRUE(gltf_declares_animations(test::write_rig(rigs::bending_cylinder(), "anim_probe", "cylinder")));
    EXPECT_TRUE(gltf_declares_animations(test::write_rig(rigs::morphed_quad(), "anim_probe_quad", "quad")));
    EXPECT_FALSE(gltf_declares_animations(test::source_path("assets/blobby.glb")));
    const auto dir = test::temp_dir("anim_probe_text");
    auto write = [&](const std::string& name, const std::string& text) {
        const std::string path = (dir / name).string();
        FILE* f = std::fopen(path.c_str(), "w");
        std::fputs(text.c_str(), f);
        std::fclose(f);
        return path;
    };
    EXPECT_FALSE(gltf_declares_animations(write("none.gltf", R"({"asset": {"version": "2.0"}, "animations": []})")));
    EXPECT_TRUE(gltf_declares_animations(write("one.gltf", R"({"asset": {"version": "2.0"}, "animations": [{}]})")));
    // Cannot tell: the full loader will say what is wrong.
    EXPECT_TRUE(gltf_declares_animations(write("broken.gltf", "{ not json")));
    // No file to read is refused as the loader refuses it, before anything is opened (check_model_file).
    const std::string missing = (dir / "missing.glb").string();
    try {
        gltf_declares_animations(missing);
        ADD_FAILURE() << "a missing file was probed";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), missing + ": no such file");
    }

    // What sends a file without animations to the animated loader too: a rest pose that may differ from
    // the static loader's placement (a skin, morph weights other than zero).
    EXPECT_FALSE(gltf_declares_deformation(test::source_path("assets/blobby.glb")));
    EXPECT_TRUE(gltf_declares_deformation(write("anim.gltf", R"({"asset": {"version": "2.0"}, "animations": [{}]})")));
    EXPECT_TRUE(gltf_declares_deformation(write("skin.gltf", R"({"asset": {"version": "2.0"}, "skins": [{"joints": [0]}]})")));
    EXPECT_FALSE(gltf_declares_deformation(write("zero.gltf", R"({"asset": {"version": "2.0"}, "meshes": [{"weights": [0, 0]}]})")));
    EXPECT_TRUE(gltf_declares_deformation(write("mesh.gltf", R"({"asset": {"version": "2.0"}, "meshes": [{"weights": [0, 0.5]}]})")));
    EXPECT_TRUE(gltf_declares_deformation(write("node.gltf", R"({"asset": {"version": "2.0"}, "nodes": [{"weights": [1]}]})")));
    EXPECT_TRUE(gltf_declares_deformation(write("broken2.gltf", "{ not json")));
}

// A file without animations draws its rest pose too: a skin under a node that glTF ignores, a mesh whose
// default weights morph it (the static loader alone would draw the first at twice its size, the second
// unmorphed).
TEST(AnimLoading, StaticFilesDrawTheirRestPose) {
    auto tube = rigs::bending_cylinder();
    const AnimatedModel plain = load_animated_model(write_rig(tube, "anim_static_tube", "plain"));
    tube.doc.erase("animations");
    tube.doc["nodes"][0]["scale"] = {2.0, 2.0, 2.0};
    const std::string scaled = write_rig(tube, "anim_static_tube_scaled", "scaled");
    EXPECT_EQ(load_model_data(scaled).mesh->positions, plain.rest.positions);
    EXPECT_NE(load_mesh_for_drawing(scaled).positions, plain.rest.positions);

    auto quad = rigs::morphed_quad();
    quad.doc.erase("animations");
    const std::string still = write_rig(quad, "anim_static_quad", "quad");
    const ObjectData data = load_model_data(still);
    EXPECT_FALSE(data.motion);
    size_t lifted = 0;
    for (const glm::vec3& p : data.mesh->positions) lifted += p == glm::vec3(2, 3, 3.25f);
    EXPECT_EQ(lifted, 1u) << "the node's weights (0.25, 0) lift the vertex (2, 3, 3) at rest";
}

}  // namespace
}  // namespace stipple::anim

namespace stipple::anim {
namespace {

TEST(AnimLoading, FromBytesAsFromTheFile) {
    // The animation fuzzer's seeds (tests/fuzz/corpus/anim, the procedural rigs as .glb and as .gltf
    // with embedded buffers) read from memory give the model the file gives, and they stay seeds that
    // animate: a seed that stopped loading would leave the fuzzer mutating refusals.
    namespace fs = std::filesystem;
    size_t seeds = 0;
    for (const auto& entry : fs::directory_iterator(test::source_path("tests/fuzz/corpus/anim"))) {
        const std::string path = entry.path().string();
        SCOPED_TRACE(path);
        const AnimatedModel from_file = load_animated_model(path);
        const AnimatedModel from_bytes = load_animated_model_from_bytes(entry.path().filename().string(), read_file(path));
        EXPECT_TRUE(from_file.is_animated());
        EXPECT_EQ(from_bytes.rest.positions, from_file.rest.positions);
        EXPECT_EQ(from_bytes.rest.indices, from_file.rest.indices);
        ASSERT_EQ(from_bytes.animations.size(), from_file.animations.size());
        const double t = 0.4 * from_file.animations[0].duration;
        EXPECT_EQ(deform_cpu(from_bytes, evaluate_pose(from_bytes, 0, t)).positions,
                  deform_cpu(from_file, evaluate_pose(from_file, 0, t)).positions);
        ++seeds;
    }
    EXPECT_GE(seeds, 10u);
    // Named by the name it is given, as every message of the file loader is by its path.
    try {
        load_animated_model_from_bytes("broken.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"meshes\": 3}");
        ADD_FAILURE() << "a broken document loaded";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("broken.gltf: ", 0), 0u) << e.what();
    }
}

}  // namespace
}  // namespace stipple::anim
