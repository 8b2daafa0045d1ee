// The scene files under assets/scenes reproduce figures of the paper (docs/paper-figures.md) from the
// project's own model. Each is drawn as a user would (`stipple render assets/scenes/NAME.json`) and
// checked for what its figure shows.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "io/png_io.hpp"
#include "support/run_command.hpp"
#include "support/test_paths.hpp"

namespace stipple {
namespace {

struct Drawn {
    Image image, mask;
};

Drawn draw(const std::string& scene, const std::string& name) {
    // A folder of its own: temp_dir empties it, and the two tests run side by side (ctest -j2), so a shared one
    // could lose the other's image while it drew (Figure3ScalesKeepTheirTone failed once in a whole-suite run,
    // likely so; alone it passes).
    const auto dir = test::temp_dir("asset-scenes-" + name);
    const std::string out = (dir / (name + ".png")).string(), mask = (dir / (name + "-mask.png")).string();
    const test::CommandResult r = test::run_stipple(
        {"render", test::source_path("assets/scenes/" + scene), "--width", "480", "--height", "240", "-o", out, "--mask", mask});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return {read_png(out), read_png(mask)};
}

double darkness(const Image& image, int x, int y) {
    const uint8_t* p = &image.pixels[(size_t(y) * size_t(image.width) + size_t(x)) * size_t(image.channels)];
    return image.channels < 3 ? 1.0 - p[0] / 255.0 : 1.0 - (0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]) / 255.0;
}
bool covered(const Image& mask, int x, int y) { return darkness(mask, x, y) < 0.5; }  // white where a surface covers

// The runs [begin, end) of columns (or, within columns [x0, x1), of rows) that the mask covers.
std::vector<std::pair<int, int>> covered_runs(const Image& mask, bool columns, int x0 = 0, int x1 = -1) {
    if (x1 < 0) x1 = mask.width;
    const int n = columns ? mask.width : mask.height;
    std::vector<std::pair<int, int>> runs;
    int start = -1;
    for (int i = 0; i <= n; ++i) {
        bool any = false;
        if (i < n) {
            if (columns)
                for (int y = 0; y < mask.height && !any; ++y) any = covered(mask, i, y);
            else
                for (int x = x0; x < x1 && !any; ++x) any = covered(mask, x, i);
        }
        if (any && start < 0) start = i;
        if (!any && start >= 0) runs.emplace_back(start, i), start = -1;
    }
    return runs;
}

// Figure 3: one model at three scales in one image, each keeping its tone (the extrinsic enhancement of
// each object, relative to its own size). The narrow field of view shows each copy from about the same
// side (with 30 degrees the copies at the frame's sides read 0.28 and 0.21, from their shading alone).
TEST(AssetScenes, Figure3ScalesKeepTheirTone) {
    const Drawn d = draw("figure3_scales.json", "figure3");
    const auto objects = covered_runs(d.mask, true);
    ASSERT_EQ(objects.size(), 3u);
    std::vector<double> ink;
    for (const auto& [x0, x1] : objects) {
        double sum = 0.0;
        size_t pixels = 0;
        for (int y = 0; y < d.mask.height; ++y)
            for (int x = x0; x < x1; ++x)
                if (covered(d.mask, x, y)) sum += darkness(d.image, x, y), ++pixels;
        ink.push_back(sum / double(pixels));
        std::printf("object over columns %d-%d: %zu covered pixels, mean ink %.4f\n", x0, x1, pixels, ink.back());
    }
    EXPECT_GT(objects[0].second - objects[0].first, 3 * (objects[2].second - objects[2].first)) << "scales 1 and 0.25";
    const double most = *std::max_element(ink.begin(), ink.end()), least = *std::min_element(ink.begin(), ink.end());
    EXPECT_GT(least, 0.15);
    EXPECT_LT(most / least, 1.12);
}

// Figure 8: no lines, Raskar-Cohen lines, and on the right two small copies, their lines thinned by the
// projected bounding sphere (above) and not (below): the same stipples, thinner lines.
TEST(AssetScenes, Figure8ThinsTheSmallCopysLines) {
    const Drawn d = draw("figure8_lines.json", "figure8");
    const auto columns = covered_runs(d.mask, true);
    ASSERT_EQ(columns.size(), 3u);
    const auto [x0, x1] = columns.back();
    const auto rows = covered_runs(d.mask, false, x0, x1);
    ASSERT_EQ(rows.size(), 2u);
    std::vector<size_t> dark;
    for (const auto& [y0, y1] : rows) {
        size_t n = 0;
        for (int y = std::max(0, y0 - 4); y < std::min(d.image.height, y1 + 4); ++y)
            for (int x = std::max(0, x0 - 4); x < std::min(d.image.width, x1 + 4); ++x) n += darkness(d.image, x, y) > 0.5;
        dark.push_back(n);
    }
    std::printf("small copies: thinned %zu dark pixels, not thinned %zu\n", dark[0], dark[1]);
    EXPECT_GT(dark[0], 100u);
    EXPECT_GT(double(dark[1]), 1.25 * double(dark[0]));
}

}  // namespace
}  // namespace stipple
