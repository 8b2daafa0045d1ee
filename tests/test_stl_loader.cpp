// STL models (src/mesh/stl_loader.cpp), binary and ASCII: a cube read either way is the same cube, each
// facet keeps its own corners (a part's sharp edges keep their normals), a binary header that begins with
// "solid" is still binary, and every broken file is a one-line error naming the file and the facet or line.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "mesh/load_mesh.hpp"

namespace stipple {
namespace {

// The unit cube's 12 facets, wound outward, and one of them wound inward when `one_inward`.
std::vector<std::array<glm::vec3, 3>> cube_facets(bool one_inward = false) {
    const glm::vec3 c[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    const int quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};
    std::vector<std::array<glm::vec3, 3>> facets;
    for (const auto& q : quads) {
        facets.push_back({c[q[0]], c[q[1]], c[q[2]]});
        facets.push_back({c[q[0]], c[q[2]], c[q[3]]});
    }
    if (one_inward) std::swap(facets[5][1], facets[5][2]);
    return facets;
}

std::string binary_stl(const std::vector<std::array<glm::vec3, 3>>& facets, const std::string& header = "made by a test") {
    std::string bytes(80, ' ');
    bytes.replace(0, header.size(), header);
    const uint32_t count = uint32_t(facets.size());
    for (int i = 0; i < 4; ++i) bytes.push_back(char((count >> (8 * i)) & 0xFF));
    auto put = [&](float v) {
        char raw[4];
        std::memcpy(raw, &v, 4);  // this machine is little-endian, as the format
        bytes.append(raw, 4);
    };
    for (const auto& f : facets) {
        for (int i = 0; i < 3; ++i) put(0.0f);  // a zero normal, as many exporters write
        for (const glm::vec3& p : f) put(p.x), put(p.y), put(p.z);
        bytes.append(2, '\0');
    }
    return bytes;
}

std::string ascii_stl(const std::vector<std::array<glm::vec3, 3>>& facets) {
    std::string text = "solid cube\n";
    for (const auto& f : facets) {
        text += "  facet normal 0 0 0\n    outer loop\n";
        for (const glm::vec3& p : f)
            text += "      vertex " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
        text += "    endloop\n  endfacet\n";
    }
    return text + "endsolid cube\n";
}

std::string load_error(const std::string& bytes) {
    try {
        load_mesh_from_bytes("part.stl", bytes);
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind("part.stl: ", 0), 0u) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        return message;
    }
    ADD_FAILURE() << "loaded without an error";
    return "";
}

TEST(StlLoader, ACubeReadsTheSameFromBinaryAndAscii) {
    const Mesh binary = load_mesh_from_bytes("cube.stl", binary_stl(cube_facets(true)));
    const Mesh ascii = load_mesh_from_bytes("cube.stl", ascii_stl(cube_facets(true)));
    ASSERT_EQ(binary.triangle_count(), 12u);
    ASSERT_EQ(ascii.triangle_count(), 12u);
    EXPECT_EQ(binary.positions.size(), 36u) << "each facet keeps its own three corners";
    EXPECT_EQ(binary.positions, ascii.positions);
    EXPECT_EQ(binary.indices, ascii.indices);
    EXPECT_NEAR(total_area(binary), 6.0, 1e-6);
    EXPECT_EQ(binary.winding.triangles_turned, 1u) << "the facet wound inward is turned, as in every format";
    // Each corner's normal is its facet's (outward), not an average across the cube's edges.
    for (size_t t = 0; t < binary.triangle_count(); ++t) {
        const glm::vec3 a = binary.positions[binary.indices[3 * t]], b = binary.positions[binary.indices[3 * t + 1]],
                        c = binary.positions[binary.indices[3 * t + 2]];
        const glm::vec3 face = glm::normalize(glm::cross(b - a, c - a));
        EXPECT_GT(glm::dot(face, (a + b + c) / 3.0f - glm::vec3(0.5f)), 0.0f) << "facet " << t << " faces outward";
        for (int k = 0; k < 3; ++k) EXPECT_GT(glm::dot(binary.normals[binary.indices[3 * t + k]], face), 0.999f);
    }
}

TEST(StlLoader, ABinaryHeaderThatBeginsWithSolidIsBinary) {
    const Mesh mesh = load_mesh_from_bytes("cube.stl", binary_stl(cube_facets(), "solid cube exported by a CAD program"));
    EXPECT_EQ(mesh.triangle_count(), 12u);
}

// What exporters write besides the format's letter: "nan" normals for degenerate facets (the normals are not read),
// upper-case keywords, a byte-order mark, "\r\n" or lone "\r" line ends, a whole file on one line.
TEST(StlLoader, AsciiAsExportersWriteIt) {
    const std::string ascii = ascii_stl(cube_facets());
    auto replaced = [](std::string text, const std::string& from, const std::string& to) {
        for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) text.replace(at, from.size(), to);
        return text;
    };
    for (const std::string& variant : {replaced(ascii, "normal 0 0 0", "normal nan -nan inf"), replaced(ascii, "facet", "FACET"),
                                       "\xEF\xBB\xBF" + ascii, replaced(ascii, "\n", "\r\n"), replaced(ascii, "\n", "\r"),
                                       replaced(ascii, "\n", " "), replaced(ascii, "solid cube\n", "solid \v\f cube\n")}) {
        const Mesh mesh = load_mesh_from_bytes("cube.stl", variant);
        EXPECT_EQ(mesh.triangle_count(), 12u) << variant.substr(0, 60);
        EXPECT_NEAR(total_area(mesh), 6.0, 1e-5);
    }
    // Line numbers count "\r\n" and lone "\r" as one line end each.
    std::string crlf = replaced(ascii, "\n", "\r\n");
    crlf.erase(crlf.find("endloop"), 7);
    EXPECT_NE(load_error(crlf).find("line 8: expected \"endloop\""), std::string::npos);
}

