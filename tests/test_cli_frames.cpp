// Frame sequences from `stipple render`: an orbit as numbered PNGs (all written, each a new view,
// identical from run to run), a scene's camera path, and clear errors for sequences that cannot be.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "io/png_io.hpp"
#include "support/image_checks.hpp"
#include "support/run_command.hpp"
#include "support/test_paths.hpp"

namespace stipple {
namespace {

using test::run_stipple;

std::string read_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string frame_name(int i) {
    char name[32];
    std::snprintf(name, sizeof(name), "%04d.png", i);
    return name;
}

// 8 frames of a 90-degree orbit of the default scene, small so that the test stays quick.
test::CommandResult render_orbit(const std::filesystem::path& dir) {
    return run_stipple({"render", "-o", (dir / "frames" / "%04d.png").string(), "--frames", "8", "--orbit", "90",
                        "--width", "320", "--height", "256", "--pitch", "15"});
}

TEST(CliFrames, OrbitWritesEveryFrameEachANewViewAndRepeatsExactly) {
    auto first = test::temp_dir("frames-orbit-1");
    auto second = test::temp_dir("frames-orbit-2");
    auto a = render_orbit(first);
    ASSERT_EQ(a.exit_code, 0) << a.err;
    EXPECT_EQ(a.err.find("validation"), std::string::npos) << a.err;
    EXPECT_TRUE(a.err.empty()) << "no progress bar unless stderr is a terminal: " << a.err;
    EXPECT_NE(a.out.find("wrote 8 frames"), std::string::npos) << a.out;
    auto b = render_orbit(second);
    ASSERT_EQ(b.exit_code, 0) << b.err;

    std::vector<Image> frames;
    for (int i = 0; i < 8; ++i) {
        auto path = first / "frames" / frame_name(i);
        ASSERT_TRUE(std::filesystem::exists(path)) << path;
        frames.push_back(read_png(path.string()));
        EXPECT_EQ(frames.back().width, 320);
        EXPECT_EQ(frames.back().height, 256);
        EXPECT_GT(test::ink_pixels(frames.back()), 1000u) << "frame " << i << " has no stipples";
        EXPECT_EQ(read_bytes(path), read_bytes(second / "frames" / frame_name(i)))
            << "frame " << i << " differs between two runs of the same command";
    }
    EXPECT_FALSE(std::filesystem::exists(first / "frames" / frame_name(8))) << "one frame too many";
    for (int i = 1; i < 8; ++i)
        EXPECT_GT(fraction_differing(frames[i - 1], frames[i], 8), 0.01) << "frames " << i - 1 << " and " << i;
}

TEST(CliFrames, CameraPathFromTheSceneFile) {
    auto dir = test::temp_dir("frames-path");
    std::string model = test::source_path("assets/blobby.glb");
    std::ofstream(dir / "scene.json") << "{\"objects\": [{\"model\": \"" << model << "\"}],\n"
                                      << " \"camera_path\": [{\"yaw\": 0, \"pitch\": 10}, {\"yaw\": 60, \"pitch\": 10,"
                                      << " \"distance\": 1.5}]}";
    auto r = run_stipple({"render", (dir / "scene.json").string(), "-o", (dir / "f%d.png").string(), "--frames", "3",
                          "--width", "240", "--height", "200"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (int i = 0; i < 3; ++i) EXPECT_TRUE(std::filesystem::exists(dir / ("f" + std::to_string(i) + ".png"))) << i;
    // The first frame sits on the first keyframe and the last on the last one.
    auto key0 = run_stipple({"render", model, "-o", (dir / "key0.png").string(), "--width", "240", "--height", "200",
                             "--yaw", "0", "--pitch", "10"});
    auto key1 = run_stipple({"render", model, "-o", (dir / "key1.png").string(), "--width", "240", "--height", "200",
                             "--yaw", "60", "--pitch", "10", "--distance", "1.5"});
    ASSERT_EQ(key0.exit_code, 0) << key0.err;
    ASSERT_EQ(key1.exit_code, 0) << key1.err;
    EXPECT_EQ(read_bytes(dir / "f0.png"), read_bytes(dir / "key0.png"));
    EXPECT_EQ(read_bytes(dir / "f2.png"), read_bytes(dir / "key1.png"));
    EXPECT_GT(fraction_differing(read_png((dir / "f0.png").string()), read_png((dir / "f1.png").string()), 8), 0.01);
}

// A vector sequence draws every frame with one capture (app::DrawingCapture; made again per frame it took
// 0.4-0.9 s of each): what one frame leaves in it must not reach the next. Three frames of one camera, then
// one of another, read alike.
TEST(CliFrames, VectorFramesOfOneViewAreAlike) {
    auto dir = test::temp_dir("frames-vector-alike");
    std::string model = test::source_path("assets/blobby.glb");
    std::ofstream(dir / "scene.json") << "{\"objects\": [{\"model\": \"" << model << "\", \"params\": {\"contours\": true}}],\n"
                                      << " \"camera_path\": [{\"yaw\": 20, \"pitch\": 10}, {\"yaw\": 20, \"pitch\": 10}]}";
    for (const char* ext : {"svg", "csv"}) {
        auto r = run_stipple({"render", (dir / "scene.json").string(), "-o", (dir / ("f%d." + std::string(ext))).string(),
                              "--frames", "3", "--width", "240", "--height", "200"});
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const std::string first = read_bytes(dir / ("f0." + std::string(ext)));
        EXPECT_GT(first.size(), 1000u);
        for (int i = 1; i < 3; ++i)
            EXPECT_EQ(read_bytes(dir / ("f" + std::to_string(i) + "." + ext)), first) << ext << " frame " << i;
    }
}

// A scene of the default model and the camera_path given (JSON), written in `dir`'s sibling folder (the
// test checks that nothing is written in `dir`).
std::string scene_with_path(const std::filesystem::path& dir, const std::string& path) {
    const std::filesystem::path scenes = dir.parent_path() / (dir.filename().string() + "-scenes");
    std::filesystem::create_directories(scenes);
    const std::filesystem::path file = scenes / (std::to_string(std::hash<std::string>{}(path)) + ".json");
    std::ofstream(file) << "{\"objects\": [{\"model\": \"" << test::source_path("assets/blobby.glb")
                        << "\"}], \"camera_path\": " << path << "}";
    return file.string();
}

// %0Nd up to 99 wide (%010d was refused, though the message allowed it); %% is a literal % in a single
// frame's name too (y%%.png was written as named); a camera_path zooming over the whole range the scene
// file allows draws every frame (the distances' ratio overflowed a float: a blank frame with exit 0).
TEST(CliFrames, PatternsAndCameraPathsAtTheirLimits) {
    auto dir = test::temp_dir("frames-limits");
    auto wide = run_stipple({"render", "-o", (dir / "d%010d.png").string(), "--frames", "2", "--orbit", "90", "--width",
                             "64", "--height", "64"});
    ASSERT_EQ(wide.exit_code, 0) << wide.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "d0000000001.png"));
    auto percent = run_stipple({"render", "-o", (dir / "y%%.png").string(), "--width", "64", "--height", "64"});
    ASSERT_EQ(percent.exit_code, 0) << percent.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "y%.png"));
    auto literal = run_stipple({"render", "-o", (dir / "50%.png").string(), "--width", "64", "--height", "64"});
    ASSERT_EQ(literal.exit_code, 0) << literal.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "50%.png")) << "a name that is no pattern is kept as written";
    auto both = run_stipple({"render", "-o", (dir / "5%%0%.png").string(), "--width", "64", "--height", "64"});
    ASSERT_EQ(both.exit_code, 0) << both.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "5%0%.png")) << "but for %%, a literal % there too";

    const std::string zoom = scene_with_path(dir, "[{\"world_distance\": 1e-20}, {\"world_distance\": 1e20}]");
    auto frames = run_stipple({"render", zoom, "-o", (dir / "z%d.png").string(), "--frames", "3", "--width", "64",
                               "--height", "64"});
    ASSERT_EQ(frames.exit_code, 0) << frames.err;
    const std::string at_one = scene_with_path(dir, "[{\"world_distance\": 1}]");
    auto one = run_stipple({"render", at_one, "-o", (dir / "one.png").string(), "--width", "64", "--height", "64"});
    ASSERT_EQ(one.exit_code, 0) << one.err;
    // Frame 1 sits halfway in the logarithm of the distance: at 1, as the one-camera scene.
    EXPECT_GT(test::ink_pixels(read_png((dir / "z1.png").string())), 100u);
    EXPECT_LT(fraction_differing(read_png((dir / "z1.png").string()), read_png((dir / "one.png").string()), 8), 0.01);
}

