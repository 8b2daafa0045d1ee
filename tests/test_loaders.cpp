// Model loaders: every format on small files written here, every kind of bad input, and the
// shared real models (skipped when they are not there).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>

#include "core/error.hpp"
#include "mesh/load_mesh.hpp"
#include "mesh/orientation.hpp"
#include "support/model_files.hpp"
#include "support/test_paths.hpp"

namespace {

using stipple::load_mesh;
using stipple::Mesh;
using stipple::test::ByteWriter;
using stipple::test::temp_dir;
using stipple::test::write_file;

// The message load_mesh throws for `path`, or "" (and a test failure) when it loads.
std::string load_error(const std::string& path) {
    try {
        load_mesh(path);
    } catch (const stipple::Error& e) {
        return e.what();
    }
    ADD_FAILURE() << path << " loaded without an error";
    return "";
}

void expect_load_error(const std::string& path, const std::string& phrase) {
    const std::string message = load_error(path);
    EXPECT_NE(message.find(path + ": "), std::string::npos) << "message does not name the file: " << message;
    EXPECT_NE(message.find(phrase), std::string::npos) << "expected '" << phrase << "' in: " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "message is not one line: " << message;
}

void expect_unit_normals(const Mesh& mesh) {
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    for (const glm::vec3& n : mesh.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
}

glm::vec3 face_normal(const Mesh& m, size_t t) {
    const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                    c = m.positions[m.indices[3 * t + 2]];
    return glm::cross(b - a, c - a);
}

// ---------------------------------------------------------------- OBJ

TEST(ObjLoader, TrianglesWithNormalsKeepFileNormals) {
    const auto dir = temp_dir("loaders_obj_normals");
    const std::string path = write_file(dir / "tri.OBJ",  // extensions are case-insensitive
                                        "# a triangle\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 2\nf 1//1 2//1 3//1\n");
    const Mesh m = load_mesh(path);
    EXPECT_EQ(m.triangle_count(), 1u);
    EXPECT_EQ(m.vertex_count(), 3u);
    EXPECT_EQ(m.source, path);
    expect_unit_normals(m);
    EXPECT_NEAR(m.normals[0].z, 1.0f, 1e-6f);  // the file's normal, normalised
}

TEST(ObjLoader, QuadsAreTriangulatedAndNormalsComputed) {
    const auto dir = temp_dir("loaders_obj_quads");
    // A unit cube of six quads, outward winding, no normals.
    const std::string path = write_file(dir / "cube.obj",
                                        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                                        "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
    const Mesh m = load_mesh(path);
    EXPECT_EQ(m.triangle_count(), 12u);
    EXPECT_EQ(m.vertex_count(), 8u);
    expect_unit_normals(m);
    const glm::vec3 center(0.5f);
    for (size_t i = 0; i < m.vertex_count(); ++i)  // computed normals point out of the cube
        EXPECT_GT(glm::dot(m.normals[i], m.positions[i] - center), 0.0f);
}

TEST(ObjLoader, NormalsOnSomeFacesOnlyAreRecomputed) {
    const auto dir = temp_dir("loaders_obj_mixed");
    const std::string path = write_file(dir / "mixed.obj",
                                        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 1 0 0\nf 1//1 2//1 3//1\nf 2 4 3\n");
    const Mesh m = load_mesh(path);
    EXPECT_EQ(m.triangle_count(), 2u);
    EXPECT_EQ(m.vertex_count(), 4u);
    expect_unit_normals(m);
    for (const glm::vec3& n : m.normals) EXPECT_NEAR(n.z, 1.0f, 1e-6f);  // computed, not the file's +X
}

TEST(ObjLoader, ZeroAreaTriangleIsKept) {
    const auto dir = temp_dir("loaders_obj_zero_area");
    const std::string path =
        write_file(dir / "flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n");
    const Mesh m = load_mesh(path);
    EXPECT_EQ(m.triangle_count(), 2u);
    EXPECT_DOUBLE_EQ(stipple::triangle_area(m, 0), 0.0);
    EXPECT_DOUBLE_EQ(stipple::total_area(m), 0.5);
    expect_unit_normals(m);
}

// Concave polygons are cut inside themselves, wherever they lie (the ear test of the library used until
// 2026-12-03 depended on the polygon's place: an L of area 3 away from the origin loaded as one triangle
// of area 1, a U of area 5 as area 7, and a concave quad was split along its shorter diagonal, outside it).
TEST(ObjLoader, ConcavePolygonsAreCutInsideThemselves) {
    const auto dir = temp_dir("loaders_obj_concave");
    const std::string path = write_file(dir / "concave.obj",
                                        "# an L of area 3 at (-5, 5), a U of area 5 at (5, -5), a dart of area 1\n"
                                        "v -5 5 0\nv -3 5 0\nv -3 6 0\nv -4 6 0\nv -4 7 0\nv -5 7 0\n"
                                        "v 5 -5 0\nv 8 -5 0\nv 8 -3 0\nv 7 -3 0\nv 7 -4 0\nv 6 -4 0\nv 6 -3 0\nv 5 -3 0\n"
                                        "v 20 0 0\nv 22 0 0\nv 20.5 0.5 0\nv 20 2 0\n"
                                        "f 1 2 3 4 5 6\nf 7 8 9 10 11 12 13 14\nf 15 16 17 18\n");
    const Mesh m = load_mesh(path);
    EXPECT_EQ(m.triangle_count(), 4u + 6u + 2u);
    EXPECT_NEAR(stipple::total_area(m), 3.0 + 5.0 + 1.0, 1e-6);
}

// What OBJ writers put around the numbers: a byte-order mark, a line continued with a backslash, comments
// at the end of a line, tags, colours after a vertex, values below float's range (read as 0).
TEST(ObjLoader, ReadsTheFileAroundItsNumbers) {
    const auto dir = temp_dir("loaders_obj_around");
    std::string tags;
    for (int i = 0; i < 200; ++i) tags += "t crease 8192/8192/8192\n";  // 320 KB each in the library used before
    const std::string path = write_file(dir / "around.obj", "\xEF\xBB\xBF# from C:\\models\\\nv 0 0 0 # origin\nv 1 0 \\\n  1e-50 0.5 0.5 0.5\n"
                                                            "v 0 1 0\n" + tags + "f 1 2 \\\n 3 # the only face\n");
    const Mesh m = load_mesh(path);
    ASSERT_EQ(m.triangle_count(), 1u);
    EXPECT_DOUBLE_EQ(stipple::total_area(m), 0.5);
    EXPECT_EQ(m.positions[1].z, 0.0f);
}

// A backslash at the very end of the file continues the line into nothing: the line ends there (it was
// read as a vertex index '\\' until 2026-12-04).
TEST(ObjLoader, AContinuationAtTheEndOfTheFileEndsTheLine) {
    const auto dir = temp_dir("loaders_obj_continued_end");
    for (const std::string end : {"f 1 2 3 \\", "f 1 2 3 \\\n", "f 1 2 \\\n3 \\\n"}) {
        const Mesh m = load_mesh(write_file(dir / "continued.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n" + end));
        EXPECT_EQ(m.triangle_count(), 1u) << end;
    }
}

// A normal that is not a number is refused where it stands; one that is NaN (read as such, not as 0)
// makes the loader compute every normal.
TEST(ObjLoader, NormalsAreReadAsWritten) {
    const auto dir = temp_dir("loaders_obj_vn");
    expect_load_error(write_file(dir / "garbage.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn garbage 1 0\nf 1//1 2//1 3//1\n"),
                      "normal 1 (line 4): 'garbage' is not a number");
    expect_load_error(write_file(dir / "short.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 1\nf 1//1 2//1 3//1\n"),
                      "normal 1 (line 4) has fewer than 3 components");
    expect_load_error(write_file(dir / "signs.obj", "v +-1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), "vertex 1 (line 1): '+-1' is not a number");
    // NaN, and beyond float's range (infinite): every normal is computed from the faces instead.
    for (const char* component : {"nan", "1e50"}) {
        const Mesh m = load_mesh(write_file(dir / "bad_normal.obj", std::string("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 ") + component +
                                                                       " 1\nf 1//1 2//1 3//1\n"));
        ASSERT_EQ(m.normals.size(), 3u);
        for (const glm::vec3& n : m.normals) EXPECT_NEAR(n.z, 1.0f, 1e-6f) << component;  // not the file's (0, ?, 1)
    }
}

// ---------------------------------------------------------------- PLY

TEST(PlyLoader, AsciiWithCommentsExtraPropertiesAndElements) {
    const auto dir = temp_dir("loaders_ply_ascii");
    const std::string path = write_file(dir / "tetra.ply",
                                        "ply\nformat ascii 1.0\ncomment made by hand\nobj_info test\n"
                                        "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                                        "property uchar red\nelement face 4\nproperty list uchar int vertex_indices\n"
                                        "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n"
                                        "0 0 0 255\n1 0 0 0\n0 1 0 0\n0 0 1 7\n"
                                        "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
                                        "0 1\n");
    const Mesh m = load_mesh(path);
    EXPECT_EQ(m.triangle_count(), 4u);
    EXPECT_EQ(m.vertex_count(), 4u);
    EXPECT_EQ(m.positions[3], glm::vec3(0, 0, 1));
    expect_unit_normals(m);
}

// The tetrahedron with normals, in either byte order, with mixed scalar types and properties and
// elements the loader must skip.
std::string binary_tetra_ply(bool big_endian, float first_x = 0.0f) {
    std::string ply = std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
                      " 1.0\nelement vertex 4\nproperty double x\nproperty float32 y\nproperty float z\n"
                      "property float nx\nproperty float ny\nproperty float nz\nproperty uint8 quality\n"
                      "element face 4\nproperty uchar flags\nproperty list uint8 uint32 vertex_indices\n"
                      "element extra 2\nproperty list ushort short data\nend_header\n";
    ByteWriter w(big_endian);
    const float p[4][3] = {{first_x, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (const auto& v : p) {
        w.put<double>(v[0]).put<float>(v[1]).put<float>(v[2]);
        w.put<float>(v[0] - 0.25f).put<float>(v[1] - 0.25f).put<float>(v[2] - 0.25f).put<uint8_t>(9);
    }
    const uint32_t faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    for (const auto& f : faces) w.put<uint8_t>(0).put<uint8_t>(3).put<uint32_t>(f[0]).put<uint32_t>(f[1]).put<uint32_t>(f[2]);
    w.put<uint16_t>(2).put<int16_t>(-1).put<int16_t>(5).put<uint16_t>(0);
    return ply + w.bytes();
}

class PlyBinary : public ::testing::TestWithParam<bool> {};

TEST_P(PlyBinary, ReadsPositionsNormalsAndFaces) {
    const auto dir = temp_dir(GetParam() ? "loaders_ply_be" : "loaders_ply_le");
    const std::string path = write_file(dir / "tetra.ply", binary_tetra_ply(GetParam()));
    const Mesh m = load_mesh(path);
    EXPECT_EQ(m.triangle_count(), 4u);
    ASSERT_EQ(m.vertex_count(), 4u);
    EXPECT_EQ(m.positions[1], glm::vec3(1, 0, 0));
    EXPECT_EQ(m.positions[3], glm::vec3(0, 0, 1));
    EXPECT_EQ(m.indices[0], 0u);
    EXPECT_EQ(m.indices[1], 2u);
    expect_unit_normals(m);
    // The file's normals (v - 0.25, normalised), not computed ones.
    EXPECT_NEAR(m.normals[1].x, glm::normalize(glm::vec3(0.75f, -0.25f, -0.25f)).x, 1e-6f);
}

INSTANTIATE_TEST_SUITE_P(ByteOrder, PlyBinary, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "BigEndian" : "LittleEndian"; });

TEST(PlyLoader, PolygonsAreFanTriangulated) {
    const auto dir = temp_dir("loaders_ply_polygons");
    const std::string path = write_file(dir / "poly.ply",
                                        "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
                                        "property float z\nelement face 2\nproperty list uchar uint vertex_index\n"
                                        "end_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 2 0\n4 0 1 2 3\n5 1 2 4 3 0\n");
    // (The pentagon overlaps the quad; started at corner 0 its first triangle would repeat the quad's, and
    // loading drops repeated faces.)
    const Mesh m = load_mesh(path);
    EXPECT_EQ(m.triangle_count(), 2u + 3u);
    const std::vector<uint32_t> fans = {0, 1, 2, 0, 2, 3, 1, 2, 4, 1, 4, 3, 1, 3, 0};
    EXPECT_EQ(m.indices, fans);
}

TEST(PlyLoader, TriangleStripsWithSeparatorsAndDegenerates) {
    const auto dir = temp_dir("loaders_ply_strips");
    // A 3x2 grid of points in z = 0; the strips zig-zag so that every triangle faces +Z.
    // Strip one ends with a repeated corner (two degenerate joins, dropped).
    const std::string path = write_file(dir / "strips.ply",
                                        "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\n"
                                        "property float z\nelement tristrips 1\nproperty list int int vertex_indices\n"
                                        "end_header\n0 0 0\n0 1 0\n1 0 0\n1 1 0\n2 0 0\n2 1 0\n"
                                        "11 1 0 3 2 2 3 -1 3 2 5 4\n");
    const Mesh m = load_mesh(path);
    ASSERT_EQ(m.triangle_count(), 4u);
    const std::vector<uint32_t> expected = {1, 0, 3, 3, 0, 2, 3, 2, 5, 5, 2, 4};
    EXPECT_EQ(m.indices, expected);
    for (size_t t = 0; t < m.triangle_count(); ++t) EXPECT_GT(face_normal(m, t).z, 0.0f) << "triangle " << t;
    for (const glm::vec3& n : m.normals) EXPECT_NEAR(n.z, 1.0f, 1e-6f);
    EXPECT_DOUBLE_EQ(stipple::total_area(m), 2.0);
}

// -1 in an unsigned list is its all-ones value: a ushort list's 65535 and a uchar list's 255 restart the strip
// (both were refused as "refers to vertex 65535" until 2026-12-04).
TEST(PlyLoader, TriangleStripRestartsInNarrowUnsignedLists) {
    const auto dir = temp_dir("loaders_ply_strip_restart");
    for (const auto& [type, restart] : {std::pair<std::string, std::string>{"ushort", "65535"}, {"uchar", "255"}}) {
        const std::string path = write_file(dir / ("strips_" + type + ".ply"),
                                            "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\n"
                                            "property float z\nelement tristrips 1\nproperty list int " + type +
                                                " vertex_indices\nend_header\n0 0 0\n0 1 0\n1 0 0\n1 1 0\n2 0 0\n2 1 0\n"
                                                "9 1 0 3 2 " + restart + " 3 2 5 4\n");
        const Mesh m = load_mesh(path);
        ASSERT_EQ(m.triangle_count(), 4u) << type;
        EXPECT_DOUBLE_EQ(stipple::total_area(m), 2.0) << type;
    }
}

// ---------------------------------------------------------------- glTF

// A glTF document around one buffer; `buffer` is the JSON of buffers[0].
std::string gltf_json(const std::string& buffer, const std::string& rest) {
    return R"({"asset":{"version":"2.0"},"buffers":[)" + buffer + "]," + rest + "}";
}

std::string embedded(const std::string& bytes) {
    return R"({"byteLength":)" + std::to_string(bytes.size()) + R"(,"uri":"data:application/octet-stream;base64,)" +
           stipple::test::base64(bytes) + "\"}";
}

TEST(GltfLoader, EmbeddedBufferIndexedTrianglesAndStrip) {
    const auto dir = temp_dir("loaders_gltf_embedded");
    ByteWriter w;
    for (float v : {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}) w.put<float>(v);  // quad, counter-clockwise
    for (float v : {0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1}) w.put<float>(v);  // zig-zag for a strip, z = 1
    for (uint16_t i : {0, 1, 2, 0, 2, 3}) w.put<uint16_t>(i);
    const std::string json = gltf_json(
        embedded(w.bytes()),
        R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":96,"byteStride":12},{"buffer":0,"byteOffset":96,"byteLength":12}],)"
        R"("accessors":[{"bufferView":0,"byteOffset":0,"componentType":5126,"count":4,"type":"VEC3"},)"
        R"({"bufferView":0,"byteOffset":48,"componentType":5126,"count":4,"type":"VEC3"},)"
        R"({"bufferView":1,"componentType":5123,"count":6,"type":"SCALAR"}],)"
        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":2},{"attributes":{"POSITION":1},"mode":5}]}],)"
        R"("nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}])");
    const Mesh m = load_mesh(write_file(dir / "quad.gltf", json));
    EXPECT_EQ(m.triangle_count(), 4u);
    EXPECT_EQ(m.vertex_count(), 8u);
    expect_unit_normals(m);
    for (size_t t = 0; t < m.triangle_count(); ++t) EXPECT_GT(face_normal(m, t).z, 0.0f) << "triangle " << t;
    const stipple::Bounds b = stipple::compute_bounds(m);
    EXPECT_EQ(b.min, glm::vec3(0, 0, 0));
    EXPECT_EQ(b.max, glm::vec3(1, 1, 1));
}

TEST(GltfLoader, GlbNodeTransformsInterleavedNormalsAndSkippedLines) {
    const auto dir = temp_dir("loaders_gltf_glb");
    ByteWriter w;  // position and normal interleaved, stride 24
    for (float v : {0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 1}) w.put<float>(v);
    for (uint8_t i : {0, 1, 2}) w.put<uint8_t>(i);
    const std::string json =
        R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":75}],)"
        R"("bufferViews":[{"buffer":0,"byteLength":72,"byteStride":24},{"buffer":0,"byteOffset":72,"byteLength":3}],)"
        R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},)"
        R"({"bufferView":0,"byteOffset":12,"componentType":5126,"count":3,"type":"VEC3"},)"
        R"({"bufferView":1,"componentType":5121,"count":3,"type":"SCALAR"}],)"
        R"("meshes":[{"name":"shape","primitives":[{"attributes":{"POSITION":0,"NORMAL":1},"indices":2},)"
        R"({"attributes":{"POSITION":0},"mode":1}]}],)"
        // Parent moves by +10 in x; the child scales by 2 and turns 90 degrees about z.
        R"("nodes":[{"translation":[10,0,0],"children":[1]},)"
        R"({"mesh":0,"scale":[2,2,2],"rotation":[0,0,0.70710678,0.70710678]}],)"
        R"("scenes":[{"nodes":[]},{"nodes":[0]}],"scene":1})";
    const std::string path = write_file(dir / "scene.glb", stipple::test::make_glb(json, w.bytes()));
    ::testing::internal::CaptureStderr();
    const Mesh m = load_mesh(path);
    const std::string warnings = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(warnings.find(path + ": warning: skipping mesh 'shape' primitive 1 (mode LINES)"), std::string::npos)
        << warnings;
    EXPECT_EQ(m.triangle_count(), 1u);
    const stipple::Bounds b = stipple::compute_bounds(m);  // (0,0),(2,0),(0,2) -> (10,0),(10,2),(8,0)
    EXPECT_NEAR(b.min.x, 8.0f, 1e-5f);
    EXPECT_NEAR(b.min.y, 0.0f, 1e-5f);
    EXPECT_NEAR(b.max.x, 10.0f, 1e-5f);
    EXPECT_NEAR(b.max.y, 2.0f, 1e-5f);
    expect_unit_normals(m);
    for (const glm::vec3& n : m.normals) EXPECT_NEAR(n.z, 1.0f, 1e-5f);
}

std::string one_triangle_gltf(const std::string& mode, uint8_t last_index) {
    ByteWriter w;
    for (float v : {0, 0, 0, 1, 0, 0, 0, 1, 0}) w.put<float>(v);
    for (uint8_t i : {uint8_t(0), uint8_t(1), last_index}) w.put<uint8_t>(i);
    return gltf_json(embedded(w.bytes()),
                     R"("bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":3}],)"
                     R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},)"
                     R"({"bufferView":1,"componentType":5121,"count":3,"type":"SCALAR"}],)"
                     R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1,"mode":)" +
                         mode + "}]}]");  // no scenes: every mesh once
}

