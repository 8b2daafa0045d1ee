// Animated models where the user meets them (issue 16): `render --animation --time`, `--frames N --fps F`
// sequences, scene files naming an animation, `info` listing what moves a model, and every bad request
// answered in one line with a non-zero exit and no file written. A generated rig (a skinned cylinder
// that bends) always; the shared fox when present.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <optional>

#include <nlohmann/json.hpp>

#include "anim/procedural_rigs.hpp"
#include "io/png_io.hpp"
#include "scene/scene_json.hpp"
#include "support/anim_files.hpp"
#include "support/draco_packing.hpp"
#include "support/image_checks.hpp"
#include "support/meshopt_packing.hpp"
#include "support/model_files.hpp"
#include "support/run_command.hpp"
#include "support/test_paths.hpp"

namespace stipple {
namespace {

using test::run_stipple;
namespace fs = std::filesystem;

// Pixels whose colour differs between two images of the same size.
size_t differing_pixels(const Image& a, const Image& b) {
    size_t n = 0;
    for (size_t i = 0; i + 3 < a.pixels.size(); i += 4) n += a.pixels[i] != b.pixels[i];
    return n;
}

std::string cylinder(const std::string& folder) {
    return test::write_rig(anim::rigs::bending_cylinder(), folder, "cylinder");
}

// Small images need few candidates: generating the default density would dominate the test's time.
std::vector<std::string> sparse(std::vector<std::string> args) {
    args.insert(args.end(), {"--dmax", "0.05"});
    return args;
}

void write_text(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

// A shader missing from the build (a broken install, a wrong STIPPLE_SHADER_DIR) is one line naming it. The
// passes made before it, whose constructors then threw, were left alive, and the validation layer
// listed each at the device's destruction (the pipeline layouts of the renderer, of the polygon
// pass, the skinning pass's texel views). Pipelines are made when a frame first needs them, but their
// shaders are checked before any frame: one this frame does not use (the silhouette lines') is told too.
TEST(CliAnimation, AMissingShaderIsOneLineAndLeavesNothingBehind) {
    const std::string model = cylinder("cli_anim_missing_shader");
    const fs::path shaders = test::temp_dir("cli_anim_missing_shader_dir");
    // The build's shaders copied, `alter` applied to the copy, and the bent cylinder rendered with them.
    const auto render_with = [&](const std::function<void(const fs::path&)>& alter) {
        fs::remove_all(shaders);
        fs::create_directories(shaders);
        for (const auto& entry : fs::directory_iterator(STIPPLE_SHADER_DIR))
            if (entry.path().extension() == ".spv") fs::copy_file(entry.path(), shaders / entry.path().filename());
        alter(shaders);
        const test::CommandResult r = [&] {
            test::ScopedEnv env("STIPPLE_SHADER_DIR", shaders.string());
            return run_stipple(sparse({"render", model, "--time", "0.3", "-o", (shaders / "never.png").string(), "--width", "64", "--height", "64"}));
        }();
        EXPECT_FALSE(fs::exists(shaders / "never.png"));
        return r;
    };
    for (const char* missing : {"depth.vert.spv", "polygon_constants.comp.spv", "deform.comp.spv", "silhouette.frag.spv"}) {
        const test::CommandResult r = render_with([&](const fs::path& dir) { fs::remove(dir / missing); });
        EXPECT_EQ(r.exit_code, 1) << missing;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(std::string(missing) + ": shader not found"), std::string::npos) << r.err;
    }
    // A module cut short, or not SPIR-V at all: named as such (until 2026-12-04 "out of memory" with the
    // validation layer on, VkResult(unknown) without it).
    for (const auto& [broken, bytes] : {std::pair<const char*, size_t>{"depth.vert.spv", 100}, {"deform.comp.spv", 0}}) {
        const char* name = broken;
        const size_t size = bytes;
        const test::CommandResult r = render_with([&](const fs::path& dir) {
            if (size > 0) fs::resize_file(dir / name, size);
            else test::write_file(dir / name, "#version 450 not compiled");
        });
        EXPECT_EQ(r.exit_code, 1) << broken;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(std::string(broken) + (bytes > 0 ? ": a truncated or corrupt SPIR-V module" : ": not a SPIR-V module")),
                  std::string::npos) << r.err;
    }
    // A module of another stage in its place (lavapipe crashed on a fragment shader bound as compute), and a
    // folder in its place (an internal error from deep in the stream): refused, naming the file.
    {
        const test::CommandResult r = render_with([&](const fs::path& dir) {
            fs::copy_file(dir / "toon.frag.spv", dir / "deform.comp.spv", fs::copy_options::overwrite_existing);
        });
        EXPECT_EQ(r.exit_code, 1);
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find("deform.comp.spv: a shader of another stage than its name says (SPIR-V execution model 4, "
                             "expected 5)"),
                  std::string::npos) << r.err;
    }
    {
        const test::CommandResult r = render_with([&](const fs::path& dir) {
            fs::remove(dir / "depth.vert.spv");
            fs::create_directory(dir / "depth.vert.spv");
        });
        EXPECT_EQ(r.exit_code, 1);
        EXPECT_NE(r.err.find("depth.vert.spv: not a file"), std::string::npos) << r.err;
    }
}

