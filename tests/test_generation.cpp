// Stipple generation (paper §2.1): tessellation independence, Poisson-disc-like spread of the full
// set and of its progressive prefixes, determinism, budgets, containment in triangles.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <cstring>
#include <random>
#include <tuple>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "mesh/primitives.hpp"
#include "stipple/progressive_order.hpp"
#include "stipple/quality.hpp"
#include "stipple/relax.hpp"
#include "stipple/stipple_classes.hpp"
#include "stipple/stipple_set.hpp"

namespace stipple {
namespace {

// D_max giving about `count` stipples on a unit sphere (bounding radius 1: kReferenceHeight / 2
// px per unit).
float dmax_for(double count) {
    const double px_per_unit = kReferenceHeight / 2.0;
    return static_cast<float>(count / (4.0 * std::numbers::pi * px_per_unit * px_per_unit));
}

bool same_positions(const StippleSet& a, const StippleSet& b) {
    return a.positions.size() == b.positions.size() &&
           std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(glm::vec3)) == 0;
}

// first[] is a prefix sum matching triangle[], and every stipple lies in its own triangle:
// barycentric coordinates >= -tol and on the plane within tol (relative to the triangle size).
void expect_consistent_and_inside(const Mesh& mesh, const StippleSet& set) {
    const size_t triangles = mesh.triangle_count();
    ASSERT_EQ(set.first.size(), triangles + 1);
    ASSERT_EQ(set.first[0], 0u);
    ASSERT_EQ(set.first[triangles], set.size());
    ASSERT_EQ(set.triangle.size(), set.size());
    size_t outside = 0, wrong_triangle = 0;
    double worst_bary = 1.0, worst_plane = 0.0;
    for (size_t t = 0; t < triangles; ++t) {
        ASSERT_LE(set.first[t], set.first[t + 1]);
        const glm::dvec3 a(mesh.positions[mesh.indices[3 * t]]), b(mesh.positions[mesh.indices[3 * t + 1]]),
            c(mesh.positions[mesh.indices[3 * t + 2]]);
        const glm::dvec3 n = glm::cross(b - a, c - a);
        const double n2 = glm::dot(n, n);
        const double size = std::max({glm::length(b - a), glm::length(c - a), glm::length(c - b)});
        for (uint32_t i = set.first[t]; i < set.first[t + 1]; ++i) {
            if (set.triangle[i] != t) ++wrong_triangle;
            const glm::dvec3 p(set.positions[i]);
            // Barycentrics from signed sub-areas.
            const double u = glm::dot(glm::cross(c - b, p - b), n) / n2;
            const double v = glm::dot(glm::cross(a - c, p - c), n) / n2;
            const double w = 1.0 - u - v;
            const double bary = std::min({u, v, w});
            const double plane = std::abs(glm::dot(p - a, n)) / std::sqrt(n2) / size;
            worst_bary = std::min(worst_bary, bary);
            worst_plane = std::max(worst_plane, plane);
            if (bary < -1e-4 || plane > 1e-4) ++outside;
        }
    }
    std::printf("  %zu stipples: min barycentric %.2e, max off-plane %.2e (relative)\n", set.size(), worst_bary,
                worst_plane);
    EXPECT_EQ(wrong_triangle, 0u);
    EXPECT_EQ(outside, 0u);
}

TEST(Generation, TessellationIndependentCount) {
    GenerationParams params;
    params.dmax = dmax_for(150000);
    const Mesh coarse = make_uv_sphere(500), fine = make_uv_sphere(200000);
    const StippleSet a = generate_stipples(coarse, params), b = generate_stipples(fine, params);
    const double diff = std::abs(double(a.size()) - double(b.size())) / double(b.size());
    std::printf("%zu triangles: %zu stipples; %zu triangles: %zu stipples; difference %.2f%%\n",
                coarse.triangle_count(), a.size(), fine.triangle_count(), b.size(), 100.0 * diff);
    EXPECT_LT(diff, 0.02);
    // Both totals are within 1 of density * area (cumulative rounding), whatever the triangle size.
    EXPECT_NEAR(double(a.size()), a.density_per_area * total_area(coarse), 1.0);
    EXPECT_NEAR(double(b.size()), b.density_per_area * total_area(fine), 1.0);
    EXPECT_DOUBLE_EQ(b.density_per_area, stipple_density_per_area(fine, params));
}

TEST(Generation, DistributionQualityFullAndPrefix) {
    const Mesh mesh = make_uv_sphere(100000);
    GenerationParams params;
    params.dmax = dmax_for(400000);
    const StippleSet set = generate_stipples(mesh, params);
    const double area = total_area(mesh);
    const double full = normalized_nn_distance(set.positions, area);
    const std::vector<glm::vec3> quarter = prefix_at_fraction(set, 0.25);
    const double prefix = normalized_nn_distance(quarter, area);
    std::printf("%zu triangles, %zu stipples (%.1f per triangle) in %.3f s = %.0f stipples/s\n",
                mesh.triangle_count(), set.size(), double(set.size()) / mesh.triangle_count(),
                set.generation_seconds, set.size() / set.generation_seconds);
    std::printf("delta-bar full %.3f, prefix f=0.25 (%zu stipples) %.3f\n", full, quarter.size(), prefix);
    EXPECT_GE(full, 0.85);  // 0.855 measured (issue 18 asks 0.85; 6 iterations of the squared falloff 0.858)
    EXPECT_GE(prefix, 0.68);  // 0.698: one stipple of each triangle's ~4 (issue 18 asks 0.80)
    // The prefix keeps, in every triangle, the stipples with k + 0.5 < f N_t: ceil(f N_t - 0.5) of them.
    size_t expected = 0;
    for (size_t t = 0; t < mesh.triangle_count(); ++t)
        expected += size_t(std::clamp(std::ceil(0.25 * set.count(t) - 0.5), 0.0, double(set.count(t))));
    EXPECT_EQ(quarter.size(), expected);
    EXPECT_GT(quarter.size(), set.size() / 6);

    // With the coarse class (stipple_classes.hpp): the quarter as even as issue 18 asks, the whole set kept.
    params.coarse_class = true;
    const StippleSet classes = generate_stipples(mesh, params);
    const double classes_full = normalized_nn_distance(classes.positions, area);
    const double classes_quarter = normalized_nn_distance(prefix_at_fraction(classes, 0.25), area);
    const double classes_eighth = normalized_nn_distance(prefix_at_fraction(classes, 0.125), area);
    const double classes_half = normalized_nn_distance(prefix_at_fraction(classes, 0.5), area);
    std::printf("with the coarse class, in %.3f s = %.0f stipples/s: delta-bar full %.3f, prefix f=0.25 %.3f, f=0.125 %.3f, "
                "f=0.5 %.3f (without: %.3f, %.3f)\n",
                classes.generation_seconds, classes.size() / classes.generation_seconds, classes_full, classes_quarter,
                classes_eighth, classes_half, normalized_nn_distance(prefix_at_fraction(set, 0.125), area),
                normalized_nn_distance(prefix_at_fraction(set, 0.5), area));
    EXPECT_EQ(classes.size(), set.size());
    EXPECT_GE(classes_full, 0.85);     // 0.855 measured
    EXPECT_GE(classes_quarter, 0.80);  // 0.809 (0.700 without)
    EXPECT_GE(classes_eighth, 0.67);   // 0.691 (0.626 without)
    EXPECT_GE(classes_half, 0.68);     // 0.696 (0.701 without)
    EXPECT_EQ(prefix_at_fraction(classes, 0.25).size(), quarter.size());
}

TEST(Generation, RelaxationImprovesSpread) {
    const Mesh mesh = make_icosphere(5);
    GenerationParams params;
    params.dmax = dmax_for(60000);
    params.relax_iterations = 0;
    const StippleSet initial = generate_stipples(mesh, params);
    params.relax_iterations = 5;
    const StippleSet relaxed = generate_stipples(mesh, params);
    const double area = total_area(mesh);
    const double before = normalized_nn_distance(initial.positions, area);
    const double after = normalized_nn_distance(relaxed.positions, area);
    // Stratified within each triangle, but triangles of ~4 stipples clump along shared edges.
    std::printf("delta-bar stratified (no relaxation) %.3f, relaxed (5 iterations) %.3f\n", before, after);
    EXPECT_LT(before, 0.6);
    EXPECT_GE(after, 0.85);  // 0.860 measured
    EXPECT_EQ(initial.size(), relaxed.size());
}

TEST(Generation, Deterministic) {
    const Mesh mesh = make_icosphere(4);
    GenerationParams params;
    params.dmax = dmax_for(50000);
    const StippleSet a = generate_stipples(mesh, params);
    const StippleSet b = generate_stipples(mesh, params);
    EXPECT_TRUE(same_positions(a, b));
    EXPECT_EQ(a.first, b.first);
    // Independent of the thread count, with the coarse class too (its own relaxation and restart run in
    // chunks as well).
    auto same_on_1_and_3_threads = [&](const StippleSet& reference) {
        set_worker_count(1);
        const StippleSet serial = generate_stipples(mesh, params);
        set_worker_count(3);
        const StippleSet three = generate_stipples(mesh, params);
        set_worker_count(0);
        return same_positions(reference, serial) && same_positions(reference, three);
    };
    EXPECT_TRUE(same_on_1_and_3_threads(a));
    params.coarse_class = true;
    const StippleSet classes = generate_stipples(mesh, params);
    EXPECT_FALSE(same_positions(a, classes));
    EXPECT_TRUE(same_on_1_and_3_threads(classes)) << "with the coarse class";
    params.coarse_class = false;
    // Also where large triangles are ordered in pieces (two triangles of ~20k stipples each).
    GenerationParams quad_params;
    quad_params.dmax = 0.05f;
    const Mesh quad = make_grid(1);
    const StippleSet quad_default = generate_stipples(quad, quad_params);
    set_worker_count(1);
    const StippleSet quad_serial = generate_stipples(quad, quad_params);
    set_worker_count(0);
    EXPECT_GT(quad_default.count(0), 10000u);
    EXPECT_TRUE(same_positions(quad_default, quad_serial));
    params.seed = 2;
    const StippleSet c = generate_stipples(mesh, params);
    EXPECT_EQ(a.first, c.first);  // counts depend on areas only
    size_t differ = 0;
    for (size_t i = 0; i < a.size(); ++i) differ += a.positions[i] != c.positions[i];
    std::printf("seed 1 vs 2: %zu of %zu stipples differ\n", differ, a.size());
    EXPECT_GT(differ, a.size() * 9 / 10);
}

// The progressive order is the greedy of progressive_order.hpp, exactly: on a mesh small enough for
// one slab and with at most 16 stipples per triangle (every remaining stipple a candidate), a
// brute-force reading of the definition gives the same order, bit for bit. The implementation gets
// there differently (placed stipples push their distance to their neighbours within the search
// radius of their own time), so this is what shows the shortcut exact.
TEST(Generation, ProgressiveOrderIsTheGreedyOfItsDefinition) {
    const Mesh mesh = make_icosphere(1);  // 80 triangles
    const size_t triangles = mesh.triangle_count();
    std::vector<uint32_t> first(triangles + 1, 0);
    std::vector<glm::vec3> positions;
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (size_t t = 0; t < triangles; ++t) {
        const uint32_t count = 1 + uint32_t(t * 7 % 16);  // 1..16 stipples, several counts sharing taus
        const glm::vec3 a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]],
                        c = mesh.positions[mesh.indices[3 * t + 2]];
        for (uint32_t k = 0; k < count; ++k) {
            const float r = std::sqrt(u(rng)), v = u(rng);
            positions.push_back((1 - r) * a + r * (1 - v) * b + r * v * c);
        }
        first[t + 1] = first[t] + count;
    }
    const double spacing = 0.15;  // 12 spacings exceed the sphere: one slab
    for (const bool classes : {false, true}) {
        std::vector<glm::vec3> ordered = positions;
        progressive_order(ordered, first, spacing, 1, {}, classes);

        // Reference: slots by (tau, triangle); each takes the first remaining stipple (in a list kept by
        // swapping the chosen one to the front) with the largest min(s(tau)^2, squared distance to every
        // stipple placed so far); with coarse classes, among the triangle's coarse class (its first
        // coarse_count(N) stipples, as given) for the first coarse_count(N) slots and among the others after.
        struct Slot {
            double tau;
            uint32_t triangle, k;
        };
        std::vector<Slot> slots;
        for (uint32_t t = 0; t < triangles; ++t)
            for (uint32_t k = 0; k < first[t + 1] - first[t]; ++k) slots.push_back({(k + 0.5) / (first[t + 1] - first[t]), t, k});
        std::stable_sort(slots.begin(), slots.end(), [](const Slot& x, const Slot& y) {
            return x.tau < y.tau || (x.tau == y.tau && x.triangle < y.triangle);
        });
        std::vector<glm::vec3> reference = positions, placed;
        for (const Slot& slot : slots) {
            const uint32_t count = first[slot.triangle + 1] - first[slot.triangle], coarse = classes ? coarse_count(count) : 0;
            const uint32_t base = first[slot.triangle] + slot.k;
            const uint32_t end = slot.k < coarse ? first[slot.triangle] + coarse : first[slot.triangle + 1];
            const float s = static_cast<float>(std::min(1.5 / std::sqrt(slot.tau), 12.0) * spacing);
            uint32_t chosen = base;
            float best = -1.0f;
            for (uint32_t i = base; i < end; ++i) {
                float d2 = s * s;
                for (const glm::vec3& q : placed) {
                    const float dx = reference[i].x - q.x, dy = reference[i].y - q.y, dz = reference[i].z - q.z;
                    d2 = std::min(d2, (dx * dx + dy * dy) + dz * dz);
                }
                if (d2 > best) best = d2, chosen = i;
            }
            std::swap(reference[base], reference[chosen]);
            placed.push_back(reference[base]);
        }
        size_t differ = 0;
        for (size_t i = 0; i < positions.size(); ++i) differ += std::memcmp(&ordered[i], &reference[i], sizeof(glm::vec3)) != 0;
        EXPECT_EQ(differ, 0u) << "of " << positions.size() << " stipples" << (classes ? ", with coarse classes" : "");
    }
}