// A triangle placed 90,000 units out by its node keeps its shape (stored about its own centre, Mesh::origin):
// the placed positions were rounded to float, 1/128 of a unit there (until 2026-12-07).
TEST(GltfLoader, AModelPlacedFarByItsNodeKeepsItsShape) {
    // A fourth vertex no face uses, at the node's origin: the model's place is its faces' (the far origin was
    // measured on every vertex, and this one made the triangle look near the origin).
    ByteWriter w;
    for (float v : {0.1f, 0.0f, 0.0f, 1.3f, 0.0f, 0.0f, 0.1f, 0.7f, 0.0f, -90000.0f, 0.0f, 0.0f}) w.put<float>(v);
    for (uint8_t i : {0, 1, 2}) w.put<uint8_t>(i);
    const std::string json = gltf_json(
        embedded(w.bytes()), R"("bufferViews":[{"buffer":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":3}],)"
                             R"("accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3"},)"
                             R"({"bufferView":1,"componentType":5121,"count":3,"type":"SCALAR"}],)"
                             R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],)"
                             R"("nodes":[{"mesh":0,"translation":[90000,0,0]}],"scenes":[{"nodes":[0]}])");
    const Mesh m = load_mesh(write_file(temp_dir("loaders_gltf_far") / "far.gltf", json));
    ASSERT_EQ(m.triangle_count(), 1u);
    EXPECT_GT(m.origin.x, 89000.0);
    const double x[3] = {90000.0 + double(0.1f), 90000.0 + double(1.3f), 90000.0 + double(0.1f)};
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(double(m.positions[i].x) + m.origin.x, x[i], 1e-5) << i;
}