size_t lines(const std::string& text) { return size_t(std::count(text.begin(), text.end(), '\n')); }

TEST(CliAnimation, TimeAndAnimationChooseThePose) {
    const std::string model = cylinder("cli_anim_time");
    const fs::path dir = test::temp_dir("cli_anim_time_out");
    const std::string straight = (dir / "straight.png").string(), bent = (dir / "bent.png").string(),
                      by_index = (dir / "index.png").string();
    auto a = run_stipple(sparse({"render", model, "-o", straight, "--mask", (dir / "straight_mask.png").string(),
                                 "--width", "200", "--height", "200", "--time", "0"}));
    ASSERT_EQ(a.exit_code, 0) << a.err;
    auto b = run_stipple(sparse({"render", model, "-o", bent, "--mask", (dir / "bent_mask.png").string(), "--width",
                                 "200", "--height", "200", "--animation", "Bend", "--time", "1", "--stats"}));
    ASSERT_EQ(b.exit_code, 0) << b.err;
    EXPECT_NE(b.out.find("animation:          object 0: 'Bend' (2.000 s) at 1.000 s"), std::string::npos) << b.out;
    auto c = run_stipple(sparse({"render", model, "-o", by_index, "--width", "200", "--height", "200", "--animation", "0",
                          "--time", "1"}));
    ASSERT_EQ(c.exit_code, 0) << c.err;
    const Image t = read_png(bent), u = read_png(by_index);
    EXPECT_GT(differing_pixels(read_png((dir / "straight_mask.png").string()), read_png((dir / "bent_mask.png").string())),
              300u) << "bent at 1 s, straight at 0 s";
    EXPECT_EQ(differing_pixels(t, u), 0u) << "the animation by name and by index is the same";
}

TEST(CliAnimation, CompressedFilesRenderAsThePlainOne) {
    // The bending cylinder compressed with meshopt (every view, lossless, the same vertex order) draws the
    // same image; losslessly Draco-compressed (its own vertex and triangle order, so other stipples) the same
    // footprint. Through the stipple binary itself: linked with libdraco as it comes, its tinygltf calls went
    // to the copy libdraco carries and `stipple info fox.glb` crashed (third_party_config/Draco.cmake).
    const fs::path dir = test::temp_dir("cli_anim_compressed");
    const std::string plain = anim::rigs::bending_cylinder().glb();
    const std::string files[3] = {test::write_file(dir / "plain.glb", plain),
                                  test::write_file(dir / "meshopt.glb", test::meshopt_pack_glb(plain)),
                                  test::write_file(dir / "draco.glb", test::draco_pack_glb(plain))};
    std::vector<Image> images, masks;
    for (const std::string& file : files) {
        const std::string png = file + ".png", mask = file + ".mask.png";
        auto r = run_stipple(sparse({"render", file, "-o", png, "--mask", mask, "--width", "200", "--height", "200",
                                     "--animation", "Bend", "--time", "1"}));
        ASSERT_EQ(r.exit_code, 0) << file << ": " << r.err;
        images.push_back(read_png(png));
        masks.push_back(read_png(mask));
    }
    // `info` says what was decoded (nothing for the plain file).
    const std::string said[3] = {"", "decoded:             EXT_meshopt_compression (", "decoded:             KHR_draco_mesh_compression (1 primitive)"};
    for (int i = 0; i < 3; ++i) {
        auto r = run_stipple(sparse({"info", files[i]}));
        ASSERT_EQ(r.exit_code, 0) << files[i] << ": " << r.err;
        if (i == 0) EXPECT_EQ(r.out.find("decoded:"), std::string::npos) << r.out;
        else EXPECT_NE(r.out.find(said[i]), std::string::npos) << r.out;
    }
    EXPECT_EQ(differing_pixels(images[0], images[1]), 0u) << "meshopt";
    EXPECT_EQ(differing_pixels(masks[0], masks[2]), 0u) << "Draco";
    EXPECT_GT(differing_pixels(images[0], images[2]), 0u) << "Draco's order makes other stipples: not the same file read twice";
}

