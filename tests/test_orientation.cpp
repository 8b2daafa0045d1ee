// The winding repair (mesh/orientation.hpp): a model whose triangles are wound inconsistently, or one of
// whose parts is inside out, loads with every triangle of each part wound alike and outward; open sheets
// keep their majority's winding; what cannot be made consistent (a Möbius strip, non-manifold fins) is
// counted and left.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "mesh/load_mesh.hpp"
#include "mesh/mesh_ops.hpp"
#include "mesh/orientation.hpp"
#include "mesh/primitives.hpp"
#include "support/test_paths.hpp"
#include "support/test_shapes.hpp"

namespace stipple {
namespace {

using test::face_centroid;
using test::face_normal;

void write_file(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// Triangles of `mesh` in [first, last) facing away from `centre` (a sphere's outward).
size_t facing_inward(const Mesh& mesh, glm::dvec3 centre, size_t first = 0, size_t last = SIZE_MAX) {
    size_t inward = 0;
    for (size_t t = first; t < std::min(last, mesh.triangle_count()); ++t)
        inward += glm::dot(face_normal(mesh, t), face_centroid(mesh, t) - centre) < 0.0;
    return inward;
}

// Reverses about `fraction` of the triangles (seeded), returning how many.
size_t reverse_some(Mesh& mesh, double fraction, uint32_t seed, size_t first = 0, size_t last = SIZE_MAX) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    size_t reversed = 0;
    for (size_t t = first; t < std::min(last, mesh.triangle_count()); ++t)
        if (u(rng) < fraction) std::swap(mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]), ++reversed;
    return reversed;
}

// Every triangle its own three corners, as a glTF primitive without indices or an OBJ with per-face
// normals is read: the parts are joined only through positions.
Mesh unwelded(const Mesh& mesh) {
    Mesh soup;
    soup.source = mesh.source;
    for (uint32_t i : mesh.indices) {
        soup.indices.push_back(uint32_t(soup.positions.size()));
        soup.positions.push_back(mesh.positions[i]);
        soup.normals.push_back(mesh.normals[i]);
    }
    return soup;
}

// A sphere of radius 1 about `centre` with `holes` holes, as a scan has: the triangles whose centroids lie
// within 0.1 of the poles (5% of its area each, their caps 5% more) left out.
Mesh holed_sphere(int holes, glm::vec3 centre = glm::vec3(0.0f)) {
    const Mesh sphere = make_icosphere(3, 1.0f, centre);
    Mesh holed = sphere;
    holed.indices.clear();
    for (size_t t = 0; t < sphere.triangle_count(); ++t) {
        const glm::vec3 c = glm::vec3(face_centroid(sphere, t)) - centre;
        if ((holes >= 1 && c.y > 0.9f) || (holes >= 2 && c.y < -0.9f)) continue;
        holed.indices.insert(holed.indices.end(), &sphere.indices[3 * t], &sphere.indices[3 * t + 3]);
    }
    return holed;
}

// The triangles of `mesh` wound the other way.
void reverse_all(Mesh& mesh) {
    for (size_t t = 0; t < mesh.triangle_count(); ++t) std::swap(mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]);
}

TEST(Winding, MixedTrianglesOfAClosedMeshAgreeAndFaceOutward) {
    for (bool soup : {false, true}) {
        Mesh sphere = make_icosphere(4);
        if (soup) sphere = unwelded(sphere);
        ASSERT_EQ(facing_inward(sphere, glm::dvec3(0.0)), 0u);
        const size_t reversed = reverse_some(sphere, 0.3, 7);
        ASSERT_GT(reversed, sphere.triangle_count() / 4);
        const WindingRepair repair = orient_consistently(sphere);
        std::printf("%s sphere: %zu of %zu triangles reversed, %zu turned in %zu part(s)\n",
                    soup ? "unwelded" : "welded", reversed, sphere.triangle_count(), repair.triangles_turned,
                    repair.parts);
        EXPECT_EQ(repair.parts, 1u);
        EXPECT_EQ(repair.triangles_turned, reversed);
        EXPECT_EQ(repair.wound_against, reversed);
        EXPECT_EQ(repair.parts_turned_outward, 0u);
        EXPECT_EQ(repair.conflicting_edges, 0u);
        EXPECT_EQ(facing_inward(sphere, glm::dvec3(0.0)), 0u);
        // Mostly reversed: the part's majority is then inward, and it is turned outward as a whole.
        reverse_some(sphere, 0.8, 11);
        const WindingRepair again = orient_consistently(sphere);
        EXPECT_EQ(facing_inward(sphere, glm::dvec3(0.0)), 0u);
        EXPECT_EQ(again.parts_turned_outward, 1u);
    }
}

