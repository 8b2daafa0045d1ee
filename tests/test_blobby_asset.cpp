// The committed default scene, assets/blobby.glb: it loads through the normal loader, is the
// closed outward-facing surface the renderer assumes (silhouettes and back-face culling depend on
// it), and is exactly what tools/make_blobby.cpp produces today.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "mesh/load_mesh.hpp"
#include "mesh/mesh.hpp"
#include "support/test_paths.hpp"

namespace {

namespace fs = std::filesystem;

const std::string kAsset = stipple::test::source_path("assets/blobby.glb");

std::string read_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Vertex ids by exact position, so the closedness check does not depend on whether the loader
// keeps, splits or merges the file's indices.
std::vector<uint32_t> weld_by_position(const stipple::Mesh& mesh) {
    std::map<std::tuple<float, float, float>, uint32_t> ids;
    std::vector<uint32_t> welded(mesh.vertex_count());
    for (size_t v = 0; v < mesh.vertex_count(); ++v) {
        const glm::vec3& p = mesh.positions[v];
        welded[v] = ids.try_emplace({p.x, p.y, p.z}, static_cast<uint32_t>(ids.size())).first->second;
    }
    return welded;
}

// <build>/tools/make_blobby, found from this executable's own path (<build>/tests/...): the
// test cannot be told the tool's location through CMake.
fs::path tool_path() {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) return {};
    return self.parent_path().parent_path() / "tools" / "make_blobby";
}

// Shell command "'tool' args... > redirect". Built by appending: GCC 12 -O3 warns falsely
// (-Wrestrict, GCC bug 105329) on `"literal" + std::string&&`.
std::string shell_command(const fs::path& tool, const std::string& args, const std::string& redirect) {
    std::string command = "'";
    command += tool.string();
    command += "' ";
    command += args;
    command += redirect;
    return command;
}

class BlobbyAsset : public ::testing::Test {
protected:
    static void SetUpTestSuite() { mesh_ = new stipple::Mesh(stipple::load_mesh(kAsset)); }
    static void TearDownTestSuite() {
        delete mesh_;
        mesh_ = nullptr;
    }
    static const stipple::Mesh& mesh() { return *mesh_; }

private:
    static stipple::Mesh* mesh_;
};
stipple::Mesh* BlobbyAsset::mesh_ = nullptr;

}  // namespace

TEST_F(BlobbyAsset, FitsTheRepositorySizeRule) {
    ASSERT_TRUE(fs::is_regular_file(kAsset)) << kAsset;
    EXPECT_LT(fs::file_size(kAsset), 1024u * 1024u) << "assets must stay under 1 MiB";
}