TEST(CliAnimation, FramesAndFpsRenderTheAnimation) {
    const std::string model = cylinder("cli_anim_frames");
    const fs::path dir = test::temp_dir("cli_anim_frames_out");
    // 4 frames at 2 fps: 0, 0.5, 1.0, 1.5 s of the 2 s bend.
    auto r = run_stipple(sparse({"render", model, "-o", (dir / "%03d.png").string(), "--frames", "4", "--fps", "2",
                          "--width", "160", "--height", "160"}));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("wrote 4 frames"), std::string::npos) << r.out;
    std::vector<Image> frames;
    for (const char* name : {"000.png", "001.png", "002.png", "003.png"}) {
        ASSERT_TRUE(fs::exists(dir / name)) << name;
        frames.push_back(read_png((dir / name).string()));
    }
    // About 200 whole dots at this density (--dmax 0.05): the upper half moves between frames. (More than 200
    // pixels until 2026-12-05, when the polygons that cannot hold a whole stipple drew faint dots on every one.)
    for (size_t i = 1; i < frames.size(); ++i) EXPECT_GT(differing_pixels(frames[i - 1], frames[i]), 100u) << i;
    // The frame at 0.5 s is the single frame rendered at --time 0.5.
    const std::string single = (dir / "single.png").string();
    auto one = run_stipple(sparse({"render", model, "-o", single, "--time", "0.5", "--width", "160", "--height", "160"}));
    ASSERT_EQ(one.exit_code, 0) << one.err;
    EXPECT_EQ(differing_pixels(read_png(single), frames[1]), 0u);
}

TEST(CliAnimation, FoxWalkSequence) {
    const std::string fox = test::shared_model("fox.glb");
    if (fox.empty()) GTEST_SKIP() << "../shared/models/fox.glb not present";
    const fs::path dir = test::temp_dir("cli_anim_fox");
    auto r = run_stipple({"render", fox, "--animation", "Walk", "--frames", "3", "--fps", "10", "-o",
                          (dir / "%d.png").string(), "--mask", (dir / "m%d.png").string(), "--width", "240", "--height",
                          "200", "--yaw", "70"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Image m0 = read_png((dir / "m0.png").string()), m2 = read_png((dir / "m2.png").string());
    EXPECT_GT(differing_pixels(m0, m2), 100u) << "the legs moved between 0 and 0.2 s";
}

TEST(CliAnimation, SceneFilesNameAnimationStartAndSpeed) {
    const std::string model = cylinder("cli_anim_scene");
    const fs::path dir = test::temp_dir("cli_anim_scene_out");
    // Starting 0.5 s in at twice the speed, scene time 0.25 s is 1 s into the bend.
    write_text(dir / "scene.json", R"({"objects": [{"model": ")" + model +
                                       R"(", "params": {"dmax": 0.05},
                                       "animation": {"name": "Bend", "start": 0.5, "speed": 2, "loop": true}}]})");
    auto scene = run_stipple({"render", (dir / "scene.json").string(), "-o", (dir / "scene.png").string(), "--time",
                              "0.25", "--width", "160", "--height", "160"});
    ASSERT_EQ(scene.exit_code, 0) << scene.err;
    auto direct = run_stipple(sparse({"render", model, "-o", (dir / "direct.png").string(), "--time", "1", "--width", "160",
                               "--height", "160"}));
    ASSERT_EQ(direct.exit_code, 0) << direct.err;
    EXPECT_EQ(differing_pixels(read_png((dir / "scene.png").string()), read_png((dir / "direct.png").string())), 0u);

    // Saved and read back, the choice is kept.
    const Scene parsed = load_scene((dir / "scene.json").string());
    ASSERT_EQ(parsed.objects.size(), 1u);
    EXPECT_EQ(parsed.objects[0].animation.name, "Bend");
    EXPECT_EQ(parsed.objects[0].animation.start, 0.5);
    EXPECT_EQ(parsed.objects[0].animation.speed, 2.0);
    const Scene again = parse_scene(scene_to_json(parsed, dir), "again.json", dir);
    EXPECT_EQ(again.objects[0].animation.name, "Bend");
    EXPECT_EQ(again.objects[0].animation.time_at(0.25), 1.0);
    // A default choice is not written at all (static scenes keep their files as they were).
    Scene plain = parsed;
    plain.objects[0].animation = {};
    EXPECT_EQ(scene_to_json(plain, dir).find("animation"), std::string::npos);
}

