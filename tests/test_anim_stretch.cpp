// Stretch headroom: the largest area each polygon reaches over an animation, against areas worked out
// by hand for the stretching plane and the bending cylinder.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "anim/procedural_rigs.hpp"
#include "anim/headroom.hpp"
#include "anim/stretch.hpp"
#include "support/anim_files.hpp"

namespace stipple::anim {
namespace {

using test::load_rig;

TEST(AnimStretch, StretchingPlaneReachesTwiceItsArea) {
    const AnimatedModel model = load_rig(rigs::stretching_plane(4), "anim_stretch_plane", "plane");
    const StretchReport report = measure_stretch(model, 0);
    EXPECT_EQ(report.times.size(), 64u);  // the keys (0 and 1) are the uniform samples' ends
    ASSERT_EQ(report.max_area_ratio.size(), 32u);
    for (size_t t = 0; t < 32; ++t) {
        EXPECT_NEAR(report.max_area_ratio[t], 2.0f, 1e-5f) << "triangle " << t;  // every x doubles at t = 1
        EXPECT_NEAR(report.min_area_ratio[t], 1.0f, 1e-5f) << "triangle " << t;  // the rest pose at t = 0
    }
    EXPECT_NEAR(report.max_ratio, 2.0f, 1e-5f);
    EXPECT_NEAR(report.min_ratio, 1.0f, 1e-5f);
    EXPECT_NEAR(report.bounds.max.x, 2.0f, 1e-5f);
    EXPECT_NEAR(report.bounds.min.x, 0.0f, 1e-5f);
}

// The cylinder bent by `degrees` (linear blend skinning written out, as in test_anim_evaluation).
glm::dvec3 bent(const glm::dvec3& p, double degrees) {
    const double w = rigs::cylinder_elbow_weight(static_cast<float>(p.y));
    const glm::dmat3 r(glm::rotate(glm::dmat4(1.0), glm::radians(degrees), glm::dvec3(0, 0, 1)));
    const glm::dvec3 elbow(0.0, 1.0, 0.0);
    return (1.0 - w) * p + w * (r * (p - elbow) + elbow);
}

double area(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) { return 0.5 * glm::length(glm::cross(b - a, c - a)); }

TEST(AnimStretch, BendingCylinderAgainstADenseHandSweep) {
    const AnimatedModel model = load_rig(rigs::bending_cylinder({.rings = 16, .segments = 24}), "anim_stretch_cylinder", "cylinder");
    const StretchReport report = measure_stretch(model, 0);
    const Mesh& rest = model.rest;
    size_t rigid = 0, checked = 0;
    for (size_t t = 0; t < rest.triangle_count(); ++t) {
        glm::dvec3 p[3];
        int moving = 0;
        for (int k = 0; k < 3; ++k) {
            p[k] = glm::dvec3(model.bind_positions[rest.indices[3 * t + k]]);
            const float w = rigs::cylinder_elbow_weight(static_cast<float>(p[k].y));
            moving += w > 0.0f && w < 1.0f;
        }
        const double rest_area = area(p[0], p[1], p[2]);
        // "Bend" sweeps the angle 0 -> 90 -> 0 degrees; sample it a thousand times.
        double hand_max = 0.0, hand_min = INFINITY;
        for (int i = 0; i <= 1000; ++i) {
            const double degrees = 90.0 * i / 1000.0;
            const double ratio = area(bent(p[0], degrees), bent(p[1], degrees), bent(p[2], degrees)) / rest_area;
            hand_max = std::max(hand_max, ratio);
            hand_min = std::min(hand_min, ratio);
        }
        EXPECT_LE(report.max_area_ratio[t], hand_max * (1.0 + 1e-5)) << "triangle " << t;
        EXPECT_GE(report.max_area_ratio[t], hand_max * 0.99) << "triangle " << t;
        EXPECT_GE(report.min_area_ratio[t], hand_min * (1.0 - 1e-5)) << "triangle " << t;
        if (moving == 0) {  // rigid with one joint or the other: its area never changes
            ++rigid;
            EXPECT_NEAR(report.max_area_ratio[t], 1.0f, 1e-5f);
            EXPECT_NEAR(report.min_area_ratio[t], 1.0f, 1e-5f);
        }
        ++checked;
    }
    EXPECT_GT(rigid, checked / 2);
    EXPECT_GT(report.max_ratio, 1.1f);  // the outside of the bend stretches
    EXPECT_LT(report.min_ratio, 0.9f);  // the inside is squeezed
}

// Two vertices at one place at rest, which a morph target pulls apart: the triangle they collapse is kept in the
// rest mesh (a static model's is dropped at load: it has no area and draws creases), else the animation opened
// a hole where it grew (the quad drew half its square).
TEST(AnimStretch, ATriangleCollapsedAtRestIsKeptForTheAnimationToOpen) {
    GltfBuilder quad = rigs::morphed_quad();
    quad.doc["nodes"][0]["weights"] = {0.0, 0.0};
    const int base = quad.add_floats({0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");  // vertex 2 on vertex 1
    const int lift = quad.add_floats({0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0}, "VEC3");
    quad.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = base;
    quad.doc["meshes"][0]["primitives"][0]["targets"][0]["POSITION"] = lift;
    const AnimatedModel model = load_rig(quad, "anim_stretch_collapsed", "collapsed");
    EXPECT_EQ(model.rest.triangle_count(), 2u) << "the collapsed triangle was dropped";
    EXPECT_EQ(measure_headroom(model).opened_triangles, 1u);
    // Without an animation nothing pulls them apart: dropped as in a static model (a morphed UV sphere kept its
    // pole's collapsed triangles, their creases fanning from the pole).
    quad.doc.erase("animations");
    quad.doc["nodes"][0]["weights"] = {0.0, 0.5};  // posed, so the file is read by the animated loader
    const AnimatedModel still = load_rig(quad, "anim_stretch_collapsed_still", "still");
    EXPECT_FALSE(still.is_animated());
    EXPECT_EQ(still.rest.triangle_count(), 1u);
}

// A polygon of no area at rest has no candidates: its ratio (5e-41 at rest, 0.5 posed) went beyond float
// range and info printed "infx" (inf in --json). It reports 1 and is counted as opened, which info says.
TEST(AnimStretch, APolygonOfNoAreaAtRestIsCountedAsOpenedNotAsInfiniteStretch) {
    GltfBuilder quad = rigs::morphed_quad();
    quad.doc["nodes"][0]["weights"] = {0.0, 0.0};  // the rest pose is the base positions
    // Vertex 2 on the edge from vertex 0 to 1: triangle 0 1 2 has no area; target 0 ("lift") opens it.
    const int base = quad.add_floats({0, 0, 0, 1, 0, 0, 0.5f, 0, 0, 0, 1, 0}, "VEC3");
    const int lift = quad.add_floats({0, 0, 0, 0, 0, 0, 0.5f, 1, 0, 0, 0, 0}, "VEC3");
    quad.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = base;
    quad.doc["meshes"][0]["primitives"][0]["targets"][0]["POSITION"] = lift;
    const AnimatedModel model = load_rig(quad, "anim_stretch_opened", "opened");
    const StretchReport report = measure_stretch(model, 0);
    EXPECT_EQ(report.opened_triangles, 1u);
    EXPECT_TRUE(std::isfinite(report.max_ratio));
    EXPECT_EQ(report.max_area_ratio[0], 1.0f) << "the opened polygon reports no stretch";
    const StretchHeadroom headroom = measure_headroom(model);
    EXPECT_EQ(headroom.opened_triangles, 1u);
    EXPECT_NE(describe_headroom(headroom, 2).find("; 1 polygon of no area at rest opens in an animation and is drawn "
                                                  "without stipples"),
              std::string::npos)
        << describe_headroom(headroom, 2);
}

TEST(AnimStretch, SampleTimesAddTheKeyframes) {
    const AnimatedModel model = load_rig(rigs::interpolation_sample("LINEAR"), "anim_stretch_times", "keys");
    const std::vector<double> times = stretch_sample_times(model.animations[0], 64);
    // 64 even samples over 0..4 s, which include 0 and 4 but not the keys at 1 and 2.
    EXPECT_EQ(times.size(), 66u);
    for (double key : {1.0, 2.0, 4.0}) EXPECT_NE(std::find(times.begin(), times.end(), key), times.end()) << key;
    for (size_t i = 1; i < times.size(); ++i) EXPECT_LT(times[i - 1], times[i]);
}

}  // namespace
}  // namespace stipple::anim