// Triangles too long for a slab are ordered in pieces and merged (progressive_order.cpp): the merge keeps
// each triangle's coarse class first, as a whole triangle's ordering does. Slivers of 60 stipples (a coarse
// class of 15) a thousand spacings long, cut into about ten pieces.
TEST(Generation, ASliversCoarseClassComesFirstAfterItsPiecesMerge) {
    const double spacing = 0.01;
    const uint32_t per_triangle = 60;
    const float length = float(1000.0 * spacing);
    const float width = float(2.0 * per_triangle * (std::sqrt(3.0) / 2.0) * spacing * spacing / length);
    Mesh mesh;
    mesh.positions = {{0.0f, 0.0f, 0.0f}, {length, 0.0f, 0.0f}, {0.0f, width, 0.0f},
                      {0.0f, 0.0f, 0.5f}, {length, 0.0f, 0.5f}, {0.0f, width, 0.5f}};
    mesh.indices = {0, 1, 2, 3, 4, 5};
    std::vector<uint32_t> first = {0, per_triangle, 2 * per_triangle};
    std::vector<glm::vec3> positions;
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (size_t t = 0; t < 2; ++t) {
        const glm::vec3 a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]],
                        c = mesh.positions[mesh.indices[3 * t + 2]];
        for (uint32_t k = 0; k < per_triangle; ++k) {
            const float r = std::sqrt(u(rng)), v = u(rng);
            positions.push_back((1 - r) * a + r * (1 - v) * b + r * v * c);
        }
    }
    std::vector<glm::vec3> ordered = positions;
    progressive_order(ordered, first, spacing, 3, {}, true);
    const uint32_t coarse = coarse_count(per_triangle);
    ASSERT_EQ(coarse, 15u);
    auto less = [](const glm::vec3& p, const glm::vec3& q) { return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z); };
    for (size_t t = 0; t < 2; ++t) {
        std::vector<glm::vec3> given(positions.begin() + first[t], positions.begin() + first[t] + coarse);
        std::vector<glm::vec3> got(ordered.begin() + first[t], ordered.begin() + first[t] + coarse);
        std::sort(given.begin(), given.end(), less), std::sort(got.begin(), got.end(), less);
        size_t differ = 0;
        for (size_t i = 0; i < coarse; ++i) differ += std::memcmp(&given[i], &got[i], sizeof(glm::vec3)) != 0;
        EXPECT_EQ(differ, 0u) << "triangle " << t << ": of its " << coarse << " first stipples";
    }
}

