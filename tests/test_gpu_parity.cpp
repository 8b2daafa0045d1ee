// Device parity (issue 17: lavapipe and a real GPU draw the same stipples), src/render/device_parity.hpp.
// CI has one device, so the measurement is checked on it twice (it must find no difference), and the
// comparison on runs made to differ (it must find the difference, by the limits).
#include <bit>

#include "mesh/primitives.hpp"
#include "render/device_parity.hpp"
#include "support/gpu_test.hpp"
#include "support/render_helpers.hpp"

namespace stipple {
namespace {

class DeviceParity : public test::GpuTest {};

TEST_F(DeviceParity, OneDeviceTwiceDrawsTheSameStipplesOnEveryPath) {
    ObjectParams params;
    const test::Prepared sphere = test::prepare(make_uv_sphere(20000), params);
    const Sphere bounds = compute_bounding_sphere(sphere.mesh);
    const std::vector<ParityView> views = parity_views(3, {DensityPath::Splat, DensityPath::Vertex, DensityPath::Cpu});
    ASSERT_EQ(views.size(), 18u);  // 3 yaws x 2 elevations x 3 paths
    const DeviceRun a = run_parity_views(*context, sphere.mesh, sphere.stipples, bounds, params, {320, 256}, views);
    const DeviceRun b = run_parity_views(*context, sphere.mesh, sphere.stipples, bounds, params, {320, 256}, views);
    for (const ParitySample& s : a.samples) {
        EXPECT_GT(s.drawn, 1000);
        EXPECT_EQ(size_t(s.drawn), test::popcount(s.mask)) << "the count and the drawn set disagree";
        EXPECT_GT(s.mean_ink, 0.05);
        EXPECT_LT(s.mean_ink, 0.6);
    }
    const ParityReport report = compare_parity(a, b, views);
    std::printf("%s twice: worst count %.6f, set %.6f, ink %.6f\n", a.device.c_str(), report.worst_count,
                report.worst_set, report.worst_ink);
    EXPECT_EQ(report.worst_count, 0.0);
    EXPECT_EQ(report.worst_set, 0.0);
    EXPECT_EQ(report.worst_ink, 0.0);
    EXPECT_TRUE(report.holds());
}

TEST(DeviceParityComparison, FindsCountsSetsAndInkThatDiffer) {
    const std::vector<ParityView> views = parity_views(1, {DensityPath::Splat});  // two views
    DeviceRun a;
    for (int i = 0; i < 2; ++i) {
        ParitySample s;
        s.drawn = 10000;
        s.mean_ink = 0.25;
        s.mask.assign(10000 / 32 + 1, 0u);
        for (int k = 0; k < 10000; ++k) s.mask[size_t(k) / 32] |= 1u << (k % 32);
        a.samples.push_back(s);
    }
    DeviceRun b = a;
    EXPECT_TRUE(compare_parity(a, b, views).holds());

    // Within the limits: 5 stipples swapped for 5 others (same count), ink 0.5% apart.
    for (int k = 0; k < 5; ++k) b.samples[1].mask[size_t(k) / 32] &= ~(1u << (k % 32));
    b.samples[1].mask.back() |= 0xF8000000u;  // stipples 10011..10015 (past the 10,000)
    b.samples[1].mean_ink = 0.25 * 1.005;
    ParityReport report = compare_parity(a, b, views);
    EXPECT_TRUE(report.holds());
    EXPECT_DOUBLE_EQ(report.rows[1].set_difference, 10.0 / 10000.0);
    EXPECT_NEAR(report.worst_ink, 0.005, 1e-9);

    // Beyond: 0.2% more drawn in the first view, then 2% more ink.
    b.samples[0].drawn = 10020;
    report = compare_parity(a, b, views);
    EXPECT_NEAR(report.worst_count, 0.002, 1e-12);
    EXPECT_FALSE(report.holds());
    b.samples[0].drawn = 10000;
    b.samples[1].mean_ink = 0.25 * 1.02;
    EXPECT_FALSE(compare_parity(a, b, views).holds());
}

}  // namespace
}  // namespace stipple
