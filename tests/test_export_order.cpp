// The plotter order of dots: a nearest-neighbour tour improved by 2-opt and Or-opt must come
// within 1.6x of the nearest-neighbour lower bound on blue noise, where generation (random)
// order is tens of times over it. Speed is measured by tools/plot_order_speed, not here.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include <glm/geometric.hpp>

#include "export/blue_noise.hpp"
#include "export/dot_order.hpp"
#include "export/nearest_alive_grid.hpp"
#include "export/neighbours.hpp"
#include "export/tour_improve.hpp"

namespace {

using namespace stipple::plot;

bool is_permutation_of_all(std::vector<uint32_t> order, size_t n) {
    if (order.size() != n) return false;
    std::sort(order.begin(), order.end());
    for (size_t i = 0; i < n; ++i)
        if (order[i] != i) return false;
    return true;
}

TEST(ExportOrder, BlueNoiseTravelWithinBound) {
    const std::vector<glm::dvec2> points = poisson_disc_points(150.0, 150.0, poisson_disc_spacing(150.0, 150.0, 20000), 3);
    ASSERT_GT(points.size(), 18000u);
    const double bound = nearest_neighbour_bound(points);
    const glm::dvec2 pen(0.0);

    const std::vector<uint32_t> order = plot_order(points, pen);
    ASSERT_TRUE(is_permutation_of_all(order, points.size()));
    // Each move after the first arrives at a dot from another dot, so it is at least that dot's
    // nearest-neighbour distance: the bound really is one (minus the first dot's share).
    const double travel = travel_length(points, order, pen) - glm::length(points[order[0]] - pen);
    EXPECT_GE(travel, bound - 2.0 * poisson_disc_spacing(150.0, 150.0, 20000));
    EXPECT_LE(travel, 1.6 * bound) << "ratio " << travel / bound;

    // The improvement must matter: the plain tour is clearly worse.
    const std::vector<uint32_t> plain = plot_order(points, pen, {.neighbours = 8, .improve = false});
    ASSERT_TRUE(is_permutation_of_all(plain, points.size()));
    EXPECT_GT(travel_length(points, plain, pen), 1.1 * travel_length(points, order, pen));

    // Generation order (here: random) is tens of times over the bound.
    std::vector<uint32_t> shuffled(points.size());
    std::iota(shuffled.begin(), shuffled.end(), 0u);
    std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(5));
    EXPECT_GT(travel_length(points, shuffled, pen), 30.0 * bound);
}

TEST(ExportOrder, ClusteredDotsAndDuplicatesStillOrderedWell) {
    // Three far-apart clusters and exact duplicates: the path must not hop between clusters.
    std::vector<glm::dvec2> points;
    for (const glm::dvec2 centre : {glm::dvec2(10, 10), glm::dvec2(180, 20), glm::dvec2(90, 250)}) {
        const std::vector<glm::dvec2> cluster = poisson_disc_points(20.0, 20.0, 0.5, 11);
        for (const glm::dvec2& p : cluster) points.push_back(centre + p);
    }
    points.push_back(points[5]);
    points.push_back(points[5]);
    const std::vector<uint32_t> order = plot_order(points, glm::dvec2(0.0));
    ASSERT_TRUE(is_permutation_of_all(order, points.size()));
    size_t long_hops = 0;
    for (size_t i = 1; i < order.size(); ++i) long_hops += glm::length(points[order[i]] - points[order[i - 1]]) > 50.0;
    EXPECT_EQ(long_hops, 2u);
    const double travel = travel_length(points, order, glm::dvec2(0.0));
    EXPECT_LE(travel - glm::length(points[order[0]]) - 2 * 250.0, 1.6 * nearest_neighbour_bound(points));
}

TEST(ExportOrder, StartsNearThePen) {
    const std::vector<glm::dvec2> points = poisson_disc_points(100.0, 100.0, 2.0, 4);
    const glm::dvec2 pen(100.0, 100.0);
    const std::vector<uint32_t> order = plot_order(points, pen);
    EXPECT_LT(glm::length(points[order.front()] - pen), glm::length(points[order.back()] - pen));
    EXPECT_LT(glm::length(points[order.front()] - pen), 20.0);
}