TEST(GltfLoader, ExternalBufferFile) {
    const auto dir = temp_dir("loaders_gltf_external");
    ByteWriter w;
    for (float v : {0, 0, 0, 1, 0, 0, 0, 1, 0}) w.put<float>(v);
    write_file(dir / "tri.bin", w.bytes());
    const std::string json = gltf_json(
        R"({"byteLength":36,"uri":"tri.bin"})",
        R"("bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}],)"
        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}])");
    const Mesh m = load_mesh(write_file(dir / "tri.gltf", json));
    EXPECT_EQ(m.triangle_count(), 1u);
    EXPECT_EQ(m.positions[1], glm::vec3(1, 0, 0));
}

// External files are resolved once, by stipple, as the validator resolves them: '+' is itself (tinygltf read
// it as a space), an absolute path stays absolute (tinygltf joined it to the folder, then tried the current
// directory), a file longer than byteLength is read only that far (tinygltf read it whole, then refused it),
// and images, which play no part, are never opened (a directory named as one read as 2^63 bytes and ended
// in 'out of memory'; a FIFO waited for ever).
TEST(GltfLoader, ExternalFilesAreTheOnesTheValidatorChecked) {
    const auto dir = temp_dir("loaders_gltf_external_names");
    ByteWriter w;
    for (float v : {0, 0, 0, 1, 0, 0, 0, 1, 0}) w.put<float>(v);
    const std::string bytes = w.bytes();
    write_file(dir / "a+b.bin", bytes);
    write_file(dir / "long.bin", bytes + std::string(1 << 20, '\x7f'));
    std::filesystem::create_directories(dir / "picture.png");
    const std::string rest =
        R"("bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}],)"
        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],)"
        R"("images":[{"uri":"picture.png"}],"textures":[{"source":0}])";
    for (const std::string& uri : {std::string("a+b.bin"), std::string("a%2Bb.bin"), (dir / "a+b.bin").string(), std::string("long.bin")}) {
        SCOPED_TRACE(uri);
        const Mesh m = load_mesh(write_file(dir / "tri.gltf", gltf_json(R"({"byteLength":36,"uri":")" + uri + "\"}", rest)));
        ASSERT_EQ(m.triangle_count(), 1u);
        EXPECT_EQ(m.positions[1], glm::vec3(1, 0, 0));
    }
    expect_load_error(write_file(dir / "empty.gltf", gltf_json(R"({"byteLength":0,"uri":"a+b.bin"})", rest)),
                      "buffers[0].byteLength: expected a positive integer, got 0");
    expect_load_error(
        write_file(dir / "mime.gltf", gltf_json(R"({"byteLength":36,"uri":"data:application/x-foo;base64,AAAA"})", rest)),
        "buffers[0].uri: a buffer's data: URI must be application/octet-stream or application/gltf-buffer in base64, got "
        "'data:application/x-foo;base64'");
}

