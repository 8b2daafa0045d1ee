// Polygons into triangles (mesh/polygon_triangulation.hpp): concave faces are cut by ear clipping, so
// their triangles cover the polygon exactly once; convex ones keep the fan loaders always made.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "mesh/load_mesh.hpp"
#include "mesh/polygon_triangulation.hpp"
#include "support/test_paths.hpp"

namespace stipple {
namespace {

struct Cut {
    std::vector<uint32_t> triangles;
    bool clipped = false;
};

Cut cut(const std::vector<glm::vec3>& positions, std::vector<uint32_t> corners = {}) {
    if (corners.empty())
        for (uint32_t i = 0; i < positions.size(); ++i) corners.push_back(i);
    Cut c;
    c.triangles.assign(3 * (corners.size() - 2), UINT32_MAX);
    c.clipped = triangulate_polygon(positions, corners, c.triangles) == Triangulated::clipped;
    return c;
}

glm::dvec3 normal_of(const std::vector<glm::vec3>& p, const uint32_t* t) {
    return glm::cross(glm::dvec3(p[t[1]]) - glm::dvec3(p[t[0]]), glm::dvec3(p[t[2]]) - glm::dvec3(p[t[0]]));
}

// The U of the loader's bug: 3 x 2 with a 1 x 1 notch from the top, area 5; a fan around corner 0
// covers 7 (its triangles reach over the notch).
std::vector<glm::vec3> u_shape() {
    return {{0, 0, 0}, {3, 0, 0}, {3, 2, 0}, {2, 2, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
}

bool in_notch(glm::dvec3 p) { return p.x > 1.0 && p.x < 2.0 && p.y > 1.0; }

// A star of `points` points (2 * points corners, every other one reflex) in the z = 0 plane.
std::vector<glm::vec3> star(int points, double inner) {
    std::vector<glm::vec3> s;
    for (int i = 0; i < 2 * points; ++i) {
        const double a = std::numbers::pi * i / points, r = i % 2 ? inner : 1.0;
        s.push_back(glm::vec3(float(r * std::cos(a)), float(r * std::sin(a)), 0.0f));
    }
    return s;
}

// A polygon in the z = 0 plane (counter-clockwise) is covered once by its cut: the triangles' signed areas
// add up to the polygon's, and so do their absolute areas (nothing overlaps or folds over). Returns the cut.
Cut expect_covered_once(const std::vector<glm::vec3>& polygon, double tolerance) {
    double polygon_area = 0.0;
    for (size_t i = 0; i < polygon.size(); ++i) {
        const glm::vec3 p = polygon[i], q = polygon[(i + 1) % polygon.size()];
        polygon_area += 0.5 * (double(p.x) * q.y - double(q.x) * p.y);
    }
    const Cut c = cut(polygon);
    double area = 0.0, absolute = 0.0;
    for (size_t t = 0; t + 2 < polygon.size(); ++t) {
        const double z = 0.5 * normal_of(polygon, &c.triangles[3 * t]).z;
        area += z, absolute += std::abs(z);
    }
    EXPECT_NEAR(area, polygon_area, tolerance * polygon_area);
    EXPECT_NEAR(absolute, polygon_area, tolerance * polygon_area) << "triangles overlap or fold over";
    return c;
}

TEST(PolygonTriangulation, ConvexPolygonsKeepTheirFan) {
    const Cut quad = cut({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    EXPECT_FALSE(quad.clipped);
    EXPECT_EQ(quad.triangles, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
    // A regular 12-gon in a tilted plane: the fan too.
    std::vector<glm::vec3> dodecagon;
    for (int i = 0; i < 12; ++i) {
        const double a = 2 * std::numbers::pi * i / 12;
        dodecagon.push_back(glm::vec3(float(std::cos(a)), float(std::sin(a)), float(0.5 * std::cos(a))));
    }
    const Cut round = cut(dodecagon);
    EXPECT_FALSE(round.clipped);
    for (size_t t = 0; t < 10; ++t) EXPECT_EQ(round.triangles[3 * t], 0u);
}

TEST(PolygonTriangulation, AConcavePolygonIsCoveredOnceWithItsWinding) {
    for (bool reversed : {false, true})
        for (int tilt = 0; tilt < 3; ++tilt) {
            std::vector<glm::vec3> u = u_shape();
            if (reversed) std::reverse(u.begin(), u.end());
            for (glm::vec3& p : u) {  // the same U in planes facing x, y and z
                if (tilt == 1) p = glm::vec3(p.z, p.x, p.y);
                if (tilt == 2) p = glm::vec3(p.y, p.z, p.x);
            }
            const Cut c = cut(u);
            EXPECT_TRUE(c.clipped);
            ASSERT_EQ(c.triangles.size(), 3u * 6);
            // Expressed back in the U's own plane (z facing), each triangle's signed area.
            double area = 0.0;
            for (size_t t = 0; t < 6; ++t) {
                glm::dvec3 n = normal_of(u, &c.triangles[3 * t]);
                if (tilt == 1) n = glm::dvec3(n.y, n.z, n.x);
                if (tilt == 2) n = glm::dvec3(n.z, n.x, n.y);
                area += 0.5 * n.z;
                EXPECT_GT(reversed ? -n.z : n.z, 0.0) << "triangle " << t << " wound against the polygon";
                glm::dvec3 centroid(0.0);
                for (int k = 0; k < 3; ++k) {
                    glm::dvec3 p(u[c.triangles[3 * t + k]]);
                    if (tilt == 1) p = glm::dvec3(p.y, p.z, p.x);
                    if (tilt == 2) p = glm::dvec3(p.z, p.x, p.y);
                    centroid += p / 3.0;
                }
                EXPECT_FALSE(in_notch(centroid)) << "triangle " << t << " covers the notch";
            }
            EXPECT_NEAR(std::abs(area), 5.0, 1e-9) << "reversed " << reversed << ", tilt " << tilt;
        }
}

TEST(PolygonTriangulation, AStarIsCoveredOnce) { EXPECT_TRUE(expect_covered_once(star(5, 0.4), 1e-6).clipped); }

TEST(PolygonTriangulation, BadPolygonsStillGiveTheirTriangles) {
    // Crossing itself (a bow tie with a notch), all on one line, a corner repeated: n - 2 triangles, every
    // index one of the polygon's.
    const std::vector<std::vector<glm::vec3>> bad = {
        {{0, 0, 0}, {2, 2, 0}, {2, 0, 0}, {1, 0.5f, 0}, {0, 2, 0}},
        {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}},
        {{0, 0, 0}, {2, 0, 0}, {2, 0, 0}, {1, 1, 0}, {1, 0.5f, 0}, {0, 1, 0}},
    };
    for (const auto& polygon : bad) {
        const Cut c = cut(polygon);
        ASSERT_EQ(c.triangles.size(), 3 * (polygon.size() - 2));
        for (uint32_t i : c.triangles) EXPECT_LT(i, polygon.size());
    }
}

// A star of 4,000 points (8,000 corners, half of them reflex; a gear in a CAD export): covered once, as
// the small one (until 2026-12-03 any polygon of more than 256 corners was fanned, a comb of 403 corners
// and area 402 loading as 20,602).
TEST(PolygonTriangulation, ALargeStarIsCoveredOnce) { EXPECT_TRUE(expect_covered_once(star(4000, 0.9), 1e-6).clipped); }

// A star of 100,000 points (200,000 corners, half of them reflex): the clipping, which went back after each
// ear, cut a fan around one corner whose ever longer ears spanned the reflex corners ahead; it spent its
// budget and fanned the rest, which covered 200 times the star's area. It now walks on after an ear and fans
// what is left once no corner is reflex (convex then).
TEST(PolygonTriangulation, AStarOf200000CornersIsCoveredOnce) {
    EXPECT_TRUE(expect_covered_once(star(100000, 0.5), 1e-6).clipped);
}

// Beyond what the budget allows, the cut says so, and the loaders refuse the face in one line (obj_loader.cpp,
// ply_loader.cpp) rather than load a fan that covers the polygon wrongly (a star of 500,000 points spends the
// default budget; here a star of 20,000 a small one).
TEST(PolygonTriangulation, APolygonBeyondTheBudgetIsReported) {
    const std::vector<glm::vec3> polygon = star(20000, 0.5);
    std::vector<uint32_t> corners(polygon.size()), triangles(3 * (polygon.size() - 2));
    for (uint32_t i = 0; i < corners.size(); ++i) corners[i] = i;
    EXPECT_EQ(triangulate_polygon(polygon, corners, triangles, 20000), Triangulated::budget_spent);
    EXPECT_EQ(triangulate_polygon(polygon, corners, triangles), Triangulated::clipped);
}

// An L of area 19 whose straight edges are divided into 75,000 corners (as CAD exports write faces along
// curves that happen to be straight): the corners on the edges are cut off as triangles of no area, and
// the L as the six-cornered polygon it is (the clipping's budget ran out on it, and a fan from where it
// stopped covered 59.8).
TEST(PolygonTriangulation, CornersOnStraightEdgesCostNothing) {
    std::vector<glm::vec3> l;
    auto edge = [&](glm::vec3 a, glm::vec3 b, int pieces) {
        for (int s = 0; s < pieces; ++s) l.push_back(a + (b - a) * (float(s) / float(pieces)));
    };
    edge({0, 0, 0}, {10, 0, 0}, 25000);
    edge({10, 0, 0}, {10, 1, 0}, 1000);
    edge({10, 1, 0}, {1, 1, 0}, 20000);
    edge({1, 1, 0}, {1, 10, 0}, 20000);
    edge({1, 10, 0}, {0, 10, 0}, 1000);
    edge({0, 10, 0}, {0, 0, 0}, 8000);
    expect_covered_once(l, 1e-5);
}

TEST(PolygonTriangulation, PlyFacesAreCutOnceTheirVerticesAreKnown) {
    // The U as one face, listed after its vertices and (legal in PLY) before them.
    const auto dir = test::temp_dir("ply_polygons");
    const std::string vertices = "0 0 0\n3 0 0\n3 2 0\n2 2 0\n2 1 0\n1 1 0\n1 2 0\n0 2 0\n4 0 0\n5 0 0\n5 1 0\n4 1 0\n";
    const std::string face = "8 0 1 2 3 4 5 6 7\n4 8 9 10 11\n";  // the U, then a square beside it
    const std::string vertex_header = "element vertex 12\nproperty float x\nproperty float y\nproperty float z\n";
    const std::string face_header = "element face 2\nproperty list uchar uint vertex_index\n";
    for (bool faces_first : {false, true}) {
        const std::string path = (dir / (faces_first ? "faces_first.ply" : "u.ply")).string();
        const std::string headers = faces_first ? face_header + vertex_header : vertex_header + face_header;
        std::ofstream(path) << "ply\nformat ascii 1.0\n" << headers << "end_header\n"
                            << (faces_first ? face + vertices : vertices + face);
        const Mesh mesh = load_mesh(path);
        ASSERT_EQ(mesh.triangle_count(), 6u + 2u);
        double u_area = 0.0;
        for (size_t t = 0; t < 6; ++t) u_area += triangle_area(mesh, t);
        std::printf("%s: the U's triangles cover %.3f (a fan: 7)\n", faces_first ? "faces first" : "vertices first",
                    u_area);
        EXPECT_NEAR(u_area, 5.0, 1e-6);
        // The convex quad after it keeps its fan.
        EXPECT_EQ(std::vector<uint32_t>(mesh.indices.begin() + 18, mesh.indices.end()),
                  (std::vector<uint32_t>{8, 9, 10, 8, 10, 11}));
    }
}

}  // namespace
}  // namespace stipple
