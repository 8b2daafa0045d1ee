// The orthographic camera (beyond the paper, for technical and scientific illustration): parallel lines of
// sight, a scale that holds at every depth, and every term of the drawing read with the eye ray +z.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/commands.hpp"
#include "io/png_io.hpp"
#include "mesh/primitives.hpp"
#include "support/model_files.hpp"
#include "support/run_command.hpp"
#include "support/test_paths.hpp"
#include "support/test_shapes.hpp"

namespace stipple {
namespace {

bool covered(const Image& mask, int x, int y) {
    if (x < 0 || y < 0 || x >= mask.width || y >= mask.height) return false;
    return mask.pixels[size_t(mask.channels) * (size_t(y) * size_t(mask.width) + size_t(x))] > 127;
}

bool inked(const Image& image, int x, int y) {
    const uint8_t* p = &image.pixels[size_t(image.channels) * (size_t(y) * size_t(image.width) + size_t(x))];
    return p[0] < 128;
}

// Renders `model` with `options` at 640x512 into `dir`/`name`.png and its coverage mask; returns {image, mask}.
std::pair<Image, Image> render(const std::filesystem::path& dir, const std::string& name, const std::string& model,
                               std::vector<std::string> options) {
    const std::string png = (dir / (name + ".png")).string(), mask = (dir / (name + "-mask.png")).string();
    std::vector<std::string> args = {"render", model, "-o", png, "--mask", mask, "--width", "640", "--height", "512"};
    args.insert(args.end(), options.begin(), options.end());
    const test::CommandResult r = test::run_stipple(args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return {read_png(png), read_png(mask)};
}

// Covered rows in each column that the mask covers, but for `margin` columns at either end.
std::vector<int> column_heights(const Image& mask, int margin) {
    std::vector<int> heights;
    for (int x = 0; x < mask.width; ++x) {
        int rows = 0;
        for (int y = 0; y < mask.height; ++y) rows += covered(mask, x, y);
        if (rows > 0) heights.push_back(rows);
    }
    if (heights.size() <= size_t(2 * margin)) return {};
    return std::vector<int>(heights.begin() + margin, heights.end() - margin);
}

// A long box seen from the side at eye height: in perspective its near end is taller on screen than its far
// end; in parallel projection every column it covers is as tall as the box.
TEST(Orthographic, ParallelEdgesStayParallel) {
    const auto dir = test::temp_dir("orthographic-box");
    const std::string box = test::write_file(dir / "long_box.obj", test::obj_text(test::make_box({1.0f, 1.0f, 8.0f})));
    int spread[2] = {0, 0};
    for (int ortho = 0; ortho < 2; ++ortho) {
        std::vector<std::string> options = {"--yaw", "60", "--pitch", "0", "--dmax", "0", "--contours"};
        if (ortho) options.push_back("--orthographic");
        const auto [image, mask] = render(dir, ortho ? "ortho" : "perspective", box, options);
        const std::vector<int> heights = column_heights(mask, 3);
        ASSERT_GT(heights.size(), 100u) << "the box covers too few columns";
        const auto [lo, hi] = std::minmax_element(heights.begin(), heights.end());
        spread[ortho] = *hi - *lo;
        std::printf("%s: the box's columns %d to %d px tall over %zu columns\n", ortho ? "orthographic" : "perspective", *lo,
                    *hi, heights.size());
    }
    EXPECT_LE(spread[1], 2) << "parallel projection: the box's top and bottom edges are parallel";
    EXPECT_GT(spread[0], 10) << "perspective foreshortens the far end (the test tells the two apart)";
}

// Framed, a sphere spans the frame's height in both projections; twice as far, exactly half of it in parallel
// projection (the view's span doubles), a little less in perspective (the cone of sight narrows faster).
TEST(Orthographic, TheDistanceSetsTheScale) {
    const auto dir = test::temp_dir("orthographic-scale");
    const std::string sphere = test::write_file(dir / "sphere.obj", test::obj_text(make_uv_sphere(20000)));
    const auto height_of = [&](const std::string& name, std::vector<std::string> options) {
        const auto [image, mask] = render(dir, name, sphere, options);
        int lo = mask.height, hi = -1;
        for (int y = 0; y < mask.height; ++y)
            for (int x = 0; x < mask.width; ++x)
                if (covered(mask, x, y)) lo = std::min(lo, y), hi = std::max(hi, y);
        return hi - lo + 1;
    };
    const int framed = height_of("framed", {"--orthographic"});
    const int far = height_of("far", {"--orthographic", "--distance", "2"});
    const int far_perspective = height_of("far-perspective", {"--distance", "2"});
    std::printf("sphere's height: framed %d px, at twice the distance %d px (perspective %d px) of 512\n", framed, far,
                far_perspective);
    EXPECT_NEAR(framed, 512, 3);
    EXPECT_NEAR(far, 256, 2);
    EXPECT_LT(far_perspective, 252);
}

// The contours (edges between a polygon facing the viewer and one facing away) lie on the sphere's outline:
// facing is judged against +z. Judged against rays from an eye at the camera's place, they would lie on a
// smaller circle inside it (about 4% of the radius in from the outline at the framing distance).
TEST(Orthographic, ContoursLieOnTheOutline) {
    const auto dir = test::temp_dir("orthographic-contours");
    const std::string sphere = test::write_file(dir / "sphere.obj", test::obj_text(make_uv_sphere(40000)));
    const auto [image, mask] = render(dir, "contours", sphere, {"--orthographic", "--dmax", "0", "--contours", "--yaw", "20",
                                                                "--pitch", "35"});
    size_t ink = 0, near_edge = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            if (!inked(image, x, y)) continue;
            ++ink;
            bool edge = false;  // a pixel the sphere does not cover within 4 px
            for (int dy = -4; dy <= 4 && !edge; ++dy)
                for (int dx = -4; dx <= 4 && !edge; ++dx) edge = !covered(mask, x + dx, y + dy);
            near_edge += edge;
        }
    std::printf("contour pixels: %zu, %.2f%% within 4 px of the outline\n", ink, 100.0 * double(near_edge) / double(ink));
    EXPECT_GT(ink, 1000u) << "no contour drawn";
    EXPECT_GE(double(near_edge), 0.98 * double(ink));
}

// The toon ramp (§3.1: ink where N.E is small) and the stipples' fade follow +z too: a sphere's shade is a ring
// centred on its image, at the outline's radius, with nothing inked at its centre.
TEST(Orthographic, TheToonRingFollowsTheOutline) {
    const auto dir = test::temp_dir("orthographic-toon");
    const std::string sphere = test::write_file(dir / "sphere.obj", test::obj_text(make_uv_sphere(40000)));
    const auto [image, mask] = render(dir, "toon", sphere, {"--orthographic", "--dmax", "0", "--toon", "--pitch", "35"});
    // Darkness against the radius from the mask's centre, in rings of 1/40 of the sphere's image radius.
    double cx = 0.0, cy = 0.0, n = 0.0;
    for (int y = 0; y < mask.height; ++y)
        for (int x = 0; x < mask.width; ++x)
            if (covered(mask, x, y)) cx += x, cy += y, n += 1.0;
    ASSERT_GT(n, 1000.0);
    cx /= n, cy /= n;
    const double radius = std::sqrt(n / 3.14159265);
    constexpr size_t kRings = 40;
    std::vector<double> dark(kRings, 0.0), count(kRings, 0.0);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            if (!covered(mask, x, y)) continue;
            const size_t ring = std::min(kRings - 1, size_t(std::hypot(x - cx, y - cy) / radius * double(kRings)));
            dark[ring] += 1.0 - image.pixels[size_t(image.channels) * (size_t(y) * size_t(image.width) + size_t(x))] / 255.0;
            count[ring] += 1.0;
        }
    for (size_t r = 0; r < kRings; ++r) dark[r] /= std::max(count[r], 1.0);
    std::printf("toon darkness from the centre out:");
    for (const double d : dark) std::printf(" %.2f", d);
    std::printf("\n");
    for (size_t r = 0; r + 4 < kRings; ++r) EXPECT_LT(dark[r], 0.02) << "facing the viewer: no toon ink, ring " << r;
    EXPECT_GT(dark[kRings - 1], 0.2) << "the outline's ring is inked";
    for (size_t r = kRings - 4; r < kRings; ++r) EXPECT_GE(dark[r], dark[r - 1]) << "the ramp darkens outward, ring " << r;
}

// --orthographic and --perspective override a scene file's camera; the viewer keeps the camera_path as written
// (Ctrl+S saves it: `view --orthographic` made every keyframe orthographic), while render draws the path's
// frames in the projection asked. Both at once are refused.
TEST(Orthographic, TheCommandLineSetsTheSceneCameraAndLeavesThePath) {
    const auto dir = test::temp_dir("orthographic-scene");
    test::write_file(dir / "sphere.obj", test::obj_text(make_uv_sphere(500)));
    const std::string scene = test::write_file(dir / "scene.json", R"({"objects": [{"model": "sphere.obj"}],
        "camera": {"projection": "orthographic"}, "camera_path": [{"yaw": 0}, {"yaw": 90, "projection": "orthographic"}]})");
    const auto read = [&](std::vector<std::string> argv) {
        const cli::CommandOptions accepted = cli::view_command_options();
        return cli::scene_from_command_line(cli::Args(argv, accepted.flags, accepted.options), "view");
    };
    const Scene as_written = read({scene});
    EXPECT_TRUE(as_written.camera.orthographic);
    const Scene perspective = read({scene, "--perspective"});
    EXPECT_FALSE(perspective.camera.orthographic);
    ASSERT_EQ(perspective.camera_path.size(), 2u);
    EXPECT_FALSE(perspective.camera_path[0].orthographic);
    EXPECT_TRUE(perspective.camera_path[1].orthographic) << "the path stays as written";
    EXPECT_TRUE(read({scene, "--orthographic"}).camera.orthographic);
    const test::CommandResult both = test::run_stipple({"render", scene, "--orthographic", "--perspective", "-o",
                                                        (dir / "x.png").string()});
    EXPECT_EQ(both.exit_code, 1);
    EXPECT_EQ(both.err, "stipple: --orthographic and --perspective: give one of them\n");
}

}  // namespace
}  // namespace stipple