TEST(GltfLoader, NodeCycleIsAnError) {
    const auto dir = temp_dir("loaders_gltf_cycle");
    std::string json = one_triangle_gltf("4", 2);
    json.pop_back();  // reopen the document to add a scene whose nodes form a cycle
    json += R"(,"nodes":[{"mesh":0,"children":[1]},{"children":[0]}],"scenes":[{"nodes":[0]}]})";
    expect_load_error(write_file(dir / "cycle.gltf", json), "node 0 is reached twice");
}

TEST(GltfLoader, OnlyPointsIsAnError) {
    const auto dir = temp_dir("loaders_gltf_points");
    ::testing::internal::CaptureStderr();
    expect_load_error(write_file(dir / "points.gltf", one_triangle_gltf("0", 2)),
                      "the model has no triangles, only mesh");
    expect_load_error((dir / "points.gltf").string(), "(mode POINTS): only triangles are drawn");
    // One line in all: the error says what was skipped, with no warning before it.
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}

// ---------------------------------------------------------------- bad input

TEST(BadInput, MissingFile) {
    expect_load_error((temp_dir("loaders_missing") / "nothing.obj").string(), "no such file");
}

TEST(BadInput, EmptyFile) { expect_load_error(write_file(temp_dir("loaders_empty") / "empty.ply", ""), "file is empty"); }

