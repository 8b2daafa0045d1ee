// Which direction the progressive order's slabs lie across (src/stipple/slab_direction.hpp): long slivers
// must be left whole, whichever way they lie, and a scan keeps its longest axis.
#include <cmath>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "mesh/primitives.hpp"
#include "stipple/slab_direction.hpp"
#include "stipple/stipple_set.hpp"

namespace stipple {
namespace {

// The rule progressive_order.cpp uses (its kSearchCap, kSlabs, kMinSlabSearches).
SlabRule rule_for(const StippleSet& set) { return SlabRule{set.poisson_radius, 24.0, 24, 4.0}; }

StippleSet stipples_of(const Mesh& mesh, float dmax) {
    GenerationParams params;
    params.dmax = dmax;
    params.relax_iterations = 0;  // where the stipples lie within their triangles does not matter here
    return generate_stipples(mesh, params);
}

Mesh turned(Mesh mesh, const glm::mat3& turn) {
    for (glm::vec3& p : mesh.positions) p = turn * p;
    for (glm::vec3& n : mesh.normals) n = turn * n;
    return mesh;
}

// The stipples in the cylinder's side slivers (its first 2 * sides triangles) that the direction cuts.
uint64_t side_stipples_cut(const SlabDirection& choice, const StippleSet& set, int sides) {
    const float split = rule_for(set).split_extent(choice.size);
    uint64_t cut = 0;
    for (int t = 0; t < 2 * sides; ++t)
        if (choice.extent[t] > split) cut += set.first[t + 1] - set.first[t];
    return cut;
}

TEST(SlabDirection, SliversAlongAnAxisAreLeftWhole) {
    const Mesh cylinder = make_cad_cylinder(256);  // slivers along y, 4 long, the caps 2 across
    const StippleSet set = stipples_of(cylinder, 0.05f);
    const SlabDirection choice = choose_slab_direction(set.positions, set.first, rule_for(set));
    std::printf("upright cylinder: slabs across (%.3f, %.3f, %.3f), %llu of %zu stipples in cut triangles\n",
                choice.direction.x, choice.direction.y, choice.direction.z,
                static_cast<unsigned long long>(choice.cut_stipples), set.positions.size());
    EXPECT_NEAR(choice.direction.y, 0.0f, 1e-6f) << "slabs across y (the longest axis) cut every sliver";
    EXPECT_EQ(side_stipples_cut(choice, set, 256), 0u);
    EXPECT_GE(rule_for(set).slab_count(choice.size), 2.0) << "two slabs at least, for two cores";
}

TEST(SlabDirection, SliversAlongNoAxisAreLeftWhole) {
    const glm::mat3 turn = glm::mat3(glm::rotate(glm::mat4(1.0f), glm::radians(25.0f), glm::vec3(1, 0, 0)) *
                                     glm::rotate(glm::mat4(1.0f), glm::radians(40.0f), glm::vec3(0, 0, 1)));
    const Mesh cylinder = turned(make_cad_cylinder(256), turn);
    const glm::vec3 axis = turn * glm::vec3(0, 1, 0);
    const StippleSet set = stipples_of(cylinder, 0.05f);
    const SlabDirection choice = choose_slab_direction(set.positions, set.first, rule_for(set));
    std::printf("turned cylinder: slabs across (%.3f, %.3f, %.3f), %.4f along its axis; %llu of %zu stipples cut\n",
                choice.direction.x, choice.direction.y, choice.direction.z, glm::dot(choice.direction, axis),
                static_cast<unsigned long long>(choice.cut_stipples), set.positions.size());
    EXPECT_NEAR(glm::length(choice.direction), 1.0f, 1e-5f);
    EXPECT_LT(std::abs(glm::dot(choice.direction, axis)), 0.01f) << "the slabs should lie along the slivers";
    EXPECT_EQ(side_stipples_cut(choice, set, 256), 0u);
    EXPECT_GE(rule_for(set).slab_count(choice.size), 2.0);
}

TEST(SlabDirection, AModelOfSmallTrianglesKeepsItsLongestAxis) {
    // An ellipsoid of small triangles, longest along z: nothing is cut across any axis.
    Mesh sphere = make_icosphere(5);
    for (glm::vec3& p : sphere.positions) p *= glm::vec3(1.0f, 1.5f, 3.0f);
    const StippleSet set = stipples_of(sphere, 0.25f);
    const SlabDirection choice = choose_slab_direction(set.positions, set.first, rule_for(set));
    EXPECT_EQ(choice.direction, glm::vec3(0, 0, 1));
    EXPECT_EQ(choice.cut_stipples, 0u);
}

// A box of 12 triangles, 2 x 0.02 x 2 (a plate).
Mesh thin_plate() {
    Mesh mesh;
    mesh.source = "plate";
    for (int i = 0; i < 8; ++i)
        mesh.positions.push_back(glm::vec3(i & 1 ? 1.0f : -1.0f, i & 2 ? 0.01f : -0.01f, i & 4 ? 1.0f : -1.0f));
    // Outward, counter-clockwise: -x, +x, -y, +y, -z, +z.
    mesh.indices = {0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4,
                    2, 6, 7, 2, 7, 3, 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6};
    return mesh;
}

TEST(SlabDirection, APlateIsNotCutAcrossItsThickness) {
    // Across y its faces would not be cut (the large ones are flat in y, the thin ones 0.02 high), but
    // there is room for one slab only (one core); across x or z its large faces are cut, two slabs or more.
    const StippleSet set = stipples_of(thin_plate(), 0.25f);
    const SlabDirection choice = choose_slab_direction(set.positions, set.first, rule_for(set));
    std::printf("plate: slabs across (%.3f, %.3f, %.3f), %.1f slabs, %llu of %zu stipples cut\n", choice.direction.x,
                choice.direction.y, choice.direction.z, rule_for(set).slab_count(choice.size),
                static_cast<unsigned long long>(choice.cut_stipples), set.positions.size());
    EXPECT_NEAR(choice.direction.y, 0.0f, 1e-6f);
    EXPECT_GE(rule_for(set).slab_count(choice.size), 2.0);
    EXPECT_GT(choice.cut_stipples, 0u);
}

TEST(SlabDirection, NothingToOrderIsNoFault) {
    const std::vector<glm::vec3> none;
    const std::vector<uint32_t> first = {0, 0, 0};
    const SlabDirection choice = choose_slab_direction(none, first, SlabRule{0.01, 24.0, 24, 4.0});
    EXPECT_EQ(choice.cut_stipples, 0u);
    EXPECT_TRUE(choice.centre.empty());
}

}  // namespace
}  // namespace stipple