// Corners a rounding step or two apart are one corner (weld_by_position, kWeldFloatSteps): an export that
// wrote each face's corners with its own rounding made every triangle a part of its own, so the winding repair
// turned nothing and every edge was a border (lines in dashes; a jittered cube drew none). Corners farther
// apart stay apart, however large the rest of the file: a first version welded within a millionth of the
// file's extent and dropped 28,907 of a bunny's triangles beside a 600-unit ground quad (all of them beside
// one stray vertex 30,000 units away).
TEST(Winding, CornersARoundingStepApartAreOneCorner) {
    Mesh soup = unwelded(make_icosphere(3));
    const size_t triangles = soup.triangle_count();
    for (size_t v = 0; v < soup.positions.size(); ++v) {  // half the corners one float step off on one axis
        if (v % 2) continue;
        float& x = soup.positions[v][int(v / 2 % 3)];
        x = std::nextafter(x, v % 4 ? 2.0f : -2.0f);
    }
    const std::vector<uint32_t> corner = weld_by_position(soup.positions);
    EXPECT_EQ(border_edge_count(soup), 0u);
    reverse_all(soup);
    const WindingRepair repair = orient_consistently(soup);
    EXPECT_EQ(repair.parts, 1u);
    EXPECT_EQ(repair.triangles_turned, triangles);  // inside out, as one part
    for (size_t v = 0; v < soup.positions.size(); ++v) EXPECT_LE(corner[v], v);  // the first of its set
    // 1e-4 of the extent apart: distinct corners (an open seam of a fine scan, not a rounding).
    Mesh apart = unwelded(make_icosphere(3));
    for (size_t v = 0; v < apart.positions.size(); v += 2) apart.positions[v].x += 2e-4f;
    EXPECT_GT(border_edge_count(apart), apart.triangle_count());
    // A sphere 2e-3 across with 642 corners 1e-4 apart or more, in one file with a 600-unit quad and a stray
    // vertex far away: every corner its own.
    Mesh scene = make_icosphere(3, 1e-3f);
    const size_t small = scene.positions.size();
    for (const glm::vec3 corner : {glm::vec3(-300, -300, -1), glm::vec3(300, -300, -1), glm::vec3(300, 300, -1)})
        scene.indices.push_back(uint32_t(scene.positions.size())), scene.positions.push_back(corner);
    scene.positions.push_back(glm::vec3(30000.0f, 0.0f, 0.0f));
    const std::vector<uint32_t> own = weld_by_position(scene.positions);
    for (size_t v = 0; v < small; ++v) EXPECT_EQ(own[v], v);
}

TEST(Winding, EachPartIsTurnedOutwardOnItsOwn) {
    // Two spheres side by side; the second inside out. A whole-mesh volume (what loading tested before)
    // is zero here and would turn neither.
    Mesh pair = make_icosphere(3, 1.0f, glm::vec3(-2.0f, 0.0f, 0.0f));
    const size_t first = pair.triangle_count();
    append_mesh(pair, make_icosphere(3, 1.0f, glm::vec3(2.0f, 0.0f, 0.0f)));
    for (size_t t = first; t < pair.triangle_count(); ++t) std::swap(pair.indices[3 * t + 1], pair.indices[3 * t + 2]);
    EXPECT_NEAR(signed_volume(pair), 0.0, 1e-3);
    const WindingRepair repair = orient_consistently(pair);
    EXPECT_EQ(repair.parts, 2u);
    EXPECT_EQ(repair.parts_turned_outward, 1u);
    EXPECT_EQ(repair.triangles_turned, pair.triangle_count() - first);
    EXPECT_EQ(facing_inward(pair, glm::dvec3(-2.0, 0.0, 0.0), 0, first), 0u);
    EXPECT_EQ(facing_inward(pair, glm::dvec3(2.0, 0.0, 0.0), first), 0u);
}

