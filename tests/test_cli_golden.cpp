// Reference images: the default scene and the bunny, rendered by the command line, must equal the PNGs
// in tests/data/golden pixel for pixel. They were made before the architecture change of issue 12 and
// hold as long as nothing meant to change the drawing changes; a deliberate change rewrites them with
// tools/update_golden.sh and says why in its commit.
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/png_io.hpp"
#include "support/run_command.hpp"
#include "support/test_paths.hpp"

namespace stipple {
namespace {

const std::string kGoldenDir = test::source_path("tests/data/golden/");

// Renders `args` to a PNG and counts the pixels that differ from the reference image `name`.
void expect_identical(const std::string& name, std::vector<std::string> args) {
    const std::string out = test::output_path("golden_" + name).string();
    args.insert(args.begin(), "render");
    for (const char* a : {"-o", out.c_str(), "--width", "400", "--height", "320"}) args.push_back(a);
    test::CommandResult r = test::run_stipple(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Image got = read_png(out), want = read_png(kGoldenDir + name);
    ASSERT_EQ(got.width, want.width);
    ASSERT_EQ(got.height, want.height);
    ASSERT_EQ(got.channels, want.channels);
    ASSERT_GE(got.channels, 3);
    size_t differing = 0;
    for (size_t i = 0; i + 2 < got.pixels.size(); i += size_t(got.channels))
        differing += got.pixels[i] != want.pixels[i] || got.pixels[i + 1] != want.pixels[i + 1] ||
                     got.pixels[i + 2] != want.pixels[i + 2];
    std::printf("%s: %zu of %d pixels differ from the reference\n", name.c_str(), differing, got.width * got.height);
    EXPECT_EQ(differing, 0u) << "the drawing changed: compare " << out << " with " << kGoldenDir + name
                             << " (if the change is meant, run tools/update_golden.sh and say why)";
}

TEST(GoldenImages, DefaultSceneOnTheSplatPath) { expect_identical("default_splat.png", {"--density-path", "splat"}); }

TEST(GoldenImages, DefaultSceneOnTheVertexPath) { expect_identical("default_vertex.png", {"--density-path", "vertex"}); }

TEST(GoldenImages, BunnyWithToonSilhouettes) {
    const std::string bunny = test::shared_model("stanford-bunny.obj");
    if (bunny.empty()) GTEST_SKIP() << "../shared/models/stanford-bunny.obj is absent";
    expect_identical("bunny_toon_splat.png", {bunny, "--yaw", "30", "--pitch", "10", "--toon"});
}

}  // namespace
}  // namespace stipple