TEST(CliAnimation, BadRequestsAreOneLineAndWriteNothing) {
    const std::string model = cylinder("cli_anim_bad");
    // Into folders that do not exist yet: a refused request makes none (it made -o's folder before refusing).
    const fs::path dir = test::temp_dir("cli_anim_bad_out");
    const std::string out = (dir / "not-made" / "x.png").string();
    const fs::path scenes = test::temp_dir("cli_anim_bad_scenes");
    write_text(scenes / "unknown.json", R"({"objects": [{"model": ")" + model + R"(", "animation": {"name": "Jump"}}]})");
    write_text(scenes / "speed.json", R"({"objects": [{"model": ")" + model + R"(", "animation": {"speed": "fast"}}]})");
    write_text(scenes / "negative.json", R"({"objects": [{"model": ")" + model + R"(", "animation": {"name": -1}}]})");
    write_text(scenes / "fraction.json", R"({"objects": [{"model": ")" + model + R"(", "animation": {"name": 0.5}}]})");
    write_text(scenes / "huge.json", R"({"objects": [{"model": ")" + model + R"(", "animation": {"name": 1e19}}]})");
    write_text(scenes / "huger.json", R"({"objects": [{"model": ")" + model + R"(", "animation": {"name": 1e20}}]})");
    write_text(scenes / "field.json", R"({"objects": [{"model": ")" + model + R"(", "animation": {"clip": "Bend"}}]})");
    write_text(scenes / "cpu.json", R"({"objects": [{"model": ")" + model + R"(", "params": {"density_path": "cpu"}}]})");

    // Bad animation data, at the command line: decreasing key times in the file.
    anim::GltfBuilder broken = anim::rigs::bending_cylinder();
    broken.doc["animations"][0]["samplers"][0]["input"] = broken.add_floats({0, 2, 1}, "SCALAR");
    const std::string broken_path = test::write_rig(broken, "cli_anim_broken", "broken");

    struct Case {
        std::vector<std::string> args;
        std::string expect;
    };
    const Case cases[] = {
        {{"render", model, "-o", out, "--animation", "Jump"}, "no animation 'Jump' (its animations: 0 'Bend', 1 'Lift')"},
        {{"render", model, "-o", out, "--animation", "7"}, "no animation '7'"},
        {{"render", model, "-o", out, "--time", "nan"}, "--time"},
        {{"render", model, "-o", out, "--time", "1e9"}, "--time"},
        {{"render", model, "-o", (dir / "frames" / "%d.png").string(), "--frames", "2", "--fps", "0"}, "--fps"},
        {{"render", model, "-o", (dir / "frames" / "%d.png").string(), "--frames", "2", "--fps", "1e-308"}, "must be in 0.001..1000"},
        {{"render", model, "-o", out, "--fps", "30"}, "--fps needs --frames"},
        {{"render", model, "-o", out, "--density-path", "cpu"}, model + ": the cpu density path cannot draw an animated model (it"},
        {{"render", model, "-o", out, "--density-path", "cpu-splat"}, "cannot draw an animated model"},
        {{"render", "-o", out, "--time", "1"}, "--time needs an animated model"},
        {{"render", "-o", out, "--animation", "Walk"}, "has no animation to play"},
        {{"render", (scenes / "unknown.json").string(), "-o", out}, "objects[0].animation.name: "},
        {{"render", (scenes / "speed.json").string(), "-o", out}, "objects[0].animation.speed: expected a number"},
        // A number said "got number", as if a number were wrong.
        {{"render", (scenes / "negative.json").string(), "-o", out},
         "objects[0].animation.name: an animation index is a whole number of 0 or more, got -1"},
        {{"render", (scenes / "fraction.json").string(), "-o", out},
         "objects[0].animation.name: an animation index is a whole number of 0 or more, got 0.5"},
        // A whole number written as a float is an index like any other (it said "a whole number ..., got 1e+19").
        {{"render", (scenes / "huge.json").string(), "-o", out}, "no animation '10000000000000000000'"},
        {{"render", (scenes / "huger.json").string(), "-o", out}, "objects[0].animation.name: animation index 1e+20 is beyond any file's animations"},
        {{"render", (scenes / "field.json").string(), "-o", out}, "objects[0].animation.clip: unknown field"},
        // Said where the scene names the path.
        {{"render", (scenes / "cpu.json").string(), "-o", out},
         "cpu.json: objects[0].params.density_path: " + model + ": the cpu density path cannot draw an animated model"},
        {{"render", (scenes / "unknown.json").string(), "-o", out, "--animation", "Bend"}, "scene file"},
        {{"render", broken_path, "-o", out}, "animations[0].samplers[0].input: key 2 (time 1) comes before key 1"},
        {{"info", broken_path}, "animations[0].samplers[0].input"},
    };
    for (const Case& c : cases) {
        auto r = run_stipple(c.args);
        EXPECT_NE(r.exit_code, 0) << c.expect;
        EXPECT_EQ(lines(r.err), 1u) << r.err;
        EXPECT_NE(r.err.find(c.expect), std::string::npos) << "expected '" << c.expect << "' in: " << r.err;
    }
    EXPECT_TRUE(fs::is_empty(dir)) << "nothing should be written";
}