TEST(Generation, ZeroAreaTrianglesGetNoStipples) {
    Mesh mesh = make_grid(4);
    const size_t real = mesh.triangle_count();
    // Degenerate faces: a repeated vertex, and three collinear vertices.
    mesh.indices.insert(mesh.indices.end(), {0, 0, 5, 0, 1, 2});
    mesh.indices.insert(mesh.indices.end(), {6, 7, 7});
    compute_vertex_normals(mesh);
    GenerationParams params;
    params.dmax = 0.05f;
    const StippleSet set = generate_stipples(mesh, params);
    std::printf("%zu stipples; degenerate triangles got %u, %u, %u\n", set.size(), set.count(real),
                set.count(real + 1), set.count(real + 2));
    EXPECT_GT(set.size(), 1000u);
    for (size_t t = real; t < mesh.triangle_count(); ++t) EXPECT_EQ(set.count(t), 0u) << "triangle " << t;
    for (size_t t = 0; t < real; ++t) EXPECT_GT(set.count(t), 0u) << "triangle " << t;
    expect_consistent_and_inside(mesh, set);
}

TEST(Generation, FacesPiledInOnePlaceAreLeftUnrelaxed) {
    // A surface (a grid) beside a pile of 8,000 copies of one small triangle, as a broken model may hold:
    // the pile's stipples crowd thousands of times the surface's density into one place. Relaxing them
    // cost the square of their number (3,000 copies took 80 s for 330k stipples) and cannot even them
    // out, so they stay where generation put them; the surface is relaxed as always.
    Mesh mesh = make_grid(8);
    const size_t surface = mesh.triangle_count();
    const uint32_t base = static_cast<uint32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {{0.0f, 0.0f, 3.0f}, {0.02f, 0.0f, 3.0f}, {0.0f, 0.02f, 3.0f}});
    for (int copy = 0; copy < 8000; ++copy) mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2});
    compute_vertex_normals(mesh);
    GenerationParams params;
    params.dmax = 0.05f;
    params.relax_iterations = 0;
    const StippleSet unrelaxed = generate_stipples(mesh, params);
    params.relax_iterations = 5;
    const StippleSet relaxed = generate_stipples(mesh, params);
    ASSERT_EQ(unrelaxed.size(), relaxed.size());
    const size_t pile = relaxed.size() - relaxed.first[surface];
    std::printf("%zu stipples on the surface, %zu in the pile\n", size_t(relaxed.first[surface]), pile);
    ASSERT_GT(pile, 5000u) << "the pile should hold more stipples than a neighbourhood of a surface can";
    auto sorted_stipples = [](const StippleSet& set, size_t t) {
        std::vector<std::array<float, 3>> points;
        for (uint32_t i = set.first[t]; i < set.first[t + 1]; ++i)
            points.push_back({set.positions[i].x, set.positions[i].y, set.positions[i].z});
        std::sort(points.begin(), points.end());
        return points;
    };
    size_t moved_on_surface = 0;
    for (size_t t = 0; t < surface; ++t) moved_on_surface += sorted_stipples(relaxed, t) != sorted_stipples(unrelaxed, t);
    EXPECT_GT(moved_on_surface, surface / 2) << "the surface should be relaxed";
    for (size_t t = surface; t < mesh.triangle_count(); ++t)
        ASSERT_EQ(sorted_stipples(relaxed, t), sorted_stipples(unrelaxed, t)) << "pile triangle " << t << " relaxed";
    expect_consistent_and_inside(mesh, relaxed);
}