TEST(Winding, AnOpenPartIsTurnedOnlyWhenNearlyClosed) {
    // A bowl wound to face its hollow (its concave side) beside a closed sphere: open wide, it encloses
    // nothing, and keeps its winding (a dish, a valley, a room is seen from its hollow).
    Mesh bowl = test::make_open_hemisphere(48, 12);
    reverse_all(bowl);
    EXPECT_LT(signed_volume(bowl), 0.0);
    Mesh scene = make_icosphere(3, 1.0f, glm::vec3(3.0f, 0.0f, 0.0f));
    const size_t sphere_triangles = scene.triangle_count();
    append_mesh(scene, bowl);
    const std::vector<uint32_t> before = scene.indices;
    const WindingRepair kept = orient_consistently(scene);
    EXPECT_EQ(kept.parts, 2u);
    EXPECT_EQ(kept.triangles_turned, 0u);
    EXPECT_EQ(scene.indices, before);
    // Everything reversed: the sphere is turned back by its own volume; the bowl, now facing its convex
    // side, keeps that.
    reverse_all(scene);
    const std::vector<uint32_t> reversed = scene.indices;
    const WindingRepair sphere_turned = orient_consistently(scene);
    EXPECT_EQ(sphere_turned.parts_turned_outward, 1u);
    EXPECT_EQ(facing_inward(scene, glm::dvec3(3.0, 0.0, 0.0), 0, sphere_triangles), 0u);
    EXPECT_TRUE(std::equal(scene.indices.begin() + 3 * sphere_triangles, scene.indices.end(),
                           reversed.begin() + 3 * sphere_triangles));
    // The bowl alone facing its hollow: kept too. Until 2026-12-05 the whole model's volume about its box's
    // centre decided the open parts, and it was turned to face away from where it is seen.
    const std::vector<uint32_t> hollow = bowl.indices;
    const WindingRepair alone = orient_consistently(bowl);
    EXPECT_EQ(alone.parts_turned_outward, 0u);
    EXPECT_EQ(bowl.indices, hollow);
    // A scan with holes wound inward (one hole, or two at opposite poles, a few percent of its area each):
    // nearly closed, its holes capped, it is inside out, and turned.
    for (int holes : {1, 2}) {
        Mesh scan = holed_sphere(holes, glm::vec3(0.5f, 0.0f, 0.0f));
        reverse_all(scan);
        const WindingRepair turned = orient_consistently(scan);
        EXPECT_EQ(turned.parts_turned_outward, 1u) << holes << " hole(s)";
        EXPECT_EQ(facing_inward(scan, glm::dvec3(0.5, 0.0, 0.0)), 0u) << holes << " hole(s)";
        // Wound outward, it stays.
        Mesh outward = holed_sphere(holes);
        const std::vector<uint32_t> right = outward.indices;
        EXPECT_EQ(orient_consistently(outward).triangles_turned, 0u) << holes << " hole(s)";
        EXPECT_EQ(outward.indices, right);
    }
}

// A closed part's own volume decides however little of its box it fills: a thin rod lying across its box
// (0.04% of it here) inside out is turned. Until 2026-12-04 it had to exceed 1% of the box.
TEST(Winding, AThinClosedPartAcrossItsBoxIsTurnedToo) {
    Mesh rod = make_cad_cylinder(16, 0.02f, 4.0f);
    const glm::mat3 tilt = glm::mat3(glm::rotate(glm::mat4(1.0f), glm::radians(54.7356f), glm::vec3(1, 0, -1)));
    for (glm::vec3& p : rod.positions) p = tilt * p;
    for (size_t t = 0; t < rod.triangle_count(); ++t) std::swap(rod.indices[3 * t + 1], rod.indices[3 * t + 2]);
    const Bounds box = compute_bounds(rod);
    const glm::vec3 extent = box.max - box.min;
    ASSERT_LT(-signed_volume(rod), 0.01 * double(extent.x) * extent.y * extent.z);
    const WindingRepair repair = orient_consistently(rod);
    EXPECT_EQ(repair.parts_turned_outward, 1u);
    EXPECT_EQ(repair.triangles_turned, rod.triangle_count());
    EXPECT_GT(signed_volume(rod), 0.0);
}

