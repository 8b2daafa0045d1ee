// The stipple cache: a reopened model with the same parameters gets the very same candidates back;
// anything else (other parameters, another mesh, a damaged entry) regenerates.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "mesh/primitives.hpp"
#include "stipple/selection_order.hpp"
#include "stipple/stipple_cache.hpp"
#include "support/test_paths.hpp"

namespace stipple {
namespace {

bool same(const StippleSet& a, const StippleSet& b) {
    return a.positions == b.positions && a.triangle == b.triangle && a.first == b.first &&
           a.density_per_area == b.density_per_area;
}

TEST(StippleCache, ReopeningReadsTheSameStipplesBack) {
    const auto dir = test::temp_dir("stipple_cache_roundtrip");
    const Mesh mesh = make_icosphere(4);
    GenerationParams params;
    params.dmax = 0.02f;
    const StippleSet generated = generate_stipples_cached(mesh, params, dir);
    EXPECT_FALSE(generated.from_cache);
    const StippleSet reopened = generate_stipples_cached(mesh, params, dir);
    EXPECT_TRUE(reopened.from_cache);
    EXPECT_TRUE(same(generated, reopened));
    // The polygons' selection values (§2.3) come back too: ranking them is the slow part of reopening.
    EXPECT_EQ(reopened.selection, polygon_selection_values(mesh, params.seed));
    EXPECT_EQ(generated.selection, reopened.selection);
    std::printf("%zu stipples: generated in %.3f s, read back in %.4f s\n", generated.size(),
                generated.generation_seconds, reopened.generation_seconds);

    GenerationParams other = params;
    other.seed = 2;
    EXPECT_FALSE(load_cached_stipples(dir, mesh, other).has_value()) << "another seed is another entry";
    Mesh moved = mesh;
    moved.positions[0].x += 1e-3f;
    EXPECT_FALSE(load_cached_stipples(dir, moved, params).has_value()) << "another mesh is another entry";
}

TEST(StippleCache, DamagedEntriesAreMissesNotErrors) {
    const auto dir = test::temp_dir("stipple_cache_damaged");
    const Mesh mesh = make_icosphere(3);
    GenerationParams params;
    params.dmax = 0.02f;
    const StippleSet generated = generate_stipples_cached(mesh, params, dir);
    char name[32];
    std::snprintf(name, sizeof(name), "%016llx.stipples",
                  static_cast<unsigned long long>(stipple_cache_key(mesh, params)));
    const auto entry = dir / name;
    ASSERT_TRUE(std::filesystem::exists(entry));

    // A triangle index changed in place: the set would be inconsistent, so it is not used.
    {
        std::fstream f(entry, std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(48 + std::streamoff(generated.size() * sizeof(glm::vec3)));
        const uint32_t wrong = 12345;
        f.write(reinterpret_cast<const char*>(&wrong), 4);
    }
    EXPECT_FALSE(load_cached_stipples(dir, mesh, params).has_value());
    // Truncated.
    std::filesystem::resize_file(entry, 100);
    EXPECT_FALSE(load_cached_stipples(dir, mesh, params).has_value());
    // Regenerated over the damaged entry, and good again.
    const StippleSet again = generate_stipples_cached(mesh, params, dir);
    EXPECT_FALSE(again.from_cache);
    EXPECT_TRUE(same(again, generated));
    EXPECT_TRUE(load_cached_stipples(dir, mesh, params).has_value());
}

}  // namespace
}  // namespace stipple
