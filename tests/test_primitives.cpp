// Procedural meshes: triangle counts, vertices on the sphere, unit outward normals, CCW-outward
// winding, grid layout.
#include <cmath>
#include <numbers>
#include <cstdio>
#include <set>
#include <utility>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "mesh/orientation.hpp"
#include "mesh/primitives.hpp"
#include "support/test_shapes.hpp"

namespace stipple {
namespace {

using test::face_centroid;
using test::face_normal;

// Every vertex at `radius` from `center`, unit normals pointing along the radius, every triangle
// non-degenerate and counter-clockwise seen from outside.
void expect_sphere(const Mesh& mesh, float radius, glm::vec3 center) {
    ASSERT_NO_THROW(validate_mesh(mesh));
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    double worst_radius = 0.0, worst_normal = 0.0, worst_dir = 1.0;
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::dvec3 d = glm::dvec3(mesh.positions[i]) - glm::dvec3(center);
        worst_radius = std::max(worst_radius, std::abs(glm::length(d) - radius) / radius);
        const glm::dvec3 n(mesh.normals[i]);
        worst_normal = std::max(worst_normal, std::abs(glm::length(n) - 1.0));
        worst_dir = std::min(worst_dir, glm::dot(n, glm::normalize(d)));
    }
    std::printf("  %s: %zu triangles, %zu vertices, max |r - R|/R %.2e, max | |n| - 1 | %.2e, min n.dir %.6f\n",
                mesh.source.c_str(), mesh.triangle_count(), mesh.vertex_count(), worst_radius, worst_normal, worst_dir);
    EXPECT_LT(worst_radius, 1e-6);
    EXPECT_LT(worst_normal, 1e-6);
    EXPECT_GT(worst_dir, 0.999999);
    size_t inward = 0, degenerate = 0;
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
        const glm::dvec3 n = face_normal(mesh, t);
        if (glm::length(n) <= 0.0) ++degenerate;
        if (glm::dot(n, face_centroid(mesh, t) - glm::dvec3(center)) <= 0.0) ++inward;
    }
    EXPECT_EQ(inward, 0u) << "triangles not counter-clockwise seen from outside";
    EXPECT_EQ(degenerate, 0u);
}

// A closed 2-manifold: every undirected edge is shared by exactly two triangles, in opposite
// directions (consistent winding), and V - E + F = 2.
void expect_closed_sphere_topology(const Mesh& mesh) {
    std::set<std::pair<uint32_t, uint32_t>> directed;
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
        for (int e = 0; e < 3; ++e) {
            const uint32_t a = mesh.indices[3 * t + e], b = mesh.indices[3 * t + (e + 1) % 3];
            EXPECT_TRUE(directed.insert({a, b}).second) << "directed edge used twice: inconsistent winding";
        }
    }
    size_t unmatched = 0;
    for (const auto& [a, b] : directed) unmatched += directed.count({b, a}) == 0;
    EXPECT_EQ(unmatched, 0u) << "open edges";
    const auto v = static_cast<long long>(mesh.vertex_count()), e = static_cast<long long>(directed.size() / 2),
               f = static_cast<long long>(mesh.triangle_count());
    EXPECT_EQ(v - e + f, 2);
}

TEST(Primitives, UvSphereTriangleCountNearTarget) {
    for (size_t target : {8u, 100u, 500u, 20000u, 200000u}) {
        const Mesh mesh = make_uv_sphere(target);
        const double error = std::abs(double(mesh.triangle_count()) - double(target)) / double(target);
        std::printf("target %zu -> %zu triangles (%.1f%%)\n", target, mesh.triangle_count(), 100.0 * error);
        EXPECT_LE(error, target >= 500 ? 0.06 : 0.5);
    }
}

TEST(Primitives, UvSphereGeometry) {
    expect_sphere(make_uv_sphere(2000), 1.0f, glm::vec3(0.0f));
    const Mesh moved = make_uv_sphere(5000, 2.5f, glm::vec3(1.0f, -2.0f, 3.0f));
    expect_sphere(moved, 2.5f, glm::vec3(1.0f, -2.0f, 3.0f));
    expect_closed_sphere_topology(make_uv_sphere(2000));
    // The area approaches the sphere's 4 pi r^2 from below as the tessellation refines.
    const double coarse = total_area(make_uv_sphere(500)), fine = total_area(make_uv_sphere(200000));
    std::printf("area 500 tris %.5f, 200k tris %.5f, 4 pi %.5f\n", coarse, fine, 4.0 * std::numbers::pi);
    EXPECT_LT(coarse, fine);
    EXPECT_NEAR(fine, 4.0 * std::numbers::pi, 4.0 * std::numbers::pi * 1e-4);
}