TEST(BadInput, Directory) {
    const auto dir = temp_dir("loaders_directory") / "model.obj";
    std::filesystem::create_directories(dir);
    expect_load_error(dir.string(), "is a directory, not a model file");
}

TEST(BadInput, UnknownExtension) {
    expect_load_error(write_file(temp_dir("loaders_unknown_ext") / "model.3ds", "solid x\n"),
                      "unknown model format '.3ds' (expected .obj, .ply, .gltf, .glb or .stl)");
    // A scene given where a model is asked for (`stipple info scene.json`) is named as what it is.
    expect_load_error(write_file(temp_dir("loaders_scene_ext") / "scene.json", "{}\n"),
                      "is a scene file, not a model (.obj, .ply, .gltf, .glb or .stl)");
}

TEST(BadInput, TruncatedBinaryPly) {
    const std::string ply = binary_tetra_ply(false);
    // Cut inside the last face (the 'extra' element takes the last 8 bytes).
    const std::string path = write_file(temp_dir("loaders_ply_truncated") / "cut.ply", ply.substr(0, ply.size() - 8 - 5));
    expect_load_error(path, "truncated: header promises 4 faces but the file ends after 3");
}

TEST(BadInput, PlyHeaderPromisesMoreFacesThanTheData) {
    const std::string path = write_file(temp_dir("loaders_ply_short") / "short.ply",
                                        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                        "property float z\nelement face 10\nproperty list uchar int vertex_indices\n"
                                        "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n");
    expect_load_error(path, "truncated: header promises 10 faces but the file ends after 2");
}