// Where the file has normals, an open part they clearly contradict is turned to them: a face of a cube
// exported loose (its corners a hair off the rest, so nothing joins it) and wound against its normal was
// left facing in, and the file's correct normals were turned to match it (until 2026-12-04). Normals that
// agree with an inside-out winding leave the decision to the volume, as without normals.
TEST(Winding, ALoosePanelWoundAgainstItsFileNormalsIsTurnedToThem) {
    const auto dir = test::temp_dir("winding_loose_panel");
    // Five faces of a unit cube sharing 8 corners, outward, with outward face normals; the +z face on its own
    // corners 1e-6 out (8 float steps: beyond the weld's, kWeldFloatSteps), wound clockwise seen from outside.
    const std::string box = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                            "v 0 0 1.000001\nv 1 0 1.000001\nv 1 1 1.000001\nv 0 1 1.000001\n"
                            "vn 0 0 -1\nvn 0 -1 0\nvn 1 0 0\nvn 0 1 0\nvn -1 0 0\nvn 0 0 1\n"
                            "f 1//1 4//1 3//1 2//1\nf 1//2 2//2 6//2 5//2\nf 2//3 3//3 7//3 6//3\n"
                            "f 3//4 4//4 8//4 7//4\nf 4//5 1//5 5//5 8//5\nf 9//6 12//6 11//6 10//6\n";
    write_file((dir / "loose.obj").string(), box);
    const Mesh cube = load_mesh((dir / "loose.obj").string());
    EXPECT_EQ(cube.winding.parts_turned_to_normals, 1u);
    EXPECT_EQ(cube.winding.normals_turned, 0u);
    EXPECT_EQ(facing_inward(cube, glm::dvec3(0.5)), 0u);
    // A lone quad wound against its normal says nothing about which is wrong: its winding stays.
    write_file((dir / "quad.obj").string(), "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1//1 4//1 3//1 2//1\n");
    const Mesh quad = load_mesh((dir / "quad.obj").string());
    EXPECT_EQ(quad.winding.parts_turned_to_normals, 0u);
    for (size_t t = 0; t < quad.triangle_count(); ++t) EXPECT_LT(face_normal(quad, t).z, 0.0) << t;
    // A bowl wound outward with normals inward (an open scan whose normals are what is wrong): the
    // normals contradict all of the model, so they are not followed (it was turned inside out by them).
    auto bowl_text = [](const Mesh& bowl, float normal_sign) {
        std::string text;
        for (size_t v = 0; v < bowl.vertex_count(); ++v) {
            const glm::vec3 p = bowl.positions[v], n = normal_sign * bowl.normals[v];
            text += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
            text += "vn " + std::to_string(n.x) + " " + std::to_string(n.y) + " " + std::to_string(n.z) + "\n";
        }
        for (size_t t = 0; t < bowl.triangle_count(); ++t) {
            text += "f";
            for (int k = 0; k < 3; ++k)
                text += " " + std::to_string(bowl.indices[3 * t + k] + 1) + "//" + std::to_string(bowl.indices[3 * t + k] + 1);
            text += "\n";
        }
        return text;
    };
    {
        Mesh outward = test::make_open_hemisphere(48, 12);
        compute_vertex_normals(outward);
        ASSERT_GT(signed_volume(outward), 0.0);
        write_file((dir / "bowl_normals_in.obj").string(), bowl_text(outward, -1.0f));
        const Mesh kept = load_mesh((dir / "bowl_normals_in.obj").string());
        EXPECT_EQ(kept.winding.triangles_turned, 0u);
        EXPECT_GT(signed_volume(kept), 0.0);
    }
    // `mesh` wound the other way, with normals that agree, written as an OBJ and loaded.
    auto inward_with_normals = [&](Mesh mesh, const std::string& name) {
        reverse_all(mesh);
        compute_vertex_normals(mesh);
        write_file((dir / name).string(), bowl_text(mesh, 1.0f));
        return load_mesh((dir / name).string());
    };
    // A bowl wound toward its hollow with normals that agree (a valley, a dish): kept, normals and all. Until
    // 2026-12-05 the volume turned it, and from above it drew no stipples.
    const Mesh kept = inward_with_normals(test::make_open_hemisphere(48, 12), "bowl.obj");
    EXPECT_EQ(kept.winding.triangles_turned, 0u);
    EXPECT_EQ(kept.winding.normals_turned, 0u);
    EXPECT_LT(signed_volume(kept), 0.0);
    // A scan with a hole wound inward, normals included: nearly closed, its volume turns it, normals and all.
    const Mesh turned = inward_with_normals(holed_sphere(1), "scan.obj");
    EXPECT_EQ(turned.winding.parts_turned_outward, 1u);
    EXPECT_EQ(turned.winding.parts_turned_to_normals, 0u);
    EXPECT_EQ(facing_inward(turned, glm::dvec3(0.0)), 0u);
}