TEST(Generation, APileOfStipplesKeepsItsOrder) {
    // 10,000 triangles of 8 stipples each, all within a ball much smaller than the spacing: every placed
    // stipple would reach all 80,000, so the order does not push their distances (kMaxPushed) and each
    // triangle keeps its stipples as they came, rather than cost the pile's square in pushes.
    constexpr uint32_t kTriangles = 10000, kPerTriangle = 8;
    std::vector<uint32_t> first(kTriangles + 1);
    for (uint32_t t = 0; t <= kTriangles; ++t) first[t] = t * kPerTriangle;
    std::vector<glm::vec3> positions(first.back());
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (glm::vec3& p : positions) p = 1e-3f * glm::vec3(u(rng), u(rng), u(rng));
    std::vector<glm::vec3> ordered = positions;
    progressive_order(ordered, first, 0.01, 1);
    EXPECT_EQ(ordered, positions) << "the pile's stipples were reordered";
    // A pile within reach of fewer stipples than the bound is ordered as a surface is.
    first.resize(1001);
    positions.resize(first.back());
    ordered = positions;
    progressive_order(ordered, first, 0.01, 1);
    EXPECT_NE(ordered, positions) << "a small pile should be ordered by distance";
}

// Far from unit size, generation runs on a copy scaled to unit radius (generate.cpp): the same counts, and
// stipples as evenly spread, where a triangle of side 1e10 made NaN positions (squared cross products beyond
// float range) and crashed the relaxation.
TEST(Generation, TheSameStipplesAtEveryScale) {
    GenerationParams params;
    params.dmax = dmax_for(20000);
    auto scaled_quad = [](float size) {
        Mesh quad = make_grid(1);
        for (glm::vec3& p : quad.positions) p *= size;
        return quad;
    };
    const Mesh unit_quad = scaled_quad(1.0f);
    const StippleSet unit = generate_stipples(unit_quad, params);
    const double spread = normalized_nn_distance(unit.positions, total_area(unit_quad));
    EXPECT_GT(spread, 0.85);
    for (const float size : {1e-12f, 1e10f, 1e17f}) {
        const Mesh quad = scaled_quad(size);
        const StippleSet set = generate_stipples(quad, params);
        ASSERT_EQ(set.size(), unit.size()) << size;
        EXPECT_EQ(set.first, unit.first) << size;
        EXPECT_NEAR(set.poisson_radius / size, unit.poisson_radius, 1e-6 * unit.poisson_radius) << size;
        expect_consistent_and_inside(quad, set);
        // Other rounding, so other stipples, but as evenly spread.
        EXPECT_NEAR(normalized_nn_distance(set.positions, total_area(quad)), spread, 0.01) << size;
    }
}

