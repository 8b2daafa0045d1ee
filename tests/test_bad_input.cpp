// Every class of malformed model is refused with one line that names the file and the field or the
// problem: models with no triangle of any area, glTF fields of the wrong JSON type or out of range
// (static and animation fields alike), misspelt or unsupported extensions, glTF 1.0, and counts that
// claim far more than the file holds.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "mesh/load_mesh.hpp"
#include "support/model_files.hpp"
#include "support/test_paths.hpp"

namespace {

using json = nlohmann::json;
using stipple::Mesh;
using stipple::test::ByteWriter;
using stipple::test::temp_dir;
using stipple::test::write_file;

std::string load_error(const std::string& path) {
    try {
        stipple::load_mesh(path);
    } catch (const stipple::Error& e) {
        return e.what();
    }
    ADD_FAILURE() << path << " loaded without an error";
    return "";
}

// The message names the file first, contains `expected` and is one line.
void expect_error(const std::string& path, const std::string& expected) {
    const std::string message = load_error(path);
    EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << "message does not start with the file: " << message;
    EXPECT_NE(message.find(expected), std::string::npos) << "expected '" << expected << "' in: " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

// ---------------------------------------------------------------- no usable triangle

TEST(NoTriangleArea, ObjOfCollinearTriangles) {
    const auto dir = temp_dir("bad_zero_area_obj");
    expect_error(write_file(dir / "line.obj", "v 0 0 0\nv 1 1 1\nv 2 2 2\nv 3 3 3\nf 1 2 3\nf 2 3 4\n"),
                 "no triangle with non-zero area (all 2 triangles are degenerate)");
}

// A text file of another kind renamed .obj said only "the model has no triangles"; vertices without faces
// say how many there are.
TEST(NoTriangleArea, ObjWithoutFacesSaysWhatItHas) {
    const auto dir = temp_dir("bad_obj_no_faces");
    expect_error(write_file(dir / "notes.obj", "Shopping list\n- bread\n- milk\n"),
                 "no vertex (v) or face (f) statements: not an OBJ model");
    expect_error(write_file(dir / "points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"),
                 "the model has no triangles (3 vertices and no face (f) statements)");
}

TEST(NoTriangleArea, PlyOfRepeatedCorners) {
    const auto dir = temp_dir("bad_zero_area_ply");
    expect_error(write_file(dir / "repeated.ply",
                            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                            "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
                            "0 0 0\n1 0 0\n0 1 0\n3 0 0 1\n3 2 2 2\n"),
                 "no triangle with non-zero area");
}

TEST(NoTriangleArea, OneGoodTriangleIsEnough) {
    const auto dir = temp_dir("bad_zero_area_one_good");
    const Mesh m = stipple::load_mesh(write_file(dir / "one.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n"));
    EXPECT_EQ(m.triangle_count(), 2u);
    EXPECT_DOUBLE_EQ(stipple::total_area(m), 0.5);
}

// ---------------------------------------------------------------- glTF fields

// A valid glTF: one triangle (positions, 16-bit indices, a morph target) in a data: URI, two nodes (a
// mesh with a skin whose joint is its child), one animation of the morph weights.
json valid_gltf() {
    ByteWriter w;
    for (float v : {0, 0, 0, 1, 0, 0, 0, 1, 0}) w.put<float>(v);
    for (uint16_t i : {0, 1, 2, 0}) w.put<uint16_t>(i);  // the last one pads to 4 bytes
    for (float t : {0.0f, 1.0f}) w.put<float>(t);
    const std::string bytes = w.bytes();
    return json::parse(R"({
      "asset": {"version": "2.0"},
      "buffers": [{"byteLength": )" + std::to_string(bytes.size()) + R"(, "uri": "data:application/octet-stream;base64,)" +
                       stipple::test::base64(bytes) + R"("}],
      "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 8},
                      {"buffer": 0, "byteOffset": 44, "byteLength": 8}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                    {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"},
                    {"bufferView": 2, "componentType": 5126, "count": 2, "type": "SCALAR"}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4, "targets": [{"POSITION": 0}]}],
                  "weights": [0.5]}],
      "nodes": [{"mesh": 0, "skin": 0, "children": [1], "translation": [1, 0, 0]}, {"rotation": [0, 0, 0, 1]}],
      "skins": [{"joints": [1]}],
      "animations": [{"samplers": [{"input": 2, "output": 2, "interpolation": "LINEAR"}],
                      "channels": [{"sampler": 0, "target": {"node": 0, "path": "weights"}}]}],
      "scenes": [{"nodes": [0]}], "scene": 0
    })");
}