TEST(StlLoader, SeveralSolidsInOneAsciiFile) {
    const std::vector<std::array<glm::vec3, 3>> facets = cube_facets();
    std::string text = ascii_stl({facets.begin(), facets.begin() + 6}) + ascii_stl({facets.begin() + 6, facets.end()});
    EXPECT_EQ(load_mesh_from_bytes("cube.stl", text).triangle_count(), 12u);
}

// What other readers take too (refused until 2026-12-07): a count of 0 from a writer that streamed its facets,
// and padding of less than a facet after the last one. A whole facet more than the count is refused.
TEST(StlLoader, AZeroCountAndPaddingAreReadAsOtherReadersReadThem) {
    const std::string binary = binary_stl(cube_facets());
    std::string uncounted = binary;
    std::memset(&uncounted[80], 0, 4);
    EXPECT_EQ(load_mesh_from_bytes("streamed.stl", uncounted).triangle_count(), 12u);
    EXPECT_EQ(load_mesh_from_bytes("padded.stl", binary + std::string(1, '\0')).triangle_count(), 12u);
    EXPECT_EQ(load_mesh_from_bytes("padded.stl", binary + std::string(49, ' ')).triangle_count(), 12u);
    EXPECT_NE(load_error(binary + binary.substr(84, 50)).find("binary STL of 734 bytes, where its count of 12 facets asks 684"),
              std::string::npos);
}

// A model far from the file's origin keeps its shape: the text is read in double and the model stored about its
// own centre (Mesh::origin), as the OBJ and PLY readers do (a unit sphere 90,000 units out lost its shape).
TEST(StlLoader, AFarAsciiModelKeepsItsShape) {
    const std::string text = "solid far\n facet normal 0 0 1\n  outer loop\n   vertex 90000.1 0 0\n   vertex 90001.3 0 0\n"
                             "   vertex 90000.1 0.7 0\n  endloop\n endfacet\nendsolid far\n";
    const Mesh m = load_mesh_from_bytes("far.stl", text);
    ASSERT_EQ(m.triangle_count(), 1u);
    EXPECT_GT(m.origin.x, 89000.0);
    const double x[3] = {90000.1, 90001.3, 90000.1};
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(double(m.positions[i].x) + m.origin.x, x[i], 1e-5) << i;
    EXPECT_NE(load_error("solid big\nfacet normal 0 0 1\nouter loop\nvertex 1e39 0 0\nvertex 0 0 0\nvertex 0 1 0\nendloop\n"
                         "endfacet\nendsolid\n").find("beyond single precision's range"), std::string::npos);
}

TEST(StlLoader, BrokenFilesAreOneLineErrors) {
    const std::string binary = binary_stl(cube_facets());
    EXPECT_NE(load_error(binary.substr(0, binary.size() - 7)).find("binary STL of 677 bytes, where its count of 12 facets asks 684"),
              std::string::npos);
    EXPECT_NE(load_error(binary.substr(0, 40)).find("shorter than a binary STL's 84-byte header"), std::string::npos);
    EXPECT_NE(load_error(binary_stl({})).find("no triangles"), std::string::npos);
    std::string nan = binary;
    const float not_a_number = std::nanf("");
    std::memcpy(&nan[84 + 3 * 50 + 12 + 4], &not_a_number, 4);  // facet 3, first corner's y
    EXPECT_NE(load_error(nan).find("facet 3 has a corner that is not a finite number"), std::string::npos);

    const std::string ascii = ascii_stl(cube_facets());
    std::string no_endloop = ascii;
    no_endloop.erase(no_endloop.find("endloop"), 7);
    EXPECT_NE(load_error(no_endloop).find("line 8: expected \"endloop\", got 'endfacet'"), std::string::npos);
    std::string bad_number = ascii;
    bad_number.replace(bad_number.find("vertex ") + 7, 8, "1,5     ");
    EXPECT_NE(load_error(bad_number).find("line 4: expected a number, got '1,5'"), std::string::npos);
    std::string infinite = ascii;
    infinite.replace(infinite.find("vertex ") + 7, 8, "nan     ");
    EXPECT_NE(load_error(infinite).find("is not finite"), std::string::npos);
    EXPECT_NE(load_error(ascii.substr(0, ascii.size() / 2)).find("the file ends"), std::string::npos);
    EXPECT_NE(load_error("solid empty\nendsolid empty\n").find("no triangles"), std::string::npos);
    EXPECT_NE(load_error(ascii + "garbage\n").find("expected \"solid\" or the end of the file"), std::string::npos);
    EXPECT_NE(load_error(std::string(200, 'x')).find("truncated, or not an STL file"), std::string::npos);
    std::string four = ascii;
    four.insert(four.find("endloop"), "vertex 0 0 0\n");
    EXPECT_NE(load_error(four).find("expected \"endloop\", got 'vertex'"), std::string::npos) << "facets are triangles";
    std::string plus_minus = ascii;
    plus_minus.replace(plus_minus.find("vertex ") + 7, 8, "+-1     ");
    EXPECT_NE(load_error(plus_minus).find("expected a number, got '+-1'"), std::string::npos);
    LoadOptions few;
    few.max_elements = 5;
    try {
        load_mesh_from_bytes("part.stl", binary, few);
        ADD_FAILURE() << "12 facets over a limit of 5 loaded";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("more than the limit of 5"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace stipple