TEST(Generation, StipplesInsideTheirTriangles) {
    GenerationParams params;
    params.dmax = dmax_for(80000);
    // Thin polar triangles, several stipples per triangle.
    const Mesh sphere = make_uv_sphere(20000);
    expect_consistent_and_inside(sphere, generate_stipples(sphere, params));
    // Two huge triangles with tens of thousands of stipples each.
    const Mesh quad = make_grid(1);
    params.dmax = 0.05f;
    const StippleSet big = generate_stipples(quad, params);
    EXPECT_GT(big.count(0), 10000u);
    expect_consistent_and_inside(quad, big);
    // Even across a shared edge the big triangles' stipples stay apart: the quality holds.
    std::printf("quad: delta-bar full %.3f, prefix f=0.1 %.3f\n", normalized_nn_distance(big.positions, 4.0),
                normalized_nn_distance(prefix_at_fraction(big, 0.1), 4.0));
    EXPECT_GE(normalized_nn_distance(big.positions, 4.0), 0.85);                  // 0.878 measured
    EXPECT_GE(normalized_nn_distance(prefix_at_fraction(big, 0.1), 4.0), 0.73);  // 0.756 measured
}

TEST(Generation, BudgetLimitsTheCount) {
    const Mesh mesh = make_icosphere(4);
    GenerationParams params;
    params.dmax = dmax_for(40000);
    const size_t unlimited = generate_stipples(mesh, params).size();
    params.max_stipples = 10000;
    const StippleSet limited = generate_stipples(mesh, params);
    std::printf("D_max alone: %zu stipples; with Object_max = 10000: %zu\n", unlimited, limited.size());
    EXPECT_GT(unlimited, 30000u);
    EXPECT_NEAR(double(limited.size()), 10000.0, 1.0);
    EXPECT_NEAR(limited.density_per_area * total_area(mesh), 10000.0, 1e-6);
    // A budget above what D_max gives changes nothing.
    params.max_stipples = 1000000;
    EXPECT_EQ(generate_stipples(mesh, params).size(), unlimited);
    params.max_stipples = 0;
    EXPECT_EQ(generate_stipples(mesh, params).size(), 0u);
}