TEST(Primitives, IcosphereCountsAndGeometry) {
    for (int s = 0; s <= 5; ++s) {
        const Mesh mesh = make_icosphere(s);
        const size_t expected = 20 * (size_t(1) << (2 * s));
        EXPECT_EQ(mesh.triangle_count(), expected) << "subdivisions " << s;
        EXPECT_EQ(mesh.vertex_count(), expected / 2 + 2) << "subdivisions " << s;
    }
    expect_sphere(make_icosphere(4), 1.0f, glm::vec3(0.0f));
    expect_sphere(make_icosphere(3, 0.5f, glm::vec3(-4.0f, 0.0f, 2.0f)), 0.5f, glm::vec3(-4.0f, 0.0f, 2.0f));
    expect_closed_sphere_topology(make_icosphere(3));
}

TEST(Primitives, Grid) {
    const Mesh mesh = make_grid(7, 3.0f);
    ASSERT_NO_THROW(validate_mesh(mesh));
    EXPECT_EQ(mesh.triangle_count(), 2u * 7 * 7);
    EXPECT_EQ(mesh.vertex_count(), 8u * 8);
    const Bounds b = compute_bounds(mesh);
    EXPECT_FLOAT_EQ(b.min.x, -1.5f);
    EXPECT_FLOAT_EQ(b.max.y, 1.5f);
    EXPECT_FLOAT_EQ(b.max.z, 0.0f);
    EXPECT_NEAR(total_area(mesh), 9.0, 1e-5);
    for (const glm::vec3& n : mesh.normals) EXPECT_EQ(n, glm::vec3(0.0f, 0.0f, 1.0f));
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
        const glm::dvec3 n = face_normal(mesh, t);
        EXPECT_GT(n.z, 0.0) << "triangle " << t << " not counter-clockwise seen from +Z";
        EXPECT_NEAR(glm::length(n) / 2.0, 9.0 / (2 * 49), 1e-5);
    }
    EXPECT_EQ(make_grid(1).triangle_count(), 2u);
}

TEST(Primitives, CadCylinder) {
    Mesh mesh = make_cad_cylinder(64, 1.0f, 4.0f);
    ASSERT_NO_THROW(validate_mesh(mesh));
    EXPECT_EQ(mesh.triangle_count(), 4u * 64);
    // Closed once its split rims are welded, wound outward: the repair has nothing to turn.
    EXPECT_NEAR(signed_volume(mesh), 4.0 * 64 / 2 * std::sin(2 * std::numbers::pi / 64), 1e-3);
    const WindingRepair repair = orient_consistently(mesh);
    EXPECT_EQ(repair.parts, 1u);
    EXPECT_EQ(repair.triangles_turned, 0u);
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
        const glm::dvec3 n = face_normal(mesh, t);
        const glm::dvec3 a(mesh.positions[mesh.indices[3 * t]]), b(mesh.positions[mesh.indices[3 * t + 1]]),
            c(mesh.positions[mesh.indices[3 * t + 2]]);
        const glm::dvec3 centroid = (a + b + c) / 3.0;
        // Outward: radially on the side, along the axis on the caps.
        const glm::dvec3 outward = std::abs(centroid.y) > 1.999 ? glm::dvec3(0.0, centroid.y, 0.0)
                                                                 : glm::dvec3(centroid.x, 0.0, centroid.z);
        EXPECT_GT(glm::dot(n, outward), 0.0) << "triangle " << t;
    }
    // The side's slivers: 4 long, 2 sin(pi / 64) ~ 0.098 wide.
    EXPECT_NEAR(glm::length(mesh.positions[1] - mesh.positions[0]) / glm::length(mesh.positions[2] - mesh.positions[0]),
                4.0 / (2 * std::sin(std::numbers::pi / 64)), 1e-2);
    EXPECT_THROW(make_cad_cylinder(2), Error);
}

TEST(Primitives, BadArgumentsThrow) {
    EXPECT_THROW(make_uv_sphere(100, 0.0f), Error);
    EXPECT_THROW(make_uv_sphere(100, -1.0f), Error);
    EXPECT_THROW(make_icosphere(-1), Error);
    EXPECT_THROW(make_icosphere(11), Error);
    EXPECT_THROW(make_grid(0), Error);
    EXPECT_THROW(make_grid(4, std::nanf("")), Error);
}

}  // namespace
}  // namespace stipple