TEST(BadInput, PlyHeaderClaimsATrillionFacesFailsFast) {
    ByteWriter w;
    for (float v : {0, 0, 0, 1, 0, 0, 0, 1, 0}) w.put<float>(v);
    w.put<uint8_t>(3).put<int32_t>(0).put<int32_t>(1).put<int32_t>(2);
    const std::string path = write_file(temp_dir("loaders_ply_huge") / "huge.ply",
                                        "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                                        "property float y\nproperty float z\nelement face 1000000000000\n"
                                        "property list uchar int vertex_indices\nend_header\n" +
                                            w.bytes());
    const auto start = std::chrono::steady_clock::now();
    expect_load_error(path, "header claims 1000000000000 faces, more than the file can hold");
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 0.5);
}

TEST(BadInput, CountAboveTheElementLimit) {
    stipple::LoadOptions options;
    options.max_elements = 3;
    const std::string path = write_file(temp_dir("loaders_limit") / "tetra.ply", binary_tetra_ply(false));
    try {
        load_mesh(path, options);
        ADD_FAILURE() << "loaded despite the limit";
    } catch (const stipple::Error& e) {
        EXPECT_NE(std::string(e.what()).find(path + ": header claims 4 vertices, more than the limit of 3"),
                  std::string::npos)
            << e.what();
    }
}

TEST(BadInput, GarbageBytes) {
    const auto dir = temp_dir("loaders_garbage");
    std::mt19937 rng(1234);
    std::string bytes(4096, '\0');
    for (char& c : bytes) c = static_cast<char>(rng());
    expect_load_error(write_file(dir / "noise.ply", bytes), "not a PLY file");
    expect_load_error(write_file(dir / "noise.obj", bytes), "not a text OBJ file");
    expect_load_error(write_file(dir / "noise.glb", bytes), "not a binary glTF file");
    expect_load_error(write_file(dir / "noise.gltf", bytes), "not valid JSON");
}

TEST(BadInput, ObjIndexOutOfRange) {
    expect_load_error(write_file(temp_dir("loaders_obj_range") / "range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"),
                      "face 1 (line 4) refers to vertex 9 but there are only 3 vertices");
}

// Texture coordinates play no part in stippling, but an index beyond them is a broken file like any other
// (it loaded without a word). Indices within them, and corners that name none, load.
TEST(BadInput, ObjTextureIndexOutOfRange) {
    const auto dir = temp_dir("loaders_obj_vt_range");
    expect_load_error(write_file(dir / "vt.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/9\n"),
                      "face 1 (line 5) refers to texture coordinate 9 but there are only 1 texture coordinates");
    expect_load_error(write_file(dir / "vt_back.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/-1 2/-1 3/-1\n"),
                      "face 1 (line 4) refers to texture coordinate -1 but only 0 texture coordinates come before it");
    const Mesh ok = load_mesh(write_file(dir / "vt_ok.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvn 0 0 1\n"
                                                           "f 1/1/1 2//1 4/-1 3/\n"));
    EXPECT_EQ(ok.triangle_count(), 2u);  // a quad: "1/" names no texture coordinate
}