TEST(Generation, BadParametersThrow) {
    const Mesh mesh = make_icosphere(1);
    GenerationParams params;
    params.dmax = -1.0f;
    EXPECT_THROW(generate_stipples(mesh, params), Error);
    params.dmax = std::nanf("");
    EXPECT_THROW(generate_stipples(mesh, params), Error);
    params.dmax = 0.1f;
    params.relax_iterations = -1;
    EXPECT_THROW(generate_stipples(mesh, params), Error);
    Mesh broken = mesh;
    broken.indices.back() = 100000;
    params.relax_iterations = 2;
    EXPECT_THROW(generate_stipples(broken, params), Error);
}

TEST(Generation, AFaceOutOfRangeIsNamedWhereverItLies) {
    // The areas are computed in blocks of triangles (generate.cpp): a bad face past the first block is
    // reported by its own number, on both calls that read the areas.
    Mesh mesh = make_uv_sphere(300000);
    ASSERT_GT(mesh.triangle_count(), 250001u);
    mesh.indices[3 * 250000 + 1] = uint32_t(mesh.positions.size());
    GenerationParams params;
    for (int call = 0; call < 2; ++call) {
        try {
            if (call == 0) generate_stipples(mesh, params);
            else stipple_density_per_area(mesh, params);
            ADD_FAILURE() << "a face out of range must throw";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("face 250000 refers to a vertex out of range"), std::string::npos)
                << e.what();
        }
    }
}