struct GltfCase {
    const char* name;
    std::function<void(json&)> change;
    const char* expected;
};
void PrintTo(const GltfCase& c, std::ostream* os) { *os << c.name; }

class GltfFields : public ::testing::TestWithParam<GltfCase> {};

TEST_P(GltfFields, NamedWithTheFieldAndProblem) {
    json doc = valid_gltf();
    GetParam().change(doc);
    const auto dir = temp_dir(std::string("bad_gltf_") + GetParam().name);
    expect_error(write_file(dir / "model.gltf", doc.dump()), GetParam().expected);
}

const GltfCase kGltfCases[] = {
    {"negative_count", [](json& d) { d["accessors"][1]["count"] = -3; },
     "accessors[1].count: expected a non-negative integer, got -3"},
    {"float_count", [](json& d) { d["accessors"][0]["count"] = 3.0; },
     "accessors[0].count: expected a non-negative integer, got 3.0"},
    {"string_for_number", [](json& d) { d["accessors"][0]["componentType"] = "5126"; },
     "accessors[0].componentType: expected a component type, got a string"},
    {"number_for_string", [](json& d) { d["accessors"][0]["type"] = 3; }, "accessors[0].type: expected a string, got 3"},
    {"unknown_type", [](json& d) { d["accessors"][0]["type"] = "VEC5"; },
     "accessors[0].type: expected one of SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3, MAT4, got 'VEC5'"},
    {"object_for_array", [](json& d) { d["meshes"] = d["meshes"][0]; }, "meshes: expected an array, got an object"},
    {"object_for_children", [](json& d) { d["nodes"][0]["children"] = json::object({{"0", 1}}); },
     "nodes[0].children: expected an array, got an object"},
    {"string_index", [](json& d) { d["bufferViews"][0]["buffer"] = "0"; },
     "bufferViews[0].buffer: expected the index of a buffer, got a string"},
    {"index_out_of_range", [](json& d) { d["meshes"][0]["primitives"][0]["indices"] = 7; },
     "meshes[0].primitives[0].indices: accessor 7 does not exist (the file has 3 of them)"},
    {"short_translation", [](json& d) { d["nodes"][0]["translation"] = {1, 2}; },
     "nodes[0].translation: expected 3 numbers, got 2"},
    {"string_in_matrix", [](json& d) { d["nodes"][1]["matrix"] = {1, 0, 0, "x", 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; },
     "nodes[1].matrix[3]: expected a finite number, got a string"},
    // A node's transform as glTF requires it (each was drawn without a word).
    {"matrix_fourth_row",
     [](json& d) {
         d["nodes"][1].erase("rotation");
         d["nodes"][1]["matrix"] = {1, 0, 0, 0.5, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};  // column-major: 0.5 in the fourth row
     },
     "nodes[1].matrix: its fourth row (elements 3, 7, 11, 15) is (0.5, 0, 0, 1); glTF requires (0, 0, 0, 1)"},
    {"matrix_and_trs", [](json& d) { d["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; },
     "nodes[0]: has both a matrix and translation; glTF allows a matrix or translation, rotation and scale, not both"},
    {"zero_rotation", [](json& d) { d["nodes"][1]["rotation"] = {0, 0, 0, 0}; },
     "nodes[1].rotation: (0, 0, 0, 0) has length 0; glTF requires a unit quaternion"},
    {"long_rotation", [](json& d) { d["nodes"][1]["rotation"] = {0, 0, 0, 2}; },
     "nodes[1].rotation: (0, 0, 0, 2) has length 2; glTF requires a unit quaternion"},
    {"bad_mode", [](json& d) { d["meshes"][0]["primitives"][0]["mode"] = 9; },
     "meshes[0].primitives[0].mode: expected a primitive mode from 0 to 6, got 9"},
    {"missing_default_scene", [](json& d) { d["scene"] = 5; }, "scene: scene 5 does not exist (the file has 1 of them)"},
    {"missing_count", [](json& d) { d["accessors"][2].erase("count"); }, "accessors[2].count: missing (it is required)"},
    {"bad_stride", [](json& d) { d["bufferViews"][0]["byteStride"] = 2; },
     "bufferViews[0].byteStride: expected an integer from 4 to 252, got 2"},
    {"version_number", [](json& d) { d["asset"]["version"] = 2; }, "asset.version: expected a string, got 2"},
    {"version_3", [](json& d) { d["asset"]["version"] = "3.0"; }, "asset.version: glTF '3.0' is not supported (only 2.x)"},
    // Animation fields, for JSON type and index range.
    {"skin_joint_range", [](json& d) { d["skins"][0]["joints"] = {5}; },
     "skins[0].joints[0]: node 5 does not exist (the file has 2 of them)"},
    {"skin_joints_object", [](json& d) { d["skins"][0]["joints"] = json::object(); },
     "skins[0].joints: expected a non-empty array, got an object"},
    {"channel_sampler_range", [](json& d) { d["animations"][0]["channels"][0]["sampler"] = 2; },
     "animations[0].channels[0].sampler: sampler 2 does not exist (the animation has 1)"},
    {"channel_path", [](json& d) { d["animations"][0]["channels"][0]["target"]["path"] = "position"; },
     "animations[0].channels[0].target.path: expected one of translation, rotation, scale, weights, got 'position'"},
    {"sampler_input_string", [](json& d) { d["animations"][0]["samplers"][0]["input"] = "2"; },
     "animations[0].samplers[0].input: expected the index of an accessor, got a string"},
    {"interpolation", [](json& d) { d["animations"][0]["samplers"][0]["interpolation"] = "linear"; },
     "animations[0].samplers[0].interpolation: expected one of LINEAR, STEP, CUBICSPLINE, got 'linear'"},
    {"morph_target_index", [](json& d) { d["meshes"][0]["primitives"][0]["targets"][0]["POSITION"] = -1; },
     "meshes[0].primitives[0].targets[0].POSITION: expected the index of an accessor, got -1"},
    {"mesh_weights", [](json& d) { d["meshes"][0]["weights"] = {"half"}; },
     "meshes[0].weights[0]: expected a finite number, got a string"},
    {"node_weights", [](json& d) { d["nodes"][0]["weights"] = json::object(); },
     "nodes[0].weights: expected an array, got an object"},
    // Extensions.
    {"misspelt_used", [](json& d) { d["extensionsUsed"] = {"KHR_mesh_quantisation"}; },
     "extensionsUsed[0]: unknown extension 'KHR_mesh_quantisation'; did you mean 'KHR_mesh_quantization'?"},
    {"malformed_used", [](json& d) { d["extensionsUsed"] = {"khr_materials_unlit"}; },
     "extensionsUsed[0]: 'khr_materials_unlit' is not an extension name (PREFIX_name, e.g. KHR_materials_unlit); "
     "did you mean 'KHR_materials_unlit'?"},
    {"used_not_array", [](json& d) { d["extensionsUsed"] = "KHR_materials_unlit"; },
     "extensionsUsed: expected an array of extension names, got a string"},
    {"used_number", [](json& d) { d["extensionsUsed"] = {5}; },
     "extensionsUsed[0]: expected an extension name (a string), got a number"},
    {"required_not_used", [](json& d) { d["extensionsRequired"] = {"KHR_materials_unlit"}; },
     "extensionsRequired[0]: 'KHR_materials_unlit' is required but not listed in extensionsUsed"},
    {"required_unsupported",
     [](json& d) {
         d["extensionsUsed"] = {"KHR_animation_pointer"};
         d["extensionsRequired"] = {"KHR_animation_pointer"};
     },
     "extensionsRequired[0]: the file requires extension 'KHR_animation_pointer', which stipple does not support"},
    // Counts beyond the data.
    {"count_beyond_view", [](json& d) { d["accessors"][0]["count"] = 100000000; },
     "accessors[0].count: 100000000 elements of 12 bytes (12 apart) from byteOffset 0 do not fit in buffer view 0 (36 bytes)"},
    {"view_beyond_buffer", [](json& d) { d["bufferViews"][2]["byteLength"] = 4096; },
     "bufferViews[2]: byteOffset 44 + byteLength 4096 reaches past the end of buffer 0 (52 bytes)"},
    {"buffer_beyond_data", [](json& d) { d["buffers"][0]["byteLength"] = 1099511627776; },
     "buffers[0].byteLength: 1099511627776 bytes, but its data: URI holds only 54"},
    // Data that is not base64 was reported as a short buffer, or with tinygltf's message quoting the whole URI.
    {"data_uri_not_base64",
     [](json& d) {
         std::string uri = d["buffers"][0]["uri"];
         uri[uri.find(',') + 5] = '@';
         d["buffers"][0]["uri"] = uri;
     },
     "buffers[0].uri: its data: URI is not base64 ('@' at character 5 of the data)"},
    // glTF reads an accessor in whole components: one 2 bytes into a float was read as other data.
    {"misaligned_accessor",
     [](json& d) {
         d["bufferViews"][0]["byteLength"] = 44;
         d["accessors"][0]["byteOffset"] = 2;
     },
     "accessors[0].byteOffset: 2 is not a multiple of its component's 4 bytes"},
};

INSTANTIATE_TEST_SUITE_P(Gltf, GltfFields, ::testing::ValuesIn(kGltfCases),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(GltfFields, ValidDocumentAndIgnorableRequiredExtensionLoad) {
    const auto dir = temp_dir("bad_gltf_valid");
    json doc = valid_gltf();
    doc["extensionsUsed"] = {"KHR_materials_unlit", "VENDOR_own_extension"};
    doc["extensionsRequired"] = {"KHR_materials_unlit"};  // materials do not change the geometry
    const Mesh m = stipple::load_mesh(write_file(dir / "model.gltf", doc.dump()));
    EXPECT_EQ(m.triangle_count(), 1u);
    EXPECT_EQ(m.positions[1], glm::vec3(2, 0, 0));  // node 0 moves the triangle by +1 in x
}

// A rotation rounded as exporters round it, and a matrix whose fourth row is (0, 0, 0, 1) to within
// rounding, load.
TEST(GltfFields, RoundedTransformsLoad) {
    const auto dir = temp_dir("bad_gltf_rounded");
    json doc = valid_gltf();
    doc["nodes"][1]["rotation"] = {0, 0, 0.7071, 0.7071};
    doc["nodes"][0].erase("translation");
    doc["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 1e-5, 1, 0, 0, 1.0001};
    const Mesh m = stipple::load_mesh(write_file(dir / "model.gltf", doc.dump()));
    EXPECT_EQ(m.triangle_count(), 1u);
}

TEST(GltfFields, DeepNestingIsRefused) {
    const auto dir = temp_dir("bad_gltf_deep");
    json doc = valid_gltf();
    json deep = json::array();
    for (int i = 0; i < 100; ++i) deep = json::array({deep});
    doc["extras"] = deep;
    expect_error(write_file(dir / "deep.gltf", doc.dump()), "JSON nested more than 64 levels deep");
}

TEST(GltfFields, InvalidJsonIsNamed) {
    const auto dir = temp_dir("bad_gltf_json");
    expect_error(write_file(dir / "cut.gltf", valid_gltf().dump().substr(0, 40)), "not valid JSON: ");
    // Cut inside a data: URI of 100 kB: what it last read is quoted in its first characters, not whole (a
    // line of 1,000 characters, most of them base64).
    json doc = valid_gltf();
    doc["buffers"][0]["uri"] = doc["buffers"][0]["uri"].get<std::string>() + std::string(100000, 'A');
    const std::string text = doc.dump();
    const std::string message = load_error(write_file(dir / "cut_uri.gltf", text.substr(0, text.find("AAAAAAAAAA") + 50000)));
    EXPECT_NE(message.find("not valid JSON: "), std::string::npos) << message;
    EXPECT_NE(message.find("; last read: '\"data:application/octet-stream;base64,"), std::string::npos) << message;
    EXPECT_LE(message.size(), 400u) << message;
}

// A .glb cut within its 12-byte header was said not to start with 'glTF', which it does.
TEST(GltfFields, GlbCutWithinItsHeaderIsSaidSo) {
    const auto dir = temp_dir("bad_glb_header");
    ByteWriter w;
    w.put<uint32_t>(0x46546C67).put<uint32_t>(2);
    expect_error(write_file(dir / "cut.glb", w.bytes() + "ab"), "GLB header: the file ends after 10 bytes, within its 12-byte header");
}

// ---------------------------------------------------------------- glTF 1.0

TEST(Gltf1, VersionOneJson) {
    const auto dir = temp_dir("bad_gltf1_json");
    json doc = valid_gltf();
    doc["asset"]["version"] = "1.0";
    expect_error(write_file(dir / "old.gltf", doc.dump()), "glTF 1.0 is not supported (convert to glTF 2.0)");
    // glTF 1.0 files without a version keep their objects in dictionaries.
    expect_error(write_file(dir / "dict.gltf", R"({"meshes": {"m": {"primitives": []}}, "accessors": {}})"),
                 "glTF 1.0 is not supported (convert to glTF 2.0)");
}

TEST(Gltf1, VersionOneBinary) {
    const auto dir = temp_dir("bad_gltf1_glb");
    ByteWriter w;
    w.put<uint32_t>(0x46546C67).put<uint32_t>(1).put<uint32_t>(36).put<uint32_t>(16).put<uint32_t>(0);
    expect_error(write_file(dir / "old.glb", w.bytes() + R"({"asset":{}}    )"),
                 "glTF 1.0 is not supported (convert to glTF 2.0)");
}

// ---------------------------------------------------------------- counts beyond the file

TEST(CountsBeyondTheFile, PlyClaiming2To31VerticesIn128Bytes) {
    const auto dir = temp_dir("bad_ply_2_31");
    const std::string header =
        "ply\nformat binary_little_endian 1.0\nelement vertex 2147483648\nproperty float x\nproperty float y\n"
        "property float z\nend_header\n";
    const std::string path = write_file(dir / "claims.ply", header + std::string(128 - header.size(), '\0'));
    expect_error(path, "header claims 2147483648 vertices, more than the file can hold");
}

TEST(CountsBeyondTheFile, ObjIndexFarBeyondItsVertices) {
    const auto dir = temp_dir("bad_obj_far_index");
    expect_error(write_file(dir / "far.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2147483647\n"),
                 "face 1 (line 4) refers to vertex 2147483647 but there are only 3 vertices");
}

TEST(CountsBeyondTheFile, GlbBinChunkLongerThanTheFile) {
    const auto dir = temp_dir("bad_glb_bin");
    const std::string json_text = valid_gltf().dump();
    std::string glb = stipple::test::make_glb(json_text, std::string(8, '\0'));
    const size_t bin_length_at = glb.size() - 16;  // the BIN chunk's length field, before its type and 8 bytes
    glb[bin_length_at + 3] = '\x7f';  // ~2 GB
    expect_error(write_file(dir / "long.glb", glb), "GLB: the BIN chunk's length 2130706440 reaches past the end of the file");
}

}  // namespace