TEST(BadInput, PlyIndexOutOfRange) {
    const std::string path = write_file(temp_dir("loaders_ply_range") / "range.ply",
                                        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                        "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                        "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 900\n");
    expect_load_error(path, "face 0 refers to vertex 900 but there are only 3 vertices");
}

TEST(BadInput, GltfIndexOutOfRange) {
    expect_load_error(write_file(temp_dir("loaders_gltf_range") / "range.gltf", one_triangle_gltf("4", 9)),
                      "refers to vertex 9 but there are only 3 vertices");
}

TEST(BadInput, ObjNaNAndInfCoordinates) {
    const auto dir = temp_dir("loaders_obj_nan");
    expect_load_error(write_file(dir / "nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"),
                      "vertex 2 (line 2) has a NaN coordinate");
    expect_load_error(write_file(dir / "inf.obj", "v 0 0 0\nv 1 0 0\nv 0 -inf 0\nf 1 2 3\n"),
                      "vertex 3 (line 3) has an infinite coordinate");
}

// A PLY whose header and data disagree is refused where they part: a count beyond 64 bits (read as 0
// until 2026-12-03, the element then skipped), and an ASCII line with a value more than its element's
// properties (read on, every later element shifted by one and loaded as other numbers).
TEST(BadInput, PlyHeaderAndDataDisagree) {
    const auto dir = temp_dir("loaders_ply_disagree");
    const std::string vertex = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
    const std::string face = "element face 2\nproperty list uchar int vertex_indices\nend_header\n";
    expect_load_error(write_file(dir / "overflow.ply", vertex + "element junk 99999999999999999999\nproperty uchar a\n" + face +
                                                           "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n"),
                      "PLY header line 7: element count '99999999999999999999' is beyond any file");
    expect_load_error(write_file(dir / "shifted.ply", vertex + face + "0 0 0\n1 0 0 7\n0 1 0\n3 0 1 2\n3 0 2 1\n"),
                      "line 11: '7' is one value more than the header gives this element (one element a line)");
    // One short: named at its own line (the next line's first value was read in its place, and that line named).
    expect_load_error(write_file(dir / "short.ply", vertex + face + "0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n"),
                      "line 10: holds fewer values than the header gives this element (one element a line)");
    expect_load_error(write_file(dir / "short_face.ply", vertex + face + "0 0 0\n1 0 0\n0 1 0\n3 0 1\n3 0 2 1\n"),
                      "line 13: holds fewer values than the header gives this element (one element a line)");
    // Still read: a value skipped before x, a list among a vertex's values, CRLF line ends, a strip wrapped over lines.
    const Mesh odd = load_mesh(write_file(
        dir / "odd.ply", "ply\r\nformat ascii 1.0\r\nelement vertex 3\r\nproperty int id\r\nproperty float x\r\nproperty float y\r\n"
                         "property list uchar float extra\r\nproperty float z\r\nelement face 1\r\n"
                         "property list uchar int vertex_indices\r\nend_header\r\n7 0 0 2 0.5 0.5 0\r\n8 1 0 0 0\r\n9 0 1 1 3 0\r\n"
                         "3 0 1 2\r\n"));
    EXPECT_EQ(odd.triangle_count(), 1u);
    EXPECT_EQ(odd.positions[2].y, 1.0f);
    const Mesh wrapped = load_mesh(write_file(
        dir / "wrapped.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                             "element tristrips 1\nproperty list int int vertex_indices\nend_header\n"
                             "0 0 0\n1 0 0\n0 1 0\n1 1 0\n4 0 1\n2 3\n"));
    EXPECT_EQ(wrapped.triangle_count(), 2u);
    // Data after the last element the header declares (a count too small) was dropped without a word: a
    // horse whose header said 1 face loaded as one triangle (until 2026-12-07). Padding after it still loads.
    expect_load_error(write_file(dir / "more_faces.ply", vertex + face + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n3 1 2 0\n"),
                      "line 15: '3' lies after the last element the header declares (its element counts are too small)");
    const std::string tetra = binary_tetra_ply(false);
    expect_load_error(write_file(dir / "more_bytes.ply", tetra + std::string("\x03\x00\x01\x02", 4)),
                      "4 bytes of data after the last element the header declares (its element counts are too small)");
    EXPECT_EQ(load_mesh(write_file(dir / "padded.ply", tetra + std::string("\n\0\0\0", 4))).triangle_count(), 4u);
    EXPECT_EQ(load_mesh(write_file(dir / "blank_lines.ply", vertex + face + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n\n \r\n"))
                  .triangle_count(), 2u);
    EXPECT_EQ(load_mesh(write_file(dir / "dos_end.ply", vertex + face + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n" +
                                                           std::string("\0\0\x1a\f", 4)))
                  .triangle_count(), 2u) << "zero bytes, a DOS end-of-file mark and a form feed are padding";
    // The same data, one element a line, loads; a leading '+' is a number as strtod reads it.
    const std::string one_face = "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const Mesh m = load_mesh(write_file(dir / "plus.ply", vertex + one_face + "+0 0 0\n+1 0 0\n0 +1e0 0\n3 +0 1 2\n"));
    EXPECT_EQ(m.triangle_count(), 1u);
    EXPECT_EQ(m.positions[1].x, 1.0f);
    EXPECT_EQ(m.positions[2].y, 1.0f);
}

TEST(BadInput, PlyBinaryNaNAndInfCoordinates) {
    const auto dir = temp_dir("loaders_ply_nan");
    expect_load_error(write_file(dir / "nan.ply", binary_tetra_ply(false, std::numeric_limits<float>::quiet_NaN())),
                      "vertex 0 has a NaN coordinate");
    expect_load_error(write_file(dir / "inf.ply", binary_tetra_ply(true, std::numeric_limits<float>::infinity())),
                      "vertex 0 has an infinite coordinate");
}

// A model far from the file's origin, written in more than single precision, keeps its shape (stored about
// its own centre, Mesh::origin, as an OBJ is): a double or text PLY was rounded to float where it lay (a unit
// sphere 90,000 units out to 1/128 of a unit, until 2026-12-07).
TEST(PlyLoader, AFarModelInDoublesKeepsItsShape) {
    const auto dir = temp_dir("loaders_ply_far");
    const double x[3] = {90000.1, 90001.3, 90000.1}, y[3] = {0.0, 0.0, 0.7};
    std::string text = "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
                       "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    ByteWriter w;
    for (int i = 0; i < 3; ++i) {
        text += std::to_string(x[i]) + " " + std::to_string(y[i]) + " 0\n";
        w.put<double>(x[i]).put<double>(y[i]).put<double>(0.0);
    }
    w.put<uint8_t>(3).put<int32_t>(0).put<int32_t>(1).put<int32_t>(2);
    std::string binary = text.substr(0, text.find("end_header\n") + 11);
    binary.replace(binary.find("ascii"), 5, "binary_little_endian");
    for (const auto& [name, bytes] : {std::pair{"far_text.ply", text + "3 0 1 2\n"}, std::pair{"far_double.ply", binary + w.bytes()}}) {
        SCOPED_TRACE(name);
        const Mesh m = load_mesh(write_file(dir / name, bytes));
        ASSERT_EQ(m.triangle_count(), 1u);
        EXPECT_GT(m.origin.x, 89000.0) << "stored about its own centre";
        for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(double(m.positions[i].x) + m.origin.x, x[i], 1e-5);
            EXPECT_NEAR(double(m.positions[i].y) + m.origin.y, y[i], 1e-5);
        }
    }
}

// Size and place are the faces': a vertex no face uses is dropped before drawing, so it neither hides a model
// too far from the origin or too small (an unused vertex at the origin let a triangle 1e6 away load and draw
// its stipples in columns, until 2026-12-04) nor gets a sound model refused.
TEST(BadInput, UnusedVerticesSetNeitherTheModelsSizeNorItsPlace) {
    const auto dir = temp_dir("loaders_unused_vertices");
    expect_load_error(write_file(dir / "far.obj", "v 0 0 0\nv 1e6 0 0\nv 1000001 0 0\nv 1e6 1 0\nf 2 3 4\n"),
                      "from the origin along an axis, 1e+06 times its size");
    expect_load_error(write_file(dir / "tiny.obj", "v 5 5 5\nv 0 0 0\nv 1e-20 0 0\nv 0 1e-20 0\nf 2 3 4\n"),
                      "units across, below the 1e-15");
    const Mesh m = load_mesh(write_file(dir / "stray.obj", "v 1e19 0 0\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 2 3 4\n"));
    EXPECT_EQ(m.triangle_count(), 1u);
    // A used vertex beyond the coordinates drawing allows is named by where it lies: the loaded order's
    // number (from 0, after an OBJ's vertices are split by their normals) named another line of the file.
    expect_load_error(write_file(dir / "huge.obj", "v 0 0 0\nv 1e20 0 0\nv 0 1 0\nf 1 2 3\n"),
                      "a vertex at (1e+20, 0, 0) has a coordinate of 1e+20, beyond the 1e+18 units it can be drawn within");
    // NaN stays an error wherever it is: the file is damaged.
    expect_load_error(write_file(dir / "nan.obj", "v nan 0 0\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 2 3 4\n"),
                      "has a NaN coordinate");
}

// ---------------------------------------------------------------- real models

// Loads a shared model, checks its size and prints the load rate.
void load_real_model(const std::string& name, size_t triangles, size_t vertices) {
    const std::string path = stipple::test::shared_model(name);
    if (path.empty()) GTEST_SKIP() << name << " is not in the shared models folder";
    const auto start = std::chrono::steady_clock::now();
    const Mesh m = load_mesh(path);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(m.triangle_count(), triangles);
    if (vertices) {
        EXPECT_EQ(m.vertex_count(), vertices);
    }
    expect_unit_normals(m);
    std::printf("%s: %zu triangles, %zu vertices in %.1f ms (%.2f M triangles/s)\n", name.c_str(), m.triangle_count(),
                m.vertex_count(), seconds * 1e3, m.triangle_count() / seconds / 1e6);
}

TEST(RealModels, StanfordBunnyObj) { load_real_model("stanford-bunny.obj", 69'451, 35'947); }
TEST(RealModels, IgeaPlyTriangleStrips) { load_real_model("igea.ply", 268'686, 134'345); }
TEST(RealModels, HorsePlyWithNormals) { load_real_model("horse.ply", 96'966, 48'485); }
TEST(RealModels, OgreObj) { load_real_model("ogre.obj", 124'008, 0); }
TEST(RealModels, SpotObj) { load_real_model("spot.obj", 5'856, 0); }

// A closed tetrahedron wound inside out loads wound outward, normals outward too.
TEST(LoadMesh, InsideOutClosedMeshIsTurnedOutward) {
    const auto dir = temp_dir("loaders_inside_out");
    const std::string path = (dir / "inside_out.obj").string();
    // Outward would be 1 3 2 / 1 2 4 / 1 4 3 / 2 3 4; every face here is reversed.
    write_file(path, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n");
    const Mesh mesh = load_mesh(path);
    EXPECT_GT(stipple::signed_volume(mesh), 0.0);
    const glm::vec3 centroid(0.25f);
    for (size_t v = 0; v < mesh.vertex_count(); ++v)
        EXPECT_GT(glm::dot(mesh.normals[v], mesh.positions[v] - centroid), 0.0f) << "vertex " << v;
    // An open sheet is left as it is, whichever way it faces.
    Mesh sheet;
    sheet.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    sheet.indices = {0, 2, 1};
    stipple::compute_vertex_normals(sheet);
    EXPECT_EQ(stipple::orient_consistently(sheet).triangles_turned, 0u);
}

}  // namespace