TEST(Winding, AnOpenSheetKeepsItsMajoritysWinding) {
    // A flat disc facing +z: no volume to tell outward by, so the winding most of its area has decides.
    for (double fraction : {0.2, 0.8}) {
        Mesh disc = test::make_disc(48, 12);
        const size_t reversed = reverse_some(disc, fraction, 3);
        const WindingRepair repair = orient_consistently(disc);
        size_t up = 0;
        for (size_t t = 0; t < disc.triangle_count(); ++t) up += face_normal(disc, t).z > 0.0;
        std::printf("disc, %.0f%% reversed: %zu of %zu face +z after the repair\n", 100 * fraction, up,
                    disc.triangle_count());
        EXPECT_EQ(repair.parts_turned_outward, 0u);
        if (fraction < 0.5) {
            EXPECT_EQ(up, disc.triangle_count());
            EXPECT_EQ(repair.triangles_turned, reversed);
        } else {
            EXPECT_EQ(up, 0u);
            EXPECT_EQ(repair.triangles_turned, disc.triangle_count() - reversed);
        }
    }
}

TEST(Winding, WhatNoWindingCanFixIsCountedAndLeft) {
    // A Möbius strip: 2 * n triangles around a half-twisted band. One edge must stay in conflict.
    Mesh strip;
    const int n = 24;
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * M_PI * i / n, half = a / 2.0;
        const glm::dvec3 centre(std::cos(a), std::sin(a), 0.0);
        const glm::dvec3 across = 0.3 * (std::cos(half) * glm::dvec3(std::cos(a), std::sin(a), 0.0) +
                                         std::sin(half) * glm::dvec3(0.0, 0.0, 1.0));
        strip.positions.push_back(glm::vec3(centre - across));
        strip.positions.push_back(glm::vec3(centre + across));
    }
    for (int i = 0; i < n; ++i) {
        // The last quad joins the band's end to its start with the sides exchanged: the half twist.
        const uint32_t a = 2 * i, b = 2 * i + 1;
        const uint32_t c = i + 1 < n ? 2 * (i + 1) : 1, d = i + 1 < n ? 2 * (i + 1) + 1 : 0;
        strip.indices.insert(strip.indices.end(), {a, c, b, b, c, d});
    }
    compute_vertex_normals(strip);
    const WindingRepair repair = orient_consistently(strip);
    EXPECT_EQ(repair.parts, 1u);
    EXPECT_EQ(repair.conflicting_edges, 1u);

    // A fin: a third triangle on one edge of a box makes that edge non-manifold; the box is still
    // repaired through its other edges, and the fin (joined only there) is a part of its own.
    Mesh box = test::make_box(glm::vec3(1.0f));
    const uint32_t tip = uint32_t(box.positions.size());
    box.positions.push_back(glm::vec3(1.5f, 1.5f, 0.0f));
    box.normals.push_back(glm::vec3(0.0f, 0.0f, 1.0f));
    box.indices.insert(box.indices.end(), {box.indices[0], box.indices[1], tip});
    std::swap(box.indices[3 * 5 + 1], box.indices[3 * 5 + 2]);
    const WindingRepair boxed = orient_consistently(box);
    EXPECT_EQ(boxed.parts, 2u);
    EXPECT_EQ(boxed.triangles_turned, 1u);
    EXPECT_EQ(facing_inward(box, glm::dvec3(0.0), 0, 12), 0u);
}

