// The spatial hash behind the relaxation, the progressive order and the quality metric
// (src/stipple/point_grid.hpp): every query must see every point within reach, whatever the table's
// layout. Its bucket starts are 16-bit offsets within blocks of 256 buckets; a block that would hold
// more than 65535 points (many faces piled in one place) falls back to 32-bit starts.
#include <algorithm>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "stipple/point_grid.hpp"

namespace stipple {
namespace {

// The slots of the 27 cells around p's cell, and every point closer than the cell size to p must be
// among them; slots are listed once each.
void expect_neighbourhood_complete(const PointGrid& grid, const std::vector<glm::vec3>& points, const glm::vec3& p) {
    PointGrid::Run runs[27];
    const int count = grid.neighbor_runs(grid.cell_of(p), runs);
    std::multiset<uint32_t> listed;
    for (int r = 0; r < count; ++r)
        for (uint32_t slot = runs[r].begin; slot < runs[r].end; ++slot) listed.insert(grid.sorted_index(slot));
    std::set<uint32_t> distinct(listed.begin(), listed.end());
    EXPECT_EQ(distinct.size(), listed.size()) << "a slot listed twice";
    const float reach = grid.cell_size();
    for (uint32_t i = 0; i < points.size(); ++i) {
        if (glm::distance(points[i], p) < reach) {
            EXPECT_TRUE(distinct.count(i)) << "point " << i << " missed";
        }
    }
}

// Every slot holds one input point, at its coordinates, and bucket ranges tile the slots.
void expect_slots_are_the_points(const PointGrid& grid, const std::vector<glm::vec3>& points) {
    ASSERT_EQ(grid.sorted_size(), points.size());
    std::vector<bool> seen(points.size(), false);
    for (uint32_t slot = 0; slot < points.size(); ++slot) {
        const uint32_t i = grid.sorted_index(slot);
        ASSERT_LT(i, points.size());
        EXPECT_FALSE(seen[i]);
        seen[i] = true;
        EXPECT_EQ(grid.sorted_position(slot), points[i]);
    }
    uint32_t expected_begin = 0;
    for (uint32_t b = 0; b < grid.bucket_count(); ++b) {
        ASSERT_EQ(grid.bucket_begin(b), expected_begin) << "bucket " << b;
        ASSERT_LE(grid.bucket_begin(b), grid.bucket_end(b));
        expected_begin = grid.bucket_end(b);
        // A bucket's points are in its cells: every point of bucket b hashes to b.
        for (uint32_t slot = grid.bucket_begin(b); slot < grid.bucket_end(b); ++slot)
            ASSERT_EQ(grid.bucket(grid.cell_of(grid.sorted_position(slot))), b);
    }
    EXPECT_EQ(expected_begin, points.size());
}

TEST(PointGrid, FindsEveryNeighbourOnASurface) {
    // Points on a sphere, as stipples lie: cells hold a few each, most buckets are empty.
    std::mt19937 rng(7);
    std::normal_distribution<float> normal;
    std::vector<glm::vec3> points(20000);
    for (glm::vec3& p : points) p = glm::normalize(glm::vec3(normal(rng), normal(rng), normal(rng)));
    for (double buckets_per_point : {2.0, 1.0, 1.0 / 8.0}) {
        PointGrid grid;
        grid.build(points, 0.03f, buckets_per_point);
        expect_slots_are_the_points(grid, points);
        for (size_t i = 0; i < points.size(); i += 997) expect_neighbourhood_complete(grid, points, points[i]);
    }
}

TEST(PointGrid, APileOfPointsInOneCellFallsBackToWideStarts) {
    // 70,000 points inside one cell (more than a 16-bit offset counts) beside a sparse scatter: the
    // starts must still be right, for the pile and for the buckets after it.
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<glm::vec3> points;
    for (int i = 0; i < 70000; ++i) points.push_back(glm::vec3(0.5f) + 0.001f * glm::vec3(unit(rng), unit(rng), unit(rng)));
    for (int i = 0; i < 5000; ++i) points.push_back(glm::vec3(unit(rng), unit(rng), unit(rng)));
    PointGrid grid;
    grid.build(points, 0.05f);
    expect_slots_are_the_points(grid, points);
    expect_neighbourhood_complete(grid, points, glm::vec3(0.5005f));
    for (size_t i = 70000; i < points.size(); i += 251) expect_neighbourhood_complete(grid, points, points[i]);
    // The same pile split over neighbouring cells of one block (each under 65536, together over it).
    std::vector<glm::vec3> spread;
    for (int i = 0; i < 80000; ++i) spread.push_back(glm::vec3(0.5f + 0.2f * unit(rng), 0.5f, 0.5f));
    grid.build(spread, 0.05f);
    expect_slots_are_the_points(grid, spread);
    expect_neighbourhood_complete(grid, spread, glm::vec3(0.6f, 0.5f, 0.5f));
}

TEST(PointGrid, FewPointsMakeATableSmallerThanABlock) {
    const std::vector<glm::vec3> points = {{0, 0, 0}, {0.1f, 0, 0}, {1, 1, 1}, {1.05f, 1, 1}, {5, 5, 5}};
    PointGrid grid;
    grid.build(points, 0.2f);
    EXPECT_LT(grid.bucket_count(), 256u);
    expect_slots_are_the_points(grid, points);
    for (const glm::vec3& p : points) expect_neighbourhood_complete(grid, points, p);
}

// Grids of over half a million points sort on every core (sort_in_blocks): build, and spatial_order on
// one core or on every core, must order the slots as a stable sort by bucket does, on a surface and with
// a pile that makes a block too full for 16-bit offsets (the serial fallback).
TEST(PointGrid, TheSortOnEveryCoreIsTheStableSortByBucket) {
    std::mt19937 rng(5);
    std::normal_distribution<float> normal;
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<glm::vec3> points(600000);
    for (glm::vec3& p : points) p = glm::normalize(glm::vec3(normal(rng), normal(rng), normal(rng)));
    for (int pile = 0; pile < 2; ++pile) {
        if (pile == 1)
            for (int i = 0; i < 70000; ++i) points[i * 7] = glm::vec3(0.5f) + 0.001f * glm::vec3(unit(rng), unit(rng), unit(rng));
        PointGrid grid;
        grid.build(points, 0.004f, 1.0);
        expect_slots_are_the_points(grid, points);
        std::vector<uint32_t> expected(points.size());
        for (uint32_t i = 0; i < expected.size(); ++i) expected[i] = i;
        std::stable_sort(expected.begin(), expected.end(), [&](uint32_t a, uint32_t b) {
            return grid.bucket(grid.cell_of(points[a])) < grid.bucket(grid.cell_of(points[b]));
        });
        size_t built_differs = 0;
        for (uint32_t slot = 0; slot < points.size(); ++slot) built_differs += grid.sorted_index(slot) != expected[slot];
        EXPECT_EQ(built_differs, 0u) << (pile ? "with a pile" : "on a sphere");
        for (const bool on_every_core : {false, true}) {
            const std::vector<uint32_t> order = PointGrid::spatial_order(points, 0.004f, 1.0, on_every_core);
            ASSERT_EQ(order.size(), points.size());
            size_t ordered_differs = 0;
            for (uint32_t slot = 0; slot < points.size(); ++slot) ordered_differs += order[slot] != expected[slot];
            EXPECT_EQ(ordered_differs, 0u) << (pile ? "with a pile" : "on a sphere") << (on_every_core ? ", on every core" : ", serially");
        }
    }
}

}  // namespace
}  // namespace stipple
