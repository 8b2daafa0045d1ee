// glTF as today's tools write it: KHR_mesh_quantization (integer positions scaled by the node, normalized
// integer normals, sparse accessors), EXT_meshopt_compression (gltfpack -cc: buffer views compressed
// with meshoptimizer's codecs into a placeholder buffer with no data) and KHR_draco_mesh_compression
// (a primitive as one Draco bitstream). Each loads as the plain float file it was made from, the
// compressed fox animates as the original, and broken compressed data is named.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <tuple>
#include <cmath>
#include <cstring>

#include <meshoptimizer.h>
#include <nlohmann/json.hpp>

#include "anim/deform_cpu.hpp"
#include "anim/pose.hpp"
#include "anim/procedural_rigs.hpp"
#include "core/error.hpp"
#include "mesh/glb_container.hpp"
#include "mesh/load_mesh.hpp"
#include "mesh/loader_util.hpp"
#include "mesh/primitives.hpp"
#include "support/anim_files.hpp"
#include "support/draco_packing.hpp"
#include "support/meshopt_packing.hpp"
#include "support/model_files.hpp"
#include "support/test_paths.hpp"

namespace stipple {
namespace {

using anim::GltfBuilder;
using nlohmann::json;

constexpr int kByte = 5120, kShort = 5122, kUnsignedShort = 5123;

// A sphere with normals as a float .glb: one node, one primitive (POSITION, NORMAL, 32-bit indices).
// Accessors 0, 1, 2 and buffer views 0, 1, 2 are positions, normals, indices.
GltfBuilder float_sphere(const Mesh& sphere) {
    GltfBuilder b;
    std::vector<float> positions, normals;
    for (size_t v = 0; v < sphere.vertex_count(); ++v)
        for (int c = 0; c < 3; ++c) positions.push_back(sphere.positions[v][c]), normals.push_back(sphere.normals[v][c]);
    const int p = b.add_floats(positions, "VEC3");
    const int n = b.add_floats(normals, "VEC3");
    const int i = b.add_uint32(sphere.indices, "SCALAR");
    b.add("meshes", {{"primitives", json::array({{{"attributes", {{"POSITION", p}, {"NORMAL", n}}}, {"indices", i}}})}});
    b.add("nodes", {{"mesh", 0}});
    b.add("scenes", {{"nodes", json::array({0})}});
    b.doc["scene"] = 0;
    return b;
}

// Replaces accessor `a`'s data with `bytes` in a view of its own with `stride`, as `component` `type`.
void replace_accessor(GltfBuilder& b, int a, const std::vector<uint8_t>& bytes, int component, const std::string& type,
                      size_t stride, bool normalized) {
    const int raw = b.add_uint8(bytes, "SCALAR");  // a view holding the bytes (its accessor is dropped)
    const json view = b.doc["accessors"][raw]["bufferView"];
    b.doc["accessors"].erase(size_t(raw));
    json& accessor = b.doc["accessors"][a];
    accessor["bufferView"] = view;
    accessor["componentType"] = component;
    accessor["type"] = type;
    accessor["normalized"] = normalized;
    accessor.erase("min"), accessor.erase("max");
    b.doc["bufferViews"][accessor["bufferView"].get<int>()]["byteStride"] = stride;
}

template <class T>
void put(std::vector<uint8_t>& out, T value) {
    uint8_t raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    out.insert(out.end(), raw, raw + sizeof(T));
}

double degrees_between(const glm::vec3& a, const glm::vec3& b) {
    return std::acos(std::clamp(double(glm::dot(glm::normalize(a), glm::normalize(b))), -1.0, 1.0)) * 180.0 / M_PI;
}

// Each triangle's corners rotated to start at its least index: triangles compared up to their first corner.
std::vector<uint32_t> rotated_to_least(std::vector<uint32_t> indices) {
    for (size_t t = 0; t + 2 < indices.size(); t += 3)
        while (indices[t] > indices[t + 1] || indices[t] > indices[t + 2])
            std::rotate(indices.begin() + t, indices.begin() + t + 1, indices.begin() + t + 3);
    return indices;
}

std::string write(const std::string& folder, const std::string& name, const std::string& bytes) {
    return test::write_file(test::temp_dir(folder) / name, bytes);
}

TEST(GltfCompression, QuantizedPositionsAndNormalsLoadAsTheFloatOnes) {
    // As gltfpack quantizes: positions as 14-bit unsigned shorts that the node's scale and translation map
    // back, normals as normalized signed bytes, both padded to 4-byte strides.
    const Mesh sphere = make_uv_sphere(2000, 3.0f, {1.0f, -2.0f, 0.5f});
    GltfBuilder plain = float_sphere(sphere), quantized = float_sphere(sphere);
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& p : sphere.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const float extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
    const float step = extent / 16383.0f;
    std::vector<uint8_t> positions, normals;
    for (size_t v = 0; v < sphere.vertex_count(); ++v) {
        for (int c = 0; c < 3; ++c) put<uint16_t>(positions, uint16_t(std::lround((sphere.positions[v][c] - lo[c]) / step)));
        put<uint16_t>(positions, 0);
        for (int c = 0; c < 3; ++c) put<int8_t>(normals, int8_t(std::lround(sphere.normals[v][c] * 127.0f)));
        put<int8_t>(normals, 0);
    }
    replace_accessor(quantized, 0, positions, kUnsignedShort, "VEC3", 8, false);
    replace_accessor(quantized, 1, normals, kByte, "VEC3", 4, true);
    quantized.doc["nodes"][0]["scale"] = {step, step, step};
    quantized.doc["nodes"][0]["translation"] = {lo.x, lo.y, lo.z};
    quantized.doc["extensionsUsed"] = {"KHR_mesh_quantization"};
    quantized.doc["extensionsRequired"] = {"KHR_mesh_quantization"};

    const Mesh a = load_mesh(write("gltf_quantized", "plain.glb", plain.glb()));
    const Mesh b = load_mesh(write("gltf_quantized", "quantized.glb", quantized.glb()));
    ASSERT_EQ(a.indices, b.indices);
    ASSERT_EQ(a.vertex_count(), b.vertex_count());
    double worst_position = 0.0, worst_normal = 0.0;
    for (size_t v = 0; v < a.vertex_count(); ++v) {
        worst_position = std::max(worst_position, double(glm::length(a.positions[v] - b.positions[v])));
        worst_normal = std::max(worst_normal, degrees_between(a.normals[v], b.normals[v]));
    }
    std::printf("quantized: worst position error %.3g (step %.3g), worst normal %.2f degrees\n", worst_position, step, worst_normal);
    EXPECT_LE(worst_position, 0.87 * step);  // half a step on each axis
    EXPECT_GT(worst_position, 0.0) << "the positions went through the integers";
    EXPECT_LE(worst_normal, 1.0);
}

TEST(GltfCompression, QuantizedMorphTargetsMorphAsTheFloatOnes) {
    // The morphed quad with its positions as plain unsigned shorts, one target's position deltas as plain
    // signed shorts and its normal deltas as normalized signed bytes, the other's position deltas as
    // normalized signed shorts (KHR_mesh_quantization's types for morph targets).
    const GltfBuilder plain = anim::rigs::morphed_quad();
    GltfBuilder quantized = anim::rigs::morphed_quad();
    auto shorts = [](const std::vector<double>& values, double scale) {  // VEC3 padded to 8 bytes
        std::vector<uint8_t> out;
        for (size_t i = 0; i < values.size(); ++i) {
            put<int16_t>(out, int16_t(std::lround(values[i] * scale)));
            if (i % 3 == 2) put<int16_t>(out, 0);
        }
        return out;
    };
    std::vector<uint8_t> normal_bytes;
    for (int v = 0; v < 4; ++v) put<int8_t>(normal_bytes, 64), put<int8_t>(normal_bytes, 0), put<int8_t>(normal_bytes, 0), put<int8_t>(normal_bytes, 0);
    replace_accessor(quantized, 0, shorts({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, 1.0), kUnsignedShort, "VEC3", 8, false);
    replace_accessor(quantized, 3, shorts({0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0}, 1.0), kShort, "VEC3", 8, false);
    replace_accessor(quantized, 4, normal_bytes, kByte, "VEC3", 4, true);
    replace_accessor(quantized, 5, shorts({0, 0, 0.5, 0, 0, 0.5, 0, 0, 0.5, 0, 0, 0.5}, 32767.0), kShort, "VEC3", 8, true);
    const anim::AnimatedModel a = test::load_rig(plain, "gltf_quantized_morph", "plain");
    const anim::AnimatedModel b = test::load_rig(quantized, "gltf_quantized_morph", "quantized");
    for (double t : {0.6, 1.5}) {
        const anim::DeformedGeometry ga = anim::deform_cpu(a, anim::evaluate_pose(a, 0, t));
        const anim::DeformedGeometry gb = anim::deform_cpu(b, anim::evaluate_pose(b, 0, t));
        ASSERT_EQ(ga.positions.size(), gb.positions.size());
        for (size_t v = 0; v < ga.positions.size(); ++v) {
            EXPECT_LE(glm::length(ga.positions[v] - gb.positions[v]), 1e-4) << "vertex " << v << " at " << t << " s";
            EXPECT_LE(degrees_between(ga.normals[v], gb.normals[v]), 0.5) << "vertex " << v << " at " << t << " s";
        }
    }
    // The morph moves the quad: the comparison is not of two rest poses.
    const anim::DeformedGeometry rest = anim::deform_cpu(a, anim::evaluate_pose(a, 0, 0.0));
    const anim::DeformedGeometry moved = anim::deform_cpu(a, anim::evaluate_pose(a, 0, 1.5));
    EXPECT_GT(glm::length(rest.positions[2] - moved.positions[2]), 0.1);
}

TEST(GltfCompression, SparsePositionsMoveTheirVertices) {
    // A POSITION accessor whose sparse entries move two vertices.
    const Mesh sphere = make_icosphere(1);
    GltfBuilder b = float_sphere(sphere);
    const int index_view = b.doc["accessors"][b.add_uint16({3, 7}, "SCALAR")]["bufferView"];
    const int value_view = b.doc["accessors"][b.add_floats({0, 5, 0, 0, -5, 0}, "VEC3")]["bufferView"];
    b.doc["accessors"][0]["sparse"] = {{"count", 2},
                                       {"indices", {{"bufferView", index_view}, {"componentType", kUnsignedShort}}},
                                       {"values", {{"bufferView", value_view}}}};
    b.doc["accessors"][0].erase("min"), b.doc["accessors"][0].erase("max");
    const Mesh loaded = load_mesh(write("gltf_sparse", "sparse.glb", b.glb()));
    ASSERT_EQ(loaded.vertex_count(), sphere.vertex_count());
    for (size_t v = 0; v < loaded.vertex_count(); ++v) {
        const glm::vec3 expected = v == 3 ? glm::vec3(0, 5, 0) : v == 7 ? glm::vec3(0, -5, 0) : sphere.positions[v];
        EXPECT_EQ(loaded.positions[v], expected) << "vertex " << v;
    }
}

TEST(GltfCompression, MeshoptCompressedViewsLoadExactly) {
    // Positions as attributes of 12-byte elements and the indices as a triangle list, or as an index
    // sequence, with the placeholder buffer marked as a fallback or not: the same mesh to the bit.
    const Mesh sphere = make_uv_sphere(5000);
    const GltfBuilder b = float_sphere(sphere);
    const Mesh plain = load_mesh(write("gltf_meshopt", "plain.glb", b.glb()));
    for (const char* indices : {"TRIANGLES", "INDICES"})
        for (bool flag : {true, false}) {
            test::ViewCoding positions{"ATTRIBUTES", 12, "NONE", flag}, normals{"ATTRIBUTES", 4, "NONE", flag};
            test::ViewCoding triangles{indices, 4, "NONE", flag};
            const std::string packed = test::meshopt_pack_glb(b.glb(), {{0, positions}, {1, normals}, {2, triangles}});
            EXPECT_LT(packed.size(), b.glb().size()) << "compressed";
            const Mesh loaded = load_mesh(write("gltf_meshopt", std::string(indices) + (flag ? "_flag" : "") + ".glb", packed));
            // The triangle codec may start a triangle at another corner (same winding); the sequence codec
            // keeps every index.
            EXPECT_EQ(rotated_to_least(loaded.indices), rotated_to_least(plain.indices)) << indices;
            if (std::string(indices) == "INDICES") {
                EXPECT_EQ(loaded.indices, plain.indices);
            }
            EXPECT_EQ(loaded.positions, plain.positions) << indices;
            EXPECT_EQ(loaded.normals, plain.normals) << indices;
        }
    // The same as a .gltf whose compressed bytes are a data: URI (the placeholder rewritten as JSON, not GLB).
    const std::string glb = test::meshopt_pack_glb(b.glb());
    const GlbChunks chunks = split_glb("packed.glb", glb);  // views into glb
    json doc = json::parse(chunks.json);
    doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + test::base64(chunks.bin);
    const Mesh text = load_mesh(write("gltf_meshopt", "packed.gltf", doc.dump()));
    EXPECT_EQ(text.positions, plain.positions);
    EXPECT_EQ(text.indices, plain.indices);
}

TEST(GltfCompression, OctahedralNormalsDecode) {
    // Normals stored as gltfpack stores them: 8-bit octahedral (meshopt_encodeFilterOct), decoded by the
    // filter after the attribute codec into normalized signed bytes.
    const Mesh sphere = make_uv_sphere(3000);
    GltfBuilder b = float_sphere(sphere);
    std::vector<float> unit(4 * sphere.vertex_count(), 0.0f);
    for (size_t v = 0; v < sphere.vertex_count(); ++v)
        for (int c = 0; c < 3; ++c) unit[4 * v + c] = sphere.normals[v][c];
    std::vector<uint8_t> encoded(4 * sphere.vertex_count());
    meshopt_encodeFilterOct(encoded.data(), sphere.vertex_count(), 4, 8, unit.data());
    replace_accessor(b, 1, encoded, kByte, "VEC3", 4, true);
    const int view = b.doc["accessors"][1]["bufferView"];
    const std::string packed = test::meshopt_pack_glb(b.glb(), {{size_t(view), {"ATTRIBUTES", 4, "OCTAHEDRAL"}}});
    const Mesh loaded = load_mesh(write("gltf_meshopt_oct", "oct.glb", packed));
    ASSERT_EQ(loaded.vertex_count(), sphere.vertex_count());
    double worst = 0.0;
    for (size_t v = 0; v < loaded.vertex_count(); ++v) worst = std::max(worst, degrees_between(loaded.normals[v], sphere.normals[v]));
    std::printf("octahedral normals: worst %.2f degrees\n", worst);
    EXPECT_LE(worst, 1.5);  // 8 bits a component of the octahedron
}

TEST(GltfCompression, CompressedFoxAnimatesAsTheOriginal) {
    // Every buffer view of the fox (vertices, skin weights, joints, keyframes) compressed: the rest mesh
    // and the posed mesh are those of the original file, bit for bit.
    const std::string fox = test::shared_model("fox.glb");
    if (fox.empty()) GTEST_SKIP() << "../shared/models/fox.glb not present";
    const std::string original = read_file(fox);
    const std::string packed = test::meshopt_pack_glb(original);
    std::printf("fox.glb: %zu bytes, %zu compressed\n", original.size(), packed.size());
    ASSERT_LT(packed.size(), original.size());
    const std::string path = write("gltf_meshopt_fox", "fox-meshopt.glb", packed);
    const anim::AnimatedModel a = anim::load_animated_model(fox), b = anim::load_animated_model(path);
    ASSERT_EQ(a.rest.indices, b.rest.indices);
    ASSERT_EQ(a.rest.positions, b.rest.positions);
    ASSERT_EQ(a.animations.size(), b.animations.size());
    const int run = anim::find_animation(a, "Run");
    for (double t : {0.0, 0.37, 0.81}) {
        const anim::DeformedGeometry pa = anim::deform_cpu(a, anim::evaluate_pose(a, run, t));
        const anim::DeformedGeometry pb = anim::deform_cpu(b, anim::evaluate_pose(b, run, t));
        EXPECT_EQ(pa.positions, pb.positions) << "Run at " << t << " s";
    }
}

// Every triangle as its three corners, rotated to start at its least corner (same winding), sorted: the
// same surface whatever order a codec put its vertices and triangles in.
std::vector<std::array<float, 9>> triangle_set(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices) {
    std::vector<std::array<float, 9>> out;
    auto less = [](const glm::vec3& a, const glm::vec3& b) {
        return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
    };
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        glm::vec3 c[3] = {positions[indices[t]], positions[indices[t + 1]], positions[indices[t + 2]]};
        while (less(c[1], c[0]) || less(c[2], c[0])) std::rotate(c, c + 1, c + 3);
        out.push_back({c[0].x, c[0].y, c[0].z, c[1].x, c[1].y, c[1].z, c[2].x, c[2].y, c[2].z});
    }
    std::sort(out.begin(), out.end());
    return out;
}

double surface_area(const Mesh& m) {
    double area = 0.0;
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
        const glm::dvec3 a(m.positions[m.indices[t]]), b(m.positions[m.indices[t + 1]]), c(m.positions[m.indices[t + 2]]);
        area += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    return area;
}

TEST(GltfCompression, DracoCompressedSphereLoadsAsTheFloatOne) {
    // Stored losslessly the Draco primitive is the same surface (vertices and triangles reordered by the
    // codec); with positions quantized to 14 bits every vertex lies within half a step of the original's.
    const Mesh sphere = make_uv_sphere(4000, 2.0f);
    const std::string plain_glb = float_sphere(sphere).glb();
    const Mesh plain = load_mesh(write("gltf_draco", "plain.glb", plain_glb));
    const Mesh lossless = load_mesh(write("gltf_draco", "lossless.glb", test::draco_pack_glb(plain_glb)));
    EXPECT_EQ(triangle_set(lossless.positions, lossless.indices), triangle_set(plain.positions, plain.indices));

    const std::string packed = test::draco_pack_glb(plain_glb, 14);
    const json doc = json::parse(split_glb("packed.glb", packed).json);
    const size_t bitstream = doc["bufferViews"][doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["bufferView"].get<int>()]["byteLength"];
    std::printf("sphere: %zu bytes of vertices and indices, a Draco bitstream of %zu (positions 14 bits)\n", plain_glb.size(), bitstream);
    EXPECT_LT(bitstream, plain_glb.size() / 2);
    const Mesh quantized = load_mesh(write("gltf_draco", "quantized.glb", packed));
    ASSERT_EQ(quantized.triangle_count(), plain.triangle_count());
    const double step = 4.0 / 16383.0;  // the bounding box's side over 2^14 - 1
    double worst = 0.0;
    for (const glm::vec3& p : quantized.positions) {
        double nearest = 1e30;
        for (const glm::vec3& q : plain.positions) nearest = std::min(nearest, double(glm::length(p - q)));
        worst = std::max(worst, nearest);
    }
    std::printf("Draco 14-bit positions: worst %.3g (step %.3g), area %.6f against %.6f\n", worst, step,
                surface_area(quantized), surface_area(plain));
    EXPECT_LE(worst, 0.87 * step);
    EXPECT_NEAR(surface_area(quantized), surface_area(plain), 1e-3 * surface_area(plain));
}

TEST(GltfCompression, DracoCompressedFoxAnimatesAsTheOriginal) {
    // The fox (no index buffer, joints as unsigned bytes, weights as floats) as one lossless Draco
    // primitive: the same triangles at rest and in every pose tried, in the codec's order.
    const std::string fox = test::shared_model("fox.glb");
    if (fox.empty()) GTEST_SKIP() << "../shared/models/fox.glb not present";
    const std::string packed = test::draco_pack_glb(read_file(fox));
    const std::string path = write("gltf_draco_fox", "fox-draco.glb", packed);
    const anim::AnimatedModel a = anim::load_animated_model(fox), b = anim::load_animated_model(path);
    EXPECT_EQ(triangle_set(b.rest.positions, b.rest.indices), triangle_set(a.rest.positions, a.rest.indices));
    const int run = anim::find_animation(a, "Run");
    for (double t : {0.2, 0.55}) {
        const anim::DeformedGeometry pa = anim::deform_cpu(a, anim::evaluate_pose(a, run, t));
        const anim::DeformedGeometry pb = anim::deform_cpu(b, anim::evaluate_pose(b, run, t));
        EXPECT_EQ(triangle_set(pb.positions, b.rest.indices), triangle_set(pa.positions, a.rest.indices)) << "Run at " << t;
    }
}

// The compressed sphere's JSON and BIN, to break fields of.
struct Packed {
    json doc;
    std::string bin;
};
Packed packed_sphere(bool draco = false) {
    const std::string plain = float_sphere(make_uv_sphere(500)).glb();
    const std::string glb = draco ? test::draco_pack_glb(plain, 12) : test::meshopt_pack_glb(plain);
    const GlbChunks chunks = split_glb("packed.glb", glb);
    return {json::parse(chunks.json), std::string(chunks.bin)};
}

// Each test writes into a folder of its own: ctest runs tests in parallel, and temp_dir empties the folder
// (the Draco cases, named draco_*, had shared the meshopt cases' folder and raced with them).
void expect_error(const Packed& p, const std::string& name, const std::string& expected) {
    const std::string folder = name.rfind("draco", 0) == 0 ? "gltf_draco_bad" : "gltf_meshopt_bad";
    const std::string path = write(folder, name + ".glb", test::make_glb(p.doc.dump(), p.bin));
    try {
        load_mesh(path);
        ADD_FAILURE() << name << ": loaded";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(expected), std::string::npos) << name << ": " << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << "one line";
        EXPECT_EQ(what.rfind(path, 0), 0u) << "names the file";
    }
}

TEST(GltfCompression, BrokenCompressedDataIsNamed) {
    {
        Packed p = packed_sphere();  // a stream cut short
        json& e = p.doc["bufferViews"][0]["extensions"]["EXT_meshopt_compression"];
        e["byteLength"] = e["byteLength"].get<int>() / 2;
        expect_error(p, "cut", "bufferViews[0].extensions.EXT_meshopt_compression: its ");
    }
    {
        Packed p = packed_sphere();  // bytes that are not a stream
        const json& e = p.doc["bufferViews"][2]["extensions"]["EXT_meshopt_compression"];
        std::fill_n(p.bin.begin() + e["byteOffset"].get<size_t>(), e["byteLength"].get<size_t>(), '\x55');
        expect_error(p, "garbage", "bufferViews[2].extensions.EXT_meshopt_compression: its ");
    }
    {
        Packed p = packed_sphere();  // decodes to more than the view holds
        p.doc["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["count"] = 10000000;
        expect_error(p, "count", "bufferViews[0].extensions.EXT_meshopt_compression.count: 10000000 elements of 4 bytes do not fill");
    }
    {
        Packed p = packed_sphere();
        p.doc["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["mode"] = "TRIANGLES";
        p.doc["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["filter"] = "OCTAHEDRAL";
        expect_error(p, "filter", "OCTAHEDRAL applies to ATTRIBUTES only, not TRIANGLES");
    }
    {
        Packed p = packed_sphere();  // the extension not declared: buffer 1 is a buffer without data
        p.doc.erase("extensionsUsed"), p.doc.erase("extensionsRequired");
        expect_error(p, "undeclared", "buffers[1].uri: missing (only the first buffer of a .glb, or a placeholder");
    }
    {
        Packed p = packed_sphere();  // an uncompressed view into the placeholder
        p.doc["bufferViews"][1].erase("extensions");
        expect_error(p, "uncompressed", "bufferViews[1].buffer: buffer 1 holds no data");
    }
    {
        Packed p = packed_sphere();  // a view far into a huge placeholder: refused, not allocated
        p.doc["buffers"][1]["byteLength"] = uint64_t(1) << 50;
        p.doc["bufferViews"][0]["byteOffset"] = (uint64_t(1) << 50) - p.doc["bufferViews"][0]["byteLength"].get<uint64_t>();
        expect_error(p, "bomb", "buffers[1]: its compressed views reach byte 1125899906842624");
    }
}

TEST(GltfCompression, BrokenDracoDataIsNamed) {
    const std::string field = "meshes[0].primitives[0].extensions.KHR_draco_mesh_compression";
    {
        Packed p = packed_sphere(true);  // bytes that are not a bitstream
        const json& view = p.doc["bufferViews"][p.doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["bufferView"].get<int>()];
        std::fill_n(p.bin.begin() + view["byteOffset"].get<size_t>(), view["byteLength"].get<size_t>(), '\x3c');
        expect_error(p, "draco_garbage", field + ": the Draco bitstream does not decode");
    }
    {
        Packed p = packed_sphere(true);  // cut short
        json& view = p.doc["bufferViews"][p.doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["bufferView"].get<int>()];
        view["byteLength"] = view["byteLength"].get<size_t>() / 3;
        expect_error(p, "draco_cut", field + ": the Draco bitstream does not decode");
    }
    {
        Packed p = packed_sphere(true);
        p.doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["attributes"]["NORMAL"] = 77;
        expect_error(p, "draco_id", field + ": attributes.NORMAL: the bitstream has no attribute 77");
    }
    {
        Packed p = packed_sphere(true);
        p.doc["accessors"][0]["count"] = 5;
        expect_error(p, "draco_count", field + ": attributes.POSITION: accessor 0 has 5 elements, the bitstream ");
    }
    {
        Packed p = packed_sphere(true);
        p.doc["accessors"][1]["componentType"] = kByte;
        p.doc["accessors"][1]["normalized"] = true;
        expect_error(p, "draco_type", field + ": attributes.NORMAL: the bitstream's attribute is 3 values of FLOAT, its accessor VEC3 of BYTE");
    }
    {
        Packed p = packed_sphere(true);
        p.doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["attributes"]["POSITION"] = -1;
        expect_error(p, "draco_json", field + ".attributes.POSITION: expected a Draco attribute id, got -1");
    }
}

}  // namespace
}  // namespace stipple