TEST(Quality, MetricMatchesKnownDistributions) {
    // Uniform random points on a unit square: about 0.46; a hexagonal lattice: 1.
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<glm::vec3> random(100000);
    for (glm::vec3& p : random) p = glm::vec3(u(rng), u(rng), 0.0f);
    std::vector<glm::vec3> hex;
    const float d = 0.01f;
    for (int j = 0; j < 100; ++j)
        for (int i = 0; i < 100; ++i) hex.emplace_back(i * d + (j % 2) * d / 2, j * d * std::sqrt(3.0f) / 2, 0.0f);
    const double hex_area = 100 * d * 100 * d * std::sqrt(3.0) / 2;
    const double r = normalized_nn_distance(random, 1.0), h = normalized_nn_distance(hex, hex_area);
    std::printf("delta-bar random %.3f, hexagonal %.3f\n", r, h);
    EXPECT_NEAR(r, 0.465, 0.02);
    EXPECT_NEAR(h, 1.0, 0.01);
    // Six-fold order: every neighbourhood of a lattice is hexagonal and oriented alike; random points
    // have neither (their windowed order is noise, ~1/sqrt(points per window)).
    const HexagonalOrder hr = hexagonal_order(random, {0, 0, 1}), hh = hexagonal_order(hex, {0, 0, 1});
    std::printf("psi_6 local / windowed: random %.3f / %.3f, hexagonal %.3f / %.3f\n", hr.local, hr.windowed, hh.local,
                hh.windowed);
    EXPECT_NEAR(hr.local, 0.365, 0.02);
    EXPECT_LT(hr.windowed, 0.05);
    EXPECT_NEAR(hh.local, 1.0, 1e-3);
    EXPECT_NEAR(hh.windowed, 1.0, 1e-3);
    // Tilted, the lattice is seen in its own plane, whatever that is. (Not 1: the plane's frame turns the
    // lattice's square within the bounding square, and neighbourhoods at its edges inside the margin
    // are cut.)
    std::vector<glm::vec3> tilted;
    const glm::mat3 turn = glm::mat3(glm::rotate(glm::mat4(1.0f), 0.7f, glm::normalize(glm::vec3(1, 2, 3))));
    for (const glm::vec3& p : hex) tilted.push_back(turn * p);
    const HexagonalOrder ht = hexagonal_order(tilted, turn * glm::vec3(0, 0, 1));
    EXPECT_GT(ht.local, 0.9);
    EXPECT_GT(ht.windowed, 0.9);
}

TEST(Generation, NoHexagonalRegularity) {
    // Two triangles of ~20k stipples each: relaxation from a lattice-like start (the R2 sequence) grew
    // hexagonal domains oriented alike across a whole triangle (windowed order 0.32-0.40); jittered, it
    // does not (issue 18: better blue noise "without hexagonal regularity").
    const Mesh quad = make_grid(1);
    GenerationParams params;
    params.dmax = 0.05f;
    const StippleSet set = generate_stipples(quad, params);
    const HexagonalOrder order = hexagonal_order(set.positions, {0, 0, 1});
    std::printf("quad of %zu stipples: psi_6 local %.3f, windowed %.3f (dart throwing about 0.41 / 0.05)\n", set.size(),
                order.local, order.windowed);
    EXPECT_LT(order.windowed, 0.15);  // 0.082 measured (0.066 with the squared falloff, relax.cpp)
    EXPECT_LT(order.local, 0.6);      // 0.52 measured: more hexagonal than dart throwing, locally
}

}  // namespace
}  // namespace stipple