TEST(Winding, LoadingRepairsTheWindingAndTheNormalsFollow) {
    const auto dir = test::temp_dir("winding");
    Mesh sphere = make_icosphere(3);
    reverse_some(sphere, 0.3, 5);

    // Without normals in the file, the computed ones follow the repaired winding: all outward. (From the
    // mixed winding they cancel, and many point inward.)
    const std::string computed_path = (dir / "mixed.obj").string();
    write_file(computed_path, test::obj_text(sphere));
    const Mesh computed = load_mesh(computed_path);
    EXPECT_GT(computed.winding.triangles_turned, 0u);
    EXPECT_EQ(facing_inward(computed, glm::dvec3(0.0)), 0u);
    size_t inward_normals = 0;
    for (size_t v = 0; v < computed.vertex_count(); ++v)
        inward_normals += glm::dot(computed.normals[v], computed.positions[v]) <= 0.5f;
    EXPECT_EQ(inward_normals, 0u);

    // A file whose whole sphere is inside out, normals included (faces as v//vn so that they are used):
    // winding and normals turn outward.
    Mesh inside_out = make_icosphere(3);
    std::string text;
    for (const glm::vec3& p : inside_out.positions) {
        const glm::vec3 n = -glm::normalize(p);
        text += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
        text += "vn " + std::to_string(n.x) + " " + std::to_string(n.y) + " " + std::to_string(n.z) + "\n";
    }
    for (size_t t = 0; t < inside_out.triangle_count(); ++t) {
        text += "f";
        for (int k : {0, 2, 1}) {
            const std::string i = std::to_string(inside_out.indices[3 * t + k] + 1);
            text += " " + i + "//" + i;
        }
        text += "\n";
    }
    const std::string normals_path = (dir / "inside_out_with_normals.obj").string();
    write_file(normals_path, text);
    const Mesh turned = load_mesh(normals_path);
    EXPECT_EQ(turned.winding.parts_turned_outward, 1u);
    EXPECT_EQ(turned.winding.normals_turned, turned.vertex_count());
    EXPECT_EQ(facing_inward(turned, glm::dvec3(0.0)), 0u);
    for (size_t v = 0; v < turned.vertex_count(); ++v)
        ASSERT_GT(glm::dot(turned.normals[v], turned.positions[v]), 0.9f) << "vertex " << v;
}

TEST(RepeatedFaces, ExactRepeatsAreDroppedAndReversedCopiesKept) {
    Mesh sphere = unwelded(make_icosphere(2));  // repeats are found through welded corners
    const size_t triangles = sphere.triangle_count();
    Mesh doubled = sphere;
    // Every triangle again, rotated (the same face, starting at another corner); then every third one
    // reversed, which is kept.
    for (size_t t = 0; t < triangles; ++t) {
        const uint32_t base = uint32_t(doubled.positions.size());
        for (int k : {1, 2, 0}) {
            doubled.positions.push_back(sphere.positions[sphere.indices[3 * t + k]]);
            doubled.normals.push_back(sphere.normals[sphere.indices[3 * t + k]]);
        }
        doubled.indices.insert(doubled.indices.end(), {base, base + 1, base + 2});
    }
    size_t reversed = 0;
    for (size_t t = 0; t < triangles; t += 3, ++reversed)
        doubled.indices.insert(doubled.indices.end(),
                               {sphere.indices[3 * t], sphere.indices[3 * t + 2], sphere.indices[3 * t + 1]});
    const std::vector<uint32_t> first_copy(doubled.indices.begin(), doubled.indices.begin() + 3 * triangles);
    EXPECT_EQ(drop_duplicate_triangles(doubled), triangles);
    ASSERT_EQ(doubled.triangle_count(), triangles + reversed);
    EXPECT_TRUE(std::equal(first_copy.begin(), first_copy.end(), doubled.indices.begin()))
        << "the first of each is kept, in order";
    EXPECT_EQ(drop_duplicate_triangles(doubled), 0u);

    // Through loading: a surface exported twice loads as once, with its triangles joined into one part.
    Mesh twice = make_icosphere(3);
    const size_t once = twice.triangle_count();
    twice.indices.insert(twice.indices.end(), twice.indices.begin(), twice.indices.end());
    const auto dir = test::temp_dir("repeated_faces");
    write_file((dir / "twice.obj").string(), test::obj_text(twice));
    const Mesh loaded = load_mesh((dir / "twice.obj").string());
    EXPECT_EQ(loaded.triangle_count(), once);
    EXPECT_EQ(loaded.duplicates_dropped, once);
    EXPECT_EQ(loaded.winding.parts, 1u);
}

