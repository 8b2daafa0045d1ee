// Inputs the fuzzers found (tests/fuzz/regressions/, one file per finding, named after it), read the
// way their harness read them: each must be refused with the one-line error listed here, or load and
// keep every promise of a loaded mesh. Every file in the folder must be listed, so none is forgotten.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "anim/animated_model.hpp"
#include "core/error.hpp"
#include "mesh/load_mesh.hpp"
#include "scene/scene_json.hpp"

namespace {

namespace fs = std::filesystem;

const fs::path kFolder = fs::path(STIPPLE_SOURCE_DIR) / "tests" / "fuzz" / "regressions";

struct Regression {
    const char* file;
    const char* expected;  // the error's problem (after "<path>: "); "" when the file must load
};

const Regression kRegressions[] = {
    // An n-gon of infinite extent made ear clipping's grid cell count NaN, converted to a size (UBSan, 2026-12-05).
    {"obj_polygon_infinite_extent_nan_cells.obj", "a vertex at (1, 1, 5.55556e+32) has a coordinate of 5.55556e+32, beyond the 1e+18 units it can be drawn within"},
    // A POSITION accessor of no elements: the accessor reader gave memcpy a null destination for 0 bytes
    // (2026-12-03, when the static glTF loader came to read through it).
    {"gltf_empty_position_accessor.gltf", "mesh 'tri' primitive 0: index 0 refers to vertex 0 but there are only 0 vertices"},
    // Four slivers whose corners lie a few float steps apart: welded into one corner since 2026-12-07 and
    // dropped as collapsed, they left the mesh empty, which loaded (fuzz_stl, "index count").
    {"stl_slivers_whose_corners_weld_into_one.stl",
     "no triangle with corners apart (all 4 triangles have two corners at one place, within a few float steps)"},
    // File normals of 7e31 square to infinity in float and normalised to zero vectors.
    {"ply_normal_length_overflows_float.ply", ""},
    // A number beyond double range made nlohmann::json throw out_of_range, which escaped parse_scene.
    {"scene_number_overflow_1e390.json", "not valid JSON: number overflow parsing '1e390'"},
    // Found by a longer campaign and by reading the readers (review of 2026-12-04). An attribute name with a
    // line break was quoted raw in the message (fail_file now makes every message one line).
    {"gltf_draco_attribute_name_with_newline.glb",
     "meshes[0].primitives[0].extensions.KHR_draco_mesh_compression: attributes.X; Y: the primitive has no X; Y attribute"},
    {"gltf_instancing_attribute_name_with_newline.gltf",
     "nodes[0].extensions.EXT_mesh_gpu_instancing.attributes._X; Y: 1 instances, but TRANSLATION has 3"},
    // 100 compressed views sharing one source range, one placed 1.6 GB out: the placeholder buffer was
    // reserved at 1.6 GB before any view was decoded.
    {"gltf_meshopt_view_far_out_reserved_1_6GB.gltf",
     "buffers[1]: its compressed views reach byte 1600000004, beyond the 800 bytes they decode to"},
    // A 22-byte GLB whose JSON chunk claims 4 GiB (the animation probe reserved it; the loader refuses it).
    {"glb_json_chunk_longer_than_the_file.glb", "GLB header: length 4294967280 is more than the file's 22 bytes"},
    // A field name with a backspace ("o\bj_y") was quoted raw, breaking the one-line message.
    {"scene_control_character_in_field_name.json",
     "o?j_y: unknown field (expected one of: objects, camera, camera_path, light, paper, ink, paused)"},
    // An instanced mesh 6e-4 across (EXT_mesh_gpu_instancing scales of 6e-4 and 3e-6) placed 3 units out: the
    // animated loader's check that its vertices are the static mesh's allowed 1e-5 of the mesh's size, less than
    // the float rounding at 3 units, and called the file's own vertices an internal error (fuzz_anim, 2026-12-06).
    // Read by the animated loader (the files named anim_*), as its harness reads them. Its second key time,
    // which the fuzzer had made 0 like the first, is 1 again (its accessor's max) since repeated times are
    // refused (2026-12-06): what it tests lies beyond the animation's reading.
    {"anim_scaled_instance_rounds_beyond_the_tolerance.glb", ""},
};

void PrintTo(const Regression& r, std::ostream* os) { *os << r.file; }

class FuzzRegression : public ::testing::TestWithParam<Regression> {};

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST_P(FuzzRegression, RefusedInOneLineOrLoadedWhole) {
    const fs::path path = kFolder / GetParam().file;
    const std::string expected = GetParam().expected;
    ASSERT_TRUE(fs::is_regular_file(path)) << path;
    try {
        if (path.extension() == ".json") {
            stipple::parse_scene(read_text(path), path.string(), kFolder);
            EXPECT_TRUE(expected.empty()) << "read without the expected error: " << expected;
            return;
        }
        const stipple::Mesh mesh = path.filename().string().rfind("anim_", 0) == 0
                                       ? stipple::anim::load_animated_model(path.string()).rest
                                       : stipple::load_mesh(path.string());
        EXPECT_TRUE(expected.empty()) << "loaded without the expected error: " << expected;
        ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
        for (uint32_t i : mesh.indices) ASSERT_LT(i, mesh.positions.size());
        for (size_t v = 0; v < mesh.positions.size(); ++v) {
            for (int axis = 0; axis < 3; ++axis) ASSERT_TRUE(std::isfinite(mesh.positions[v][axis])) << "vertex " << v;
            EXPECT_NEAR(glm::length(mesh.normals[v]), 1.0f, 1e-5f) << "normal " << v;
        }
    } catch (const stipple::Error& e) {
        const std::string message = e.what();
        EXPECT_FALSE(expected.empty()) << "refused: " << message;
        EXPECT_EQ(message, path.string() + ": " + expected);
    }
}

INSTANTIATE_TEST_SUITE_P(Files, FuzzRegression, ::testing::ValuesIn(kRegressions), [](const auto& info) {
    std::string name = info.param.file;
    for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    return name;
});

TEST(FuzzRegressions, EveryFileInTheFolderIsListed) {
    size_t files = 0;
    for (const fs::directory_entry& entry : fs::directory_iterator(kFolder)) {
        if (entry.path().filename() == "README.md") continue;
        ++files;
        bool listed = false;
        for (const Regression& r : kRegressions) listed = listed || entry.path().filename() == r.file;
        EXPECT_TRUE(listed) << entry.path() << " is not listed in kRegressions";
    }
    EXPECT_EQ(files, std::size(kRegressions));
}

}  // namespace
