// The sphere a scene is framed by (scene_bounds, enclosing_sphere): it encloses every object, does not
// depend on their order, and stays near the smallest for many objects (merged one by one, a 200-object
// grid was framed 22% too large with its centre far off the grid's).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "scene/scene.hpp"

namespace stipple {
namespace {

bool encloses(const Sphere& outer, const std::vector<Sphere>& spheres) {
    for (const Sphere& s : spheres)
        if (glm::length(s.center - outer.center) + s.radius > outer.radius * (1.0f + 1e-5f)) return false;
    return true;
}

TEST(SceneBounds, AGridOfManyObjectsIsFramedByNearlyItsSmallestSphere) {
    std::vector<Sphere> grid;  // 10 x 20 unit spheres 3 apart in a plane, as a scene of many copies
    for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 20; ++x) grid.push_back({glm::vec3(3.0f * x, 3.0f * y, 0.0f), 1.0f});
    const glm::vec3 middle(28.5f, 13.5f, 0.0f);
    const float smallest = glm::length(glm::vec3(28.5f, 13.5f, 0.0f)) + 1.0f;  // to a corner sphere's far side
    Sphere merged = grid[0];
    for (const Sphere& s : grid) merged = merge_spheres(merged, s);
    const Sphere framed = enclosing_sphere(grid);
    std::printf("200 spheres: smallest radius %.3f, merged one by one %.3f (centre %.2f off), enclosing_sphere %.3f (%.2f off)\n",
                double(smallest), double(merged.radius), double(glm::length(merged.center - middle)), double(framed.radius),
                double(glm::length(framed.center - middle)));
    EXPECT_TRUE(encloses(framed, grid));
    EXPECT_LE(framed.radius, smallest * 1.02f);
    EXPECT_LE(glm::length(framed.center - middle), 0.05f * smallest);
    // In any order the same frame, within rounding.
    std::mt19937 random(7);
    for (int round = 0; round < 3; ++round) {
        std::shuffle(grid.begin(), grid.end(), random);
        const Sphere again = enclosing_sphere(grid);
        EXPECT_NEAR(again.radius, framed.radius, 1e-3f * framed.radius);
        EXPECT_LE(glm::length(again.center - framed.center), 1e-3f * framed.radius);
    }
}

TEST(SceneBounds, TwoOrOneAreAsExactAsTheMerge) {
    const std::vector<Sphere> two{{glm::vec3(0.0f), 1.0f}, {glm::vec3(10.0f, 4.0f, -2.0f), 3.0f}};
    const Sphere merged = merge_spheres(two[0], two[1]);
    const Sphere framed = enclosing_sphere(two);
    EXPECT_TRUE(encloses(framed, two));
    EXPECT_LE(framed.radius, merged.radius * (1.0f + 1e-5f));
    const std::vector<Sphere> one{{glm::vec3(1.0f, 2.0f, 3.0f), 0.5f}};
    EXPECT_EQ(enclosing_sphere(one).center, one[0].center);
    EXPECT_FLOAT_EQ(enclosing_sphere(one).radius, 0.5f);
    const std::vector<Sphere> nested{{glm::vec3(0.0f), 5.0f}, {glm::vec3(1.0f, 0.0f, 0.0f), 1.0f}};
    EXPECT_FLOAT_EQ(enclosing_sphere(nested).radius, 5.0f);
}

}  // namespace
}  // namespace stipple