// A triangle two of whose corners lie at one place (a a b, or two vertices of one position) has no area and no
// edge of its own: it is dropped at load. Kept, its edges counted as faces' edges: creases fanned over a smooth
// sphere from its pole, and each split its part in the winding repair (5,952 parts on a UV sphere).
TEST(RepeatedFaces, TrianglesWithTwoCornersAtOnePlaceAreDropped) {
    Mesh sphere = make_icosphere(3);
    const size_t clean = sphere.triangle_count();
    const uint32_t extra = uint32_t(sphere.positions.size());
    for (size_t t = 0; t < clean; t += 4) {
        const uint32_t a = sphere.indices[3 * t], b = sphere.indices[3 * t + 1];
        sphere.indices.insert(sphere.indices.end(), {a, a, b});  // one index twice
    }
    for (size_t t = 2; t < clean; t += 4) {  // a second vertex at a corner's place
        const uint32_t a = sphere.indices[3 * t], b = sphere.indices[3 * t + 1];
        sphere.positions.push_back(sphere.positions[a]);
        sphere.normals.push_back(sphere.normals[a]);
        sphere.indices.insert(sphere.indices.end(), {a, b, uint32_t(sphere.positions.size() - 1)});
    }
    ASSERT_GT(sphere.positions.size(), extra);
    const size_t added = sphere.triangle_count() - clean;
    const auto dir = test::temp_dir("degenerate_faces");
    write_file((dir / "sphere.obj").string(), test::obj_text(sphere));
    const Mesh loaded = load_mesh((dir / "sphere.obj").string());
    std::printf("%zu triangles with two corners at one place added to %zu: %zu loaded, %zu dropped, %zu part(s)\n", added, clean,
                loaded.triangle_count(), loaded.duplicates_dropped, loaded.winding.parts);
    EXPECT_EQ(loaded.triangle_count(), clean);
    EXPECT_EQ(loaded.duplicates_dropped, added);
    EXPECT_EQ(loaded.winding.parts, 1u);
    EXPECT_EQ(loaded.winding.triangles_turned, 0u);
}

// A sheet made two-sided by a reversed copy on the same vertices: the computed normals of the two sides
// summed to nothing at every vertex (+Z everywhere, what the toon ramp then read) until 2026-12-04. Each
// such vertex is now split, one copy for the side turned away, so each side is smooth and faces its own
// way, whether the copy repeats the triangles reversed or cuts its quads along the other diagonal.
TEST(RepeatedFaces, AReversedCopyOnTheSameVerticesGetsItsOwn) {
  for (const bool other_diagonal : {false, true}) {
    Mesh sheet = make_grid(8);
    for (glm::vec3& p : sheet.positions) p.z = 0.3f * p.x * p.x;  // curved, so that smooth differs from flat
    const size_t one_side = sheet.triangle_count(), vertices = sheet.vertex_count();
    if (!other_diagonal) {
        for (size_t t = 0; t < one_side; ++t)
            sheet.indices.insert(sheet.indices.end(), {sheet.indices[3 * t], sheet.indices[3 * t + 2], sheet.indices[3 * t + 1]});
    } else {  // the grid's (n+1)^2 vertices row by row; each cell's quad reversed, cut along its other diagonal
        const uint32_t row = 9;
        for (uint32_t y = 0; y < 8; ++y)
            for (uint32_t x = 0; x < 8; ++x) {
                const uint32_t a = y * row + x, b = a + 1, c = a + row + 1, d = a + row;
                sheet.indices.insert(sheet.indices.end(), {a, d, b, b, d, c});
            }
    }
    const auto dir = test::temp_dir("reversed_copy");
    write_file((dir / "two_sided.obj").string(), test::obj_text(sheet));
    const Mesh loaded = load_mesh((dir / "two_sided.obj").string());
    ASSERT_EQ(loaded.triangle_count(), 2 * one_side);
    EXPECT_EQ(loaded.vertex_count(), 2 * vertices);
    for (size_t t = 0; t < loaded.triangle_count(); ++t)
        for (int k = 0; k < 3; ++k)
            ASSERT_GT(glm::dot(glm::dvec3(loaded.normals[loaded.indices[3 * t + k]]), glm::normalize(face_normal(loaded, t))), 0.9)
                << "triangle " << t << " corner " << k << (other_diagonal ? " (other diagonal)" : "");
    // Sides on vertices of their own already are left as they are, and so is a closed surface.
    Mesh again = loaded;
    EXPECT_EQ(split_vertices_between_opposite_sides(again), 0u);
  }
  Mesh sphere = make_icosphere(3);
  EXPECT_EQ(split_vertices_between_opposite_sides(sphere), 0u);
}