// tone draws an animated model as render does, its first animation at 0 s. It drew it without its
// motion: the candidates generated for stretch all drawn as rest density (the fox read 0.52 mean ink in
// tone, 0.41 in render). parity, changed alike, frames its views its own way and compares a device with
// itself here: it is only run on the animated model.
// The deformation and polygon passes dispatched in rows (see CliRender.WideDispatchesGoInRowsAndDrawTheSame):
// the bent cylinder is drawn exactly as in one row.
TEST(CliAnimation, DeformationInRowsDrawsTheSame) {
    const fs::path dir = test::temp_dir("cli_anim_rows");
    const std::string model = cylinder("cli_anim_rows_model");
    std::string bytes[2];
    for (int rows = 0; rows < 2; ++rows) {
        const std::string out = (dir / (rows ? "rows.png" : "one.png")).string();
        // Rows of one group: the cylinder's 110 vertices are two groups of the deformation, 216 polygons four.
        std::optional<test::ScopedEnv> in_rows;
        if (rows) in_rows.emplace("STIPPLE_MAX_WORKGROUPS", "1");
        auto r = run_stipple({"render", model, "--time", "0.7", "--contours", "--width", "320", "--height", "256", "-o", out});
        in_rows.reset();
        ASSERT_EQ(r.exit_code, 0) << r.err;
        std::ifstream in(out, std::ios::binary);
        bytes[rows].assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    ASSERT_GT(bytes[0].size(), 1000u);
    EXPECT_TRUE(bytes[0] == bytes[1]) << "the deformed drawing in rows differs from the drawing in one row";
}

TEST(CliAnimation, ToneDrawsAnAnimatedModelAsRenderDoes) {
    const fs::path dir = test::temp_dir("cli_anim_tone");
    const std::string model = cylinder("cli_anim_tone_model");
    const std::vector<std::string> size{"--width", "320", "--height", "256", "--dmax", "0.05"};
    std::vector<std::string> render{"render", model, "--yaw", "30", "--pitch", "10", "-o", (dir / "c.png").string(),
                                    "--mask", (dir / "m.png").string()};
    render.insert(render.end(), size.begin(), size.end());
    auto drawn = run_stipple(render);
    ASSERT_EQ(drawn.exit_code, 0) << drawn.err;
    const double ink = test::mean_ink_inside(read_png((dir / "c.png").string()), read_png((dir / "m.png").string()));
    std::vector<std::string> tone{"tone", model, "--distances", "1,2", "--views", "30:10"};
    tone.insert(tone.end(), size.begin(), size.end());
    auto table = run_stipple(tone);
    ASSERT_EQ(table.exit_code, 0) << table.err;
    const size_t row = table.out.find("| on  |");
    ASSERT_NE(row, std::string::npos) << table.out;
    double near = 0.0;
    ASSERT_EQ(std::sscanf(table.out.c_str() + table.out.find("|", row + 12) + 1, "%lf", &near), 1) << table.out;
    EXPECT_NEAR(near, ink, 0.002) << table.out;

    std::vector<std::string> parity{"parity", model, "--devices", "0,0", "--yaws", "1", "--paths", "splat"};
    parity.insert(parity.end(), size.begin(), size.end());
    auto same = run_stipple(parity);
    ASSERT_EQ(same.exit_code, 0) << same.err;
    EXPECT_NE(same.out.find("parity holds"), std::string::npos) << same.out;
}

// --stats names the time into the animation the frame shows (it printed the scene clock: 5 s into a 2 s
// loop); --fps spaces a camera_path's frames too (it was refused without --frames).
TEST(CliAnimation, StatsTimeIsTheAnimationsAndFpsSpacesACameraPath) {
    const fs::path dir = test::temp_dir("cli_anim_clock");
    const std::string model = cylinder("cli_anim_clock_model");
    auto looped = run_stipple(sparse({"render", model, "--time", "5", "--stats", "-o", (dir / "t.png").string(), "--width",
                                      "96", "--height", "96"}));
    ASSERT_EQ(looped.exit_code, 0) << looped.err;
    EXPECT_NE(looped.out.find("'Bend' (2.000 s) at 1.000 s"), std::string::npos) << looped.out;

    write_text(dir / "path.json", "{\"objects\": [{\"model\": \"" + model +
                                      "\", \"params\": {\"dmax\": 0.05}}], \"camera_path\": [{\"yaw\": 0}, "
                                      "{\"yaw\": 20}, {\"yaw\": 40}]}");
    auto spaced = run_stipple({"render", (dir / "path.json").string(), "--fps", "10", "-o", (dir / "p%d.png").string(),
                               "--width", "96", "--height", "96", "--stats"});
    ASSERT_EQ(spaced.exit_code, 0) << spaced.err;
    EXPECT_TRUE(fs::exists(dir / "p2.png"));
    EXPECT_NE(spaced.out.find("at 0.200 s (last frame)"), std::string::npos) << "frame 2 at 10 fps\n" << spaced.out;
}

TEST(CliAnimation, InfoListsAnimationsSkinsAndHeadroom) {
    const std::string model = cylinder("cli_anim_info");
    auto r = run_stipple({"info", model});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("animation 0 'Bend': 2.000 s, 1 channel (LINEAR)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("animation 1 'Lift': 1.000 s"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("skin 0 'arm': 2 joints"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("stretch headroom:    polygons reach up to"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("candidates generated for up to 3x"), std::string::npos) << r.out;

    // A skin that no animation moves: said, with the rest pose it is drawn in (info said nothing of it).
    anim::GltfBuilder still = anim::rigs::bending_cylinder();
    still.doc.erase("animations");
    auto s = run_stipple({"info", test::write_rig(still, "cli_anim_info_still", "still"), "--json"});
    ASSERT_EQ(s.exit_code, 0) << s.err;
    const nlohmann::json still_info = nlohmann::json::parse(s.out);
    EXPECT_EQ(still_info["skins"][0]["joints"], 2) << s.out;
    EXPECT_TRUE(still_info["rest_pose_only"].get<bool>()) << s.out;
    EXPECT_TRUE(still_info["animations"].empty()) << s.out;
    // One whose rest pose collapses faces (a joint at scale 0) is drawn as stored, and info says so.
    still.doc["nodes"][2]["scale"] = {0.0, 0.0, 0.0};
    auto collapsed = run_stipple({"info", test::write_rig(still, "cli_anim_info_collapsed", "collapsed")});
    ASSERT_EQ(collapsed.exit_code, 0) << collapsed.err;
    EXPECT_NE(collapsed.out.find("none moves it: drawn as stored (its rest pose collapses faces"), std::string::npos) << collapsed.out;
    // Where it is drawn too, not only in info: one warning line.
    EXPECT_NE(collapsed.err.find(": warning: its rest pose (skins and default morph weights applied) collapses faces"),
              std::string::npos) << collapsed.err;

    // Skin weights that sum to 2 (glTF requires 1) are scaled to 1, and the file is warned about, once.
    anim::GltfBuilder heavy = anim::rigs::bending_cylinder();
    const auto& attributes = heavy.doc["meshes"][0]["primitives"][0]["attributes"];
    const size_t vertices = heavy.doc["accessors"][attributes["POSITION"].get<int>()]["count"].get<size_t>();
    std::vector<float> doubled;
    for (size_t v = 0; v < vertices; ++v) doubled.insert(doubled.end(), {2.0f, 0.0f, 0.0f, 0.0f});
    heavy.doc["meshes"][0]["primitives"][0]["attributes"]["WEIGHTS_0"] = heavy.add_floats(doubled, "VEC4");
    auto h = run_stipple({"info", test::write_rig(heavy, "cli_anim_info_heavy", "heavy")});
    ASSERT_EQ(h.exit_code, 0) << h.err;
    EXPECT_NE(h.err.find("meshes[0].primitives[0].attributes.WEIGHTS_0: " + std::to_string(vertices) + " of " +
                         std::to_string(vertices) + " vertices' weights sum to other than 1 (2 to 2)"),
              std::string::npos) << h.err;
    auto plain = run_stipple({"info", test::write_rig(anim::rigs::bending_cylinder(), "cli_anim_info_heavy", "plain")});
    EXPECT_EQ(plain.err.find("warning"), std::string::npos) << plain.err;

    // A channel of KHR_animation_pointer in a file that uses it without requiring it is skipped (it was refused
    // for its path); the file's other animation still moves it.
    anim::GltfBuilder pointer = anim::rigs::bending_cylinder();
    pointer.doc["extensionsUsed"] = {"KHR_animation_pointer"};
    pointer.doc["animations"][0]["channels"].push_back(
        {{"sampler", 0},
         {"target", {{"path", "pointer"}, {"extensions", {{"KHR_animation_pointer", {{"pointer", "/materials/0/alphaCutoff"}}}}}}}});
    auto p = run_stipple({"info", test::write_rig(pointer, "cli_anim_info_pointer", "pointer")});
    ASSERT_EQ(p.exit_code, 0) << p.err;
    EXPECT_NE(p.out.find("animation 0 'Bend': 2.000 s, 1 channel (LINEAR)"), std::string::npos) << p.out;
    pointer.doc.erase("extensionsUsed");  // a path of an extension the file does not declare: refused
    auto undeclared = run_stipple({"info", test::write_rig(pointer, "cli_anim_info_pointer_undeclared", "pointer")});
    EXPECT_NE(undeclared.exit_code, 0);
    EXPECT_NE(undeclared.err.find("animations[0].channels[1].target.path: expected one of translation, rotation, scale, weights, got 'pointer'"),
              std::string::npos) << undeclared.err;

    const std::string fox = test::shared_model("fox.glb");
    if (fox.empty()) GTEST_SKIP() << "../shared/models/fox.glb not present";
    auto j = run_stipple({"info", fox, "--json"});
    ASSERT_EQ(j.exit_code, 0) << j.err;
    const nlohmann::json info = nlohmann::json::parse(j.out);
    ASSERT_EQ(info["animations"].size(), 3u);
    EXPECT_EQ(info["animations"][2]["name"], "Run");
    EXPECT_EQ(info["skins"][0]["joints"], 24);
    EXPECT_FALSE(info["rest_pose_only"].get<bool>()) << "the fox moves";
    EXPECT_GT(info["stretch"]["max_area_ratio"].get<double>(), 3.0) << "the Run stretches joints beyond the cap";
    EXPECT_GT(info["stretch"]["capped_polygons"].get<int>(), 0);
    const std::string cube = test::shared_model("AnimatedMorphCube.gltf");
    if (cube.empty()) return;
    auto m = run_stipple({"info", cube, "--dmax", "0.05"});
    ASSERT_EQ(m.exit_code, 0) << m.err;
    EXPECT_NE(m.out.find("morph targets of mesh"), std::string::npos) << m.out;
    EXPECT_NE(m.out.find("'thin', 'angle'"), std::string::npos) << m.out;
}

}  // namespace
}  // namespace stipple