TEST(CliFrames, SequencesThatCannotBeAreRejectedClearly) {
    auto dir = test::temp_dir("frames-bad");
    struct Case {
        std::vector<std::string> args;
        const char* expect;
    };
    const std::string out = (dir / "x.png").string();
    const Case cases[] = {
        {{"render", "-o", out, "--frames", "4", "--orbit", "90"}, "no frame number"},
        {{"render", "-o", (dir / "%04d.png").string(), "--frames", "4"}, "--orbit"},
        {{"render", "-o", (dir / "%04d.png").string(), "--orbit", "90"}, "--frames"},
        {{"render", "-o", (dir / "%s.png").string(), "--frames", "2", "--orbit", "90"}, "%0Nd"},
        {{"render", "-o", (dir / "%d_%d.png").string(), "--frames", "2", "--orbit", "90"}, "more than one"},
        {{"render", "-o", (dir / "%d.png").string(), "--frames", "0", "--orbit", "90"}, "--frames"},
        // As typed (it was 1000000000000000019884624838656.000000).
        {{"render", "-o", (dir / "%d.png").string(), "--frames", "2", "--orbit", "1e30"},
         "--orbit = 1e30 must be in -36000..36000 degrees"},
        {{"render", "-o", (dir / "%d.png").string(), "--frames", "3", "--orbit", "90", "--repeat", "2"}, "--repeat"},
        // printf's %Nd pads with spaces, which no file name wants: %0Nd pads with zeros.
        {{"render", "-o", (dir / "%10d.png").string(), "--frames", "2", "--orbit", "90"}, "%0Nd"},
        {{"render", "-o", (dir / "%0100d.png").string(), "--frames", "2", "--orbit", "90"}, "%0Nd"},
        // Mask frames 0 and 1 (g10, g11) were written over by image frames 10 and 11, in silence.
        {{"render", "-o", (dir / "g%d.png").string(), "--mask", (dir / "g1%d.png").string(), "--frames", "12", "--orbit",
          "90"},
         "names the file of an image of -o"},
        {{"render", scene_with_path(dir, "[{\"yaw\": 30}]"), "-o", (dir / "b%d.png").string(), "--frames", "5"},
         ".json: its camera_path of one camera shows every frame the same (--frames 5)"},
        {{"render", "-o", (dir / "%d.png").string(), "--mask", (dir / "m%s.png").string(), "--frames", "2", "--orbit", "90"},
         "--mask: output pattern"},
    };
    for (const Case& c : cases) {
        auto r = run_stipple(c.args);
        EXPECT_EQ(r.exit_code, 1) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(c.expect), std::string::npos) << r.err;
    }
    EXPECT_TRUE(std::filesystem::is_empty(dir)) << "nothing should be written";
}

}  // namespace
}  // namespace stipple