TEST_F(BlobbyAsset, LoadsWithExpectedSize) {
    const stipple::Mesh& m = mesh();
    EXPECT_GE(m.triangle_count(), 30'000u);
    EXPECT_LE(m.triangle_count(), 60'000u);
    // A closed genus-0 triangle mesh has V = F/2 + 2; allow for a loader that splits vertices.
    EXPECT_GE(m.vertex_count(), m.triangle_count() / 2 + 2);
    ASSERT_EQ(m.normals.size(), m.positions.size());
    for (const glm::vec3& n : m.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-3f);

    // The metaballs span roughly two units; a different scale would mean a broken file or a
    // loader applying a transform it should not.
    const stipple::Bounds b = stipple::compute_bounds(m);
    const glm::vec3 size = b.max - b.min;
    for (int k = 0; k < 3; ++k) {
        EXPECT_GT(size[k], 1.0f) << "axis " << k;
        EXPECT_LT(size[k], 3.0f) << "axis " << k;
    }
}

TEST_F(BlobbyAsset, IsClosedAndConsistentlyWound) {
    const stipple::Mesh& m = mesh();
    const std::vector<uint32_t> id = weld_by_position(m);
    // Every directed edge once and its reverse once <=> every edge shared by exactly two
    // triangles that traverse it in opposite directions (closed, manifold, consistent winding).
    std::vector<uint64_t> directed;
    directed.reserve(m.indices.size());
    for (size_t t = 0; t < m.indices.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            const uint64_t a = id[m.indices[t + k]], b = id[m.indices[t + (k + 1) % 3]];
            ASSERT_NE(a, b) << "degenerate triangle " << t / 3;
            directed.push_back(a << 32 | b);
        }
    std::sort(directed.begin(), directed.end());
    const auto duplicate = std::adjacent_find(directed.begin(), directed.end());
    ASSERT_EQ(duplicate, directed.end()) << "directed edge used twice (non-manifold or flipped triangle)";
    size_t open_edges = 0;
    for (uint64_t e : directed)
        if (!std::binary_search(directed.begin(), directed.end(), (e << 32) | (e >> 32))) ++open_edges;
    EXPECT_EQ(open_edges, 0u);
}

TEST_F(BlobbyAsset, NormalsAndWindingPointOutward) {
    const stipple::Mesh& m = mesh();
    glm::dvec3 centroid(0.0);
    for (const glm::vec3& p : m.positions) centroid += glm::dvec3(p);
    centroid /= static_cast<double>(m.vertex_count());

    double mean_dot = 0.0;
    for (size_t v = 0; v < m.vertex_count(); ++v)
        mean_dot += glm::dot(glm::dvec3(m.normals[v]), glm::normalize(glm::dvec3(m.positions[v]) - centroid));
    mean_dot /= static_cast<double>(m.vertex_count());
    EXPECT_GT(mean_dot, 0.5) << "vertex normals should point away from the centre";

    // Outward winding gives a positive signed volume (divergence theorem), and the stored
    // normals must agree with the faces they belong to.
    double volume = 0.0;
    size_t disagreeing = 0;
    for (size_t t = 0; t < m.indices.size(); t += 3) {
        const uint32_t i0 = m.indices[t], i1 = m.indices[t + 1], i2 = m.indices[t + 2];
        const glm::dvec3 a(m.positions[i0]), b(m.positions[i1]), c(m.positions[i2]);
        const glm::dvec3 face = glm::cross(b - a, c - a);
        volume += glm::dot(a, glm::cross(b, c)) / 6.0;
        const glm::dvec3 n = glm::dvec3(m.normals[i0]) + glm::dvec3(m.normals[i1]) + glm::dvec3(m.normals[i2]);
        if (glm::dot(face, n) <= 0.0) ++disagreeing;
    }
    EXPECT_GT(volume, 0.5) << "signed volume must be positive (and the blob is about 2 units wide)";
    EXPECT_EQ(disagreeing, 0u) << "triangles whose winding disagrees with their vertex normals";
}

TEST_F(BlobbyAsset, RegeneratingGivesIdenticalBytes) {
    const fs::path tool = tool_path();
    if (!fs::is_regular_file(tool))
        GTEST_SKIP() << "tool not built (configure with STIPPLE_BUILD_TOOLS=ON and build make_blobby): " << tool;
    const fs::path out = stipple::test::temp_dir("blobby_asset") / "blobby.glb";
    std::string quoted_out = "'";
    quoted_out += out.string();
    quoted_out += "'";
    const std::string command = shell_command(tool, quoted_out, " > /dev/null");
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    const std::string fresh = read_bytes(out), committed = read_bytes(kAsset);
    ASSERT_FALSE(fresh.empty());
    EXPECT_TRUE(fresh == committed)
        << "assets/blobby.glb is not what tools/make_blobby writes now (" << fresh.size() << " vs "
        << committed.size() << " bytes); regenerate it as assets/README.md says";
}

TEST_F(BlobbyAsset, ToolRejectsBadUsage) {
    const fs::path tool = tool_path();
    if (!fs::is_regular_file(tool)) GTEST_SKIP() << "tool not built: " << tool;
    const std::string quiet = " > /dev/null 2>&1";
    EXPECT_NE(std::system(shell_command(tool, "", quiet).c_str()), 0) << "no argument";
    EXPECT_NE(std::system(shell_command(tool, "/nonexistent-dir/x/blobby.glb", quiet).c_str()), 0)
        << "unwritable output";
}