// A reversed copy on the same vertices makes every edge one of four triangles: no edge joined two, each triangle
// was a part of its own, turned or not by the rounding of a volume of nothing (8,594 of a curved sheet's 24,964
// triangles turned, so that both copies faced one way in places: drawn twice, and lined along every cell). The
// winding repair sets the reversed copies aside, orients the rest, and winds each copy against its first: the
// sheet is one part as in its file, and a closed sphere with a reversed copy keeps its outside out.
TEST(RepeatedFaces, AReversedCopyKeepsBothSidesAsTheFileWindsThem) {
    Mesh sheet = make_grid(30);
    for (glm::vec3& p : sheet.positions) p.z = 0.15f * std::sin(3.0f * p.x) * std::cos(2.0f * p.y);
    Mesh sphere = make_icosphere(3);
    for (Mesh* mesh : {&sheet, &sphere}) {
        const size_t one_side = mesh->triangle_count();
        for (size_t t = 0; t < one_side; ++t)
            mesh->indices.insert(mesh->indices.end(), {mesh->indices[3 * t], mesh->indices[3 * t + 2], mesh->indices[3 * t + 1]});
        const auto dir = test::temp_dir("reversed_copy_winding");
        write_file((dir / "two_sided.obj").string(), test::obj_text(*mesh));
        const Mesh loaded = load_mesh((dir / "two_sided.obj").string());
        std::printf("%s with a reversed copy: %zu triangles, %zu part(s), %zu turned, %zu turned outward\n",
                    mesh == &sheet ? "sheet" : "sphere", loaded.triangle_count(), loaded.winding.parts,
                    loaded.winding.triangles_turned, loaded.winding.parts_turned_outward);
        ASSERT_EQ(loaded.triangle_count(), 2 * one_side);
        EXPECT_EQ(loaded.winding.parts, 1u);
        EXPECT_EQ(loaded.winding.triangles_turned, 0u);
        // Each copy faces against its first, the first as the file had it.
        size_t against = 0, as_file = 0;
        for (size_t t = 0; t < one_side; ++t) {
            against += glm::dot(face_normal(loaded, t), face_normal(loaded, t + one_side)) < 0.0;
            as_file += glm::dot(face_normal(loaded, t), face_normal(*mesh, t)) > 0.0;
        }
        EXPECT_EQ(against, one_side);
        EXPECT_EQ(as_file, one_side);
    }
}

// The shared models are consistent already (the horse inside out as a whole): the repair turns nothing
// else, so their stipples and the figures measured on them stay.
TEST(Winding, SharedModelsKeepTheirWinding) {
    struct Expected {
        const char* name;
        size_t turned;
    };
    for (const Expected& e : {Expected{"stanford-bunny.obj", 0}, Expected{"ogre.obj", 0}, Expected{"igea.ply", 0},
                              Expected{"spot.obj", 0}, Expected{"horse.ply", 96'966}}) {
        const std::string path = test::shared_model(e.name);
        if (path.empty()) {
            std::printf("skipped %s: not in the shared models folder\n", e.name);
            continue;
        }
        const Mesh mesh = load_mesh(path);
        std::printf("%s: %zu part(s), %zu turned, %zu outward, %zu conflicting edges\n", e.name, mesh.winding.parts,
                    mesh.winding.triangles_turned, mesh.winding.parts_turned_outward, mesh.winding.conflicting_edges);
        EXPECT_EQ(mesh.winding.triangles_turned, e.turned) << e.name;
        EXPECT_EQ(mesh.winding.wound_against, 0u) << e.name;
    }
}

// Whether a surface is open decides whether the depth pass holds its back faces (depth_holds_back_faces):
// the rims of a hemisphere's opening are border edges, a closed sphere has none, and the count loading
// keeps is the one counted afresh.
TEST(Winding, BorderEdgesAreCountedOnceForTheRenderer) {
    const Mesh closed = make_icosphere(2);
    EXPECT_EQ(border_edge_count(closed), 0u);
    const int segments = 24;
    const Mesh bowl = test::make_open_hemisphere(segments, 6);
    EXPECT_EQ(border_edge_count(bowl), size_t(segments)) << "the rim of the bowl";
    Mesh repaired = bowl;
    repaired.winding = orient_consistently(repaired);
    EXPECT_EQ(repaired.winding.border_edges, size_t(segments));
    EXPECT_EQ(border_edge_count(repaired), size_t(segments));
    const std::string bunny = test::shared_model("stanford-bunny.obj");
    if (bunny.empty()) return;
    const Mesh loaded = load_mesh(bunny);
    Mesh fresh = loaded;
    fresh.winding = {};
    std::printf("stanford-bunny.obj: %zu border edges\n", loaded.winding.border_edges);
    EXPECT_GT(loaded.winding.border_edges, 100u) << "the bunny's base has holes";
    EXPECT_EQ(border_edge_count(fresh), loaded.winding.border_edges);
}

}  // namespace
}  // namespace stipple