TEST(ExportOrder, TinySets) {
    EXPECT_TRUE(plot_order({}, glm::dvec2(0.0)).empty());
    const std::vector<glm::dvec2> one{{5, 5}};
    EXPECT_EQ(plot_order(one, glm::dvec2(0.0)), std::vector<uint32_t>{0});
    // On a line, from the left end: left to right, whatever the input order.
    const std::vector<glm::dvec2> line{{4, 0}, {1, 0}, {3, 0}, {0, 0}, {2, 0}, {6, 0}, {5, 0}};
    EXPECT_EQ(plot_order(line, glm::dvec2(-1.0, 0.0)), (std::vector<uint32_t>{3, 1, 4, 2, 0, 6, 5}));
}

// Path length without the approach from the pen: what improve_path minimises (its ends are free).
double open_length(const std::vector<glm::dvec2>& points, const std::vector<uint32_t>& order) {
    return order.empty() ? 0.0 : travel_length(points, order, points[order[0]]);
}

TEST(ExportOrder, ImprovementKeepsAPermutationAndNeverLengthens) {
    // Small and odd sets (uniform random, with duplicates, many sizes) exercise the moves' wrap-around.
    std::mt19937 rng(12);
    std::uniform_real_distribution<double> coord(0.0, 50.0);
    for (size_t n = 4; n <= 60; ++n) {
        std::vector<glm::dvec2> points;
        for (size_t i = 0; i < n; ++i) points.push_back(i % 7 == 6 ? points[i / 2] : glm::dvec2(coord(rng), coord(rng)));
        const NeighbourLists lists = nearest_neighbours(points, 5);
        std::vector<uint32_t> order = nearest_neighbour_tour(points, lists, glm::dvec2(0.0));
        ASSERT_TRUE(is_permutation_of_all(order, n));
        const double before = open_length(points, order);
        improve_path(points, lists, order);
        ASSERT_TRUE(is_permutation_of_all(order, n)) << n;
        EXPECT_LE(open_length(points, order), before + 1e-9) << n;
    }
}

TEST(ExportOrder, NeighbourListsAreTheNearestSorted) {
    const std::vector<glm::dvec2> points = poisson_disc_points(30.0, 30.0, 1.0, 9);
    const NeighbourLists lists = nearest_neighbours(points, 6);
    for (size_t i = 0; i < points.size(); i += 37) {
        std::vector<double> all;
        for (size_t j = 0; j < points.size(); ++j)
            if (j != i) all.push_back(glm::length(points[j] - points[i]));
        std::sort(all.begin(), all.end());
        ASSERT_EQ(lists.of(i).size(), 6u);
        for (size_t k = 0; k < 6; ++k) EXPECT_NEAR(glm::length(points[lists.of(i)[k]] - points[i]), all[k], 1e-12);
    }
}

TEST(ExportOrder, NearestAliveGridMatchesBruteForce) {
    const std::vector<glm::dvec2> points = poisson_disc_points(50.0, 20.0, 0.7, 2);
    NearestAliveGrid grid(points);
    std::vector<uint8_t> alive(points.size(), 1);
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> coord(-30.0, 80.0);
    for (size_t step = 0; step < points.size(); ++step) {
        const glm::dvec2 q(coord(rng), coord(rng));  // inside and outside the points' bounds
        double best = 1e300;
        for (size_t i = 0; i < points.size(); ++i)
            if (alive[i]) best = std::min(best, glm::length(points[i] - q));
        const uint32_t found = grid.nearest(q);
        ASSERT_NE(found, NearestAliveGrid::kNone);
        ASSERT_TRUE(alive[found]);
        ASSERT_NEAR(glm::length(points[found] - q), best, 1e-12) << "step " << step;
        grid.remove(found);
        alive[found] = 0;
    }
    EXPECT_EQ(grid.nearest(glm::dvec2(0.0)), NearestAliveGrid::kNone);
}

}  // namespace
