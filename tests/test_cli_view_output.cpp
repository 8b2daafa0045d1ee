// `stipple view`'s output, end to end in a real X11 window (Xvfb, drawn by lavapipe): a script's
// screenshots and exports (the same frame `stipple render` draws), what the X server shows (the frame
// the viewer drew, through shared memory and through the swapchain), the panel laid over the frame, and
// the script's checks. The viewer driven by input: test_cli_view.cpp.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <thread>

#include <tinyxml2.h>

#include "anim/procedural_rigs.hpp"
#include "app/viewer_script.hpp"
#include "core/error.hpp"
#include "io/png_io.hpp"
#include "mesh/ply_writer.hpp"
#include "mesh/primitives.hpp"
#include "support/anim_files.hpp"
#include "support/image_checks.hpp"
#include "support/run_command.hpp"
#include "support/test_paths.hpp"
#include "support/xvfb_viewer.hpp"

// Last: X11's headers define None, Bool, Status...
#include <X11/Xlib.h>
#include <X11/Xutil.h>

namespace stipple {
namespace {

using namespace std::chrono_literals;
using test::count_of;
using test::ink_pixels;
using test::slurp;
using test::ViewerSession;
using test::wait_for;

// Issue 15: the viewer's export writes the view it shows. A script exports the window's view as SVG;
// the file parses, has an A4 page in mm, and carries as many dots as `stipple render -o x.svg` of the
// same view at the window's size, exactly: the viewer and the offline render draw the same frame.
size_t svg_dots(const std::string& path, std::string* width) {
    tinyxml2::XMLDocument doc;
    EXPECT_EQ(doc.LoadFile(path.c_str()), tinyxml2::XML_SUCCESS) << path << " is not XML";
    const tinyxml2::XMLElement* root = doc.RootElement();
    if (!root) return 0;
    *width = root->Attribute("width") ? root->Attribute("width") : "";
    size_t dots = 0;
    for (const tinyxml2::XMLElement* g = root->FirstChildElement("g"); g; g = g->NextSiblingElement("g"))
        for (const tinyxml2::XMLElement* c = g->FirstChildElement("circle"); c; c = c->NextSiblingElement("circle")) ++dots;
    return dots;
}

// A script's screenshot line followed at once by quit: the screenshot is taken and written before the
// window closes (the quit used to close it first, and the file never appeared). A screenshot shows the
// state at its line: two in a row are both written, and a `set` after one does not change it (both
// were taken of a later frame until 2026-12-04: the first of two was never written, and a screenshot
// followed by a larger point size showed the larger dots).
TEST(CliView, ScriptScreenshotThenQuitWritesIt) {
    if (const std::string missing = test::missing_viewer_tools(); !missing.empty()) GTEST_SKIP() << missing;
    auto dir = test::temp_dir("cli-view-screenshot-quit");
    const std::string shot = (dir / "shot.png").string(), first = (dir / "first.png").string(),
                      second = (dir / "second.png").string();
    std::ofstream(dir / "script.txt") << "wait-idle\nscreenshot " + first + "\nscreenshot " + second +
                                             "\nset 0 point_size 4\nscreenshot " + shot + "\nquit\n";
    ViewerSession session(dir);
    ASSERT_TRUE(session.start_x()) << "could not start Xvfb: " << slurp(dir / "xvfb.err");
    session.start_viewer({"--width", "320", "--height", "256", "--no-panel", "--script", (dir / "script.txt").string(),
                          "--cache-dir", (dir / "cache").string()});
    ASSERT_EQ(session.viewer().wait_exit(300s), 0) << session.out() << session.err();
    ASSERT_TRUE(std::filesystem::exists(shot)) << session.out() << session.err();
    ASSERT_TRUE(std::filesystem::exists(first)) << session.out() << session.err();
    ASSERT_TRUE(std::filesystem::exists(second)) << session.out() << session.err();
    const Image image = read_png(shot);
    EXPECT_EQ(image.width, 320);
    EXPECT_GT(ink_pixels(image), 200u) << "the screenshot shows no stipples";
    // Dots of 4 px against 1.5: far more ink after the set than in the two before it, which are alike.
    const size_t before = ink_pixels(read_png(first)), again = ink_pixels(read_png(second)), after = ink_pixels(image);
    std::printf("ink pixels: %zu, %zu before the set, %zu after\n", before, again, after);
    EXPECT_EQ(before, again);
    EXPECT_GT(double(after), 2.0 * double(before));
}

// A script's screenshot that cannot be written is an error (exit code 1), not a message in a run that passes.
TEST(CliView, ScriptScreenshotNotWrittenFailsTheRun) {
    if (const std::string missing = test::missing_viewer_tools(); !missing.empty()) GTEST_SKIP() << missing;
    auto dir = test::temp_dir("cli-view-screenshot-fails");
    std::ofstream(dir / "script.txt") << "wait-idle\nscreenshot /dev/null/shot.png\nquit\n";
    ViewerSession session(dir);
    ASSERT_TRUE(session.start_x()) << "could not start Xvfb: " << slurp(dir / "xvfb.err");
    session.start_viewer({"--width", "320", "--height", "256", "--no-panel", "--script", (dir / "script.txt").string(),
                          "--cache-dir", (dir / "cache").string()});
    EXPECT_EQ(session.viewer().wait_exit(300s), 1) << session.out() << session.err();
    EXPECT_NE(session.err().find("/dev/null/shot.png: cannot write PNG"), std::string::npos) << session.err();
}

// A setting the scene refuses when it is applied (the cpu density path for an animated model) ends the script
// with exit code 1, named at its line: the viewer went on with the old path and the run passed. Also where
// `quit` follows at once (the quit closed the window before a frame applied the setting, exit code 0).
TEST(CliView, ASettingTheSceneRefusesFailsTheScript) {
    if (const std::string missing = test::missing_viewer_tools(); !missing.empty()) GTEST_SKIP() << missing;
    auto dir = test::temp_dir("cli-view-refused-setting");
    const std::string model = test::write_rig(anim::rigs::bending_cylinder(), "cli-view-refused-setting-rig", "cylinder");
    const std::string shot = (dir / "after.png").string();
    for (const std::string& script : {"wait-idle\nset 0 density_path cpu\nwait-idle\nwait 0.3\nscreenshot " + shot + "\nquit\n",
                                      std::string("wait-idle\nset 0 density_path cpu\nquit\n")}) {
        std::ofstream(dir / "script.txt") << script;
        ViewerSession session(dir);
        ASSERT_TRUE(session.start_x()) << "could not start Xvfb: " << slurp(dir / "xvfb.err");
        session.start_viewer({model, "--width", "320", "--height", "256", "--no-panel", "--script", (dir / "script.txt").string(),
                              "--cache-dir", (dir / "cache").string()});
        EXPECT_EQ(session.viewer().wait_exit(300s), 1) << script << session.out() << session.err();
        EXPECT_NE(session.err().find("script.txt:2: "), std::string::npos) << session.err();
        EXPECT_NE(session.err().find("cannot draw an animated model"), std::string::npos) << session.err();
        EXPECT_FALSE(std::filesystem::exists(shot)) << "the script ends at the refusal";
    }
}

// An error of a later action is named at its own line: a missing object was named at the line before and its
// own (doubled prefix), an export that cannot write at the line before.
TEST(CliView, AScriptErrorNamesItsOwnLine) {
    if (const std::string missing = test::missing_viewer_tools(); !missing.empty()) GTEST_SKIP() << missing;
    auto dir = test::temp_dir("cli-view-script-error-line");
    for (const auto& [action, said] : {std::pair<std::string, std::string>{"set 5 seed 2", "script.txt:3: there is no object 5"},
                                       {"export /proc/nope/x.svg", "script.txt:3: "}}) {
        std::ofstream(dir / "script.txt") << "wait 0.1\nwait 0.1\n" + action + "\nquit\n";
        ViewerSession session(dir);
        ASSERT_TRUE(session.start_x()) << "could not start Xvfb: " << slurp(dir / "xvfb.err");
        session.start_viewer({"--width", "160", "--height", "128", "--no-panel", "--script", (dir / "script.txt").string(),
                              "--cache-dir", (dir / "cache").string()});
        EXPECT_EQ(session.viewer().wait_exit(300s), 1) << action << session.out() << session.err();
        EXPECT_NE(session.err().find(said), std::string::npos) << session.err();
        EXPECT_EQ(session.err().find("script.txt:2:"), std::string::npos) << session.err();
    }
}

// The viewer's export draws the scene again, with a list of each object's visible stipples: checked against
// the device as render checks vector output (a crowd render refused exported from the viewer).
TEST(CliView, AnExportTheDeviceCannotHoldIsRefused) {
    if (const std::string missing = test::missing_viewer_tools(); !missing.empty()) GTEST_SKIP() << missing;
    auto dir = test::temp_dir("cli-view-export-refused");
    std::string scene = "{\"objects\": [";
    for (int i = 0; i < 5; ++i)
        scene += std::string(i ? ", " : "") + "{\"model\": \"" + test::source_path("assets/blobby.glb") +
                 "\", \"transform\": {\"translate\": [" + std::to_string(3 * i) + ", 0, 0]}}";
    std::ofstream(dir / "five.json") << scene + "]}";
    const std::string svg = (dir / "five.svg").string();
    std::ofstream(dir / "script.txt") << "wait-idle\nexport " + svg + "\nquit\n";
    ViewerSession session(dir);
    ASSERT_TRUE(session.start_x()) << "could not start Xvfb: " << slurp(dir / "xvfb.err");
    session.start_viewer({(dir / "five.json").string(), "--width", "160", "--height", "128", "--no-panel", "--script",
                          (dir / "script.txt").string(), "--cache-dir", (dir / "cache").string()},
                         {{"STIPPLE_GPU_MEMORY_LIMIT", "60M"}});
    EXPECT_EQ(session.viewer().wait_exit(300s), 1) << session.out() << session.err();
    EXPECT_NE(session.err().find("script.txt:2: " + svg + ": exporting needs about"), std::string::npos) << session.err();
    EXPECT_FALSE(std::filesystem::exists(svg));
}

// A model too big for the device is refused before its stipples are made, as render refuses it: the viewer
// made them first (minutes for a large model at a high density) and refused them after.
TEST(CliView, AModelTooBigForTheDeviceIsRefusedBeforeItsStipplesAreMade) {
    if (const std::string missing = test::missing_viewer_tools(); !missing.empty()) GTEST_SKIP() << missing;
    auto dir = test::temp_dir("cli-view-refused-before-generation");
    const auto cache = dir / "cache";
    std::filesystem::create_directories(cache);
    ViewerSession session(dir);
    ASSERT_TRUE(session.start_x(180)) << "could not start Xvfb: " << slurp(dir / "xvfb.err");
    // A seed no other test uses: the cache cannot hold these stipples from before.
    session.start_viewer({test::source_path("assets/blobby.glb"), "--dmax", "1.5", "--seed", "424244", "--width", "320",
                          "--height", "256", "--no-panel", "--cache-dir", cache.string()},
                         {{"STIPPLE_MAX_STORAGE_BUFFER", "1M"}});
    EXPECT_EQ(session.viewer().wait_exit(120s), 1) << session.out() << session.err();
    EXPECT_NE(session.err().find("this device's largest is 1.0 MiB: lower --dmax or --max-stipples"), std::string::npos)
        << session.err();
    EXPECT_TRUE(std::filesystem::is_empty(cache)) << "the viewer generated the stipples before refusing them";
}

TEST(CliView, ExportsTheViewAsSvg) {
    if (const std::string missing = test::missing_viewer_tools(); !missing.empty()) GTEST_SKIP() << missing;
    auto dir = test::temp_dir("cli-view-export");
    const std::string exported = (dir / "view.svg").string(), rendered = (dir / "render.svg").string();
    const std::string cache = (dir / "cache").string();
    std::ofstream(dir / "script.txt") << "wait-idle\nwait 0.3\nexport " + exported + "\nquit\n";
    ViewerSession session(dir);
    ASSERT_TRUE(session.start_x()) << "could not start Xvfb: " << slurp(dir / "xvfb.err");
    session.start_viewer({"--width", "320", "--height", "256", "--no-panel", "--script", (dir / "script.txt").string(),
                          "--cache-dir", cache});
    ASSERT_EQ(session.viewer().wait_exit(300s), 0) << session.out() << session.err();
    EXPECT_NE(session.out().find("exported: " + exported), std::string::npos) << session.out();
    ASSERT_TRUE(std::filesystem::exists(exported)) << session.out() << session.err();

    const test::CommandResult offline = test::run_stipple({"render", "--width", "320", "--height", "256", "-o", rendered,
                                                           "--cache-dir", cache});
    ASSERT_EQ(offline.exit_code, 0) << offline.err;
    std::string width_view, width_render;
    const size_t view_dots = svg_dots(exported, &width_view), render_dots = svg_dots(rendered, &width_render);
    std::printf("viewer export: %zu dots; render -o x.svg: %zu dots\n", view_dots, render_dots);
    EXPECT_EQ(width_view, width_render) << "the viewer laid its page out as render does";
    EXPECT_TRUE(width_view == "210mm" || width_view == "297mm") << width_view << ": A4, the CLI's default page";
    EXPECT_GT(view_dots, 500u);
    EXPECT_EQ(view_dots, render_dots) << "the viewer exported another frame than render draws";
}

// The pixels an X11 window shows now (what the server holds, not what the viewer drew), as RGBA, or an
// empty image where the window cannot be read.
Image grab_window(const std::string& display, const std::string& window, int width, int height) {
    Image grabbed;
    Display* x = XOpenDisplay(display.c_str());
    if (!x) return grabbed;
    XImage* image = XGetImage(x, ::Window(std::stoul(window)), 0, 0, unsigned(width), unsigned(height), AllPlanes, ZPixmap);
    if (image) {
        grabbed.width = width, grabbed.height = height, grabbed.channels = 4;
        grabbed.pixels.resize(size_t(width) * height * 4);
        for (int y = 0; y < height; ++y)
            for (int x_ = 0; x_ < width; ++x_) {
                const unsigned long p = XGetPixel(image, x_, y);  // 24-bit true colour: 0xRRGGBB
                uint8_t* rgba = &grabbed.pixels[4 * (size_t(y) * width + x_)];
                rgba[0] = uint8_t(p >> 16), rgba[1] = uint8_t(p >> 8), rgba[2] = uint8_t(p), rgba[3] = 255;
            }
        XDestroyImage(image);
    }
    XCloseDisplay(x);
    return grabbed;
}

// Frames reach the window both ways: through X11 shared memory (the default on lavapipe, where Xvfb has
// no DRI3 and the swapchain would write each frame into the X socket) and through Vulkan's swapchain. What
// the X server shows is the frame the viewer drew (its screenshot), pixel for pixel: coloured paper and
// ink (channels in the wrong order would show), and a width whose rows a linear image pads (the shared
// images then have no words for the splat, and their rows are copied one by one).
TEST(CliView, TheWindowShowsTheFrameThroughSharedMemoryAndTheSwapchain) {
    if (const std::string missing = test::missing_viewer_tools(); !missing.empty()) GTEST_SKIP() << missing;
    auto dir = test::temp_dir("cli-view-present");
    const std::string cache = (dir / "cache").string();
    write_ply_binary((dir / "sphere.ply").string(), make_uv_sphere(4000));
    std::ofstream(dir / "scene.json") << R"({"objects": [{"model": "sphere.ply"}], "paper": [1, 0.85, 0.6],
                                             "ink": [0.1, 0.2, 0.7]})";
    constexpr int kWidth = 333, kHeight = 256;
    for (const std::string present : {"auto", "swapchain"}) {
        SCOPED_TRACE("--present " + present);
        const std::string shot = (dir / ("shot-" + present + ".png")).string();
        std::ofstream(dir / "script.txt") << "wait-idle\nscreenshot " + shot + "\nwait 5\nquit\n";
        ViewerSession session(dir);
        ASSERT_TRUE(session.start_x(140)) << "could not start Xvfb: " << slurp(dir / "xvfb.err");
        session.start_viewer({(dir / "scene.json").string(), "--width", std::to_string(kWidth), "--height",
                              std::to_string(kHeight), "--no-panel", "--present", present, "--verbose", "--script",
                              (dir / "script.txt").string(), "--cache-dir", cache});
        ASSERT_TRUE(session.find_window()) << session.out() << session.err();
        ASSERT_TRUE(wait_for([&] { return session.out().find("screenshot: " + shot) != std::string::npos; }, 120s))
            << session.out() << session.err();
        std::this_thread::sleep_for(1s);  // frames keep coming: the window shows one drawn after the screenshot
        const Image shown = grab_window(session.display(), session.window(), kWidth, kHeight);
        ASSERT_EQ(session.viewer().wait_exit(60s), 0) << session.out() << session.err();
        // auto takes shared memory on lavapipe (the tests' device) under Xvfb; swapchain does not.
        EXPECT_EQ(session.out().find("X11 shared memory") != std::string::npos, present == "auto") << session.out();
        // --verbose says which, and why.
        EXPECT_NE(session.out().find(present == "auto" ? "presenting through X11 shared memory: a CPU device"
                                                       : "presenting through the swapchain: --present swapchain"),
                  std::string::npos)
            << session.out();
        ASSERT_EQ(shown.width, kWidth) << "could not read the window back";
        const Image drawn = read_png(shot);
        ASSERT_EQ(drawn.width, kWidth);
        ASSERT_GE(drawn.channels, 3);
        EXPECT_EQ(int(drawn.pixels[0]), 255) << "the paper's red";
        EXPECT_NEAR(int(drawn.pixels[2]), 153, 1) << "the paper's blue";
        size_t differing = 0;
        for (size_t p = 0; p < size_t(kWidth * kHeight); ++p)
            for (int c = 0; c < 3; ++c)
                differing += std::abs(int(shown.pixels[4 * p + c]) - int(drawn.pixels[drawn.channels * p + c])) > 2;
        std::printf("--present %s: %zu ink pixels shown, %zu drawn, %zu channel values differ\n", present.c_str(),
                    ink_pixels(shown), ink_pixels(drawn), differing);
        EXPECT_GT(ink_pixels(shown), 200u) << "the window shows no stipples";
        EXPECT_LE(double(differing), 0.001 * 3 * kWidth * kHeight) << "the window shows another image";
    }
}

// On lavapipe under Xvfb the panel is drawn into a layer of its own only when it changes, and laid over
// each frame as the frame is copied to the X server; a window that changes every frame (the timeline
// while an animation plays) is drawn into each frame instead (app/panel_layer.hpp). The window shows what
// drawing it all straight into the frame shows (STIPPLE_PANEL_LAYER=off), but for the figures that change
// from run to run (fps, GPU times, the scene clock), and most frames reuse the layer.
TEST(CliView, ThePanelLaidOverTheFrameLooksAsIfDrawnIntoIt) {
    if (const std::string missing = test::missing_viewer_tools(); !missing.empty()) GTEST_SKIP() << missing;
    auto dir = test::temp_dir("cli-view-panel-layer");
    const std::string cache = (dir / "cache").string();
    // Animated at speed 0: the timeline's clock runs (its window changes every frame), the drawing stays.
    const std::string model = test::write_rig(anim::rigs::bending_cylinder(), "cli-view-panel-layer-model", "cylinder");
    std::ofstream(dir / "scene.json") << R"({"objects": [{"model": ")" << model << R"(", "params": {"dmax": 0.05},
                                             "animation": {"speed": 0, "start": 0.4}}],
                                             "paper": [1, 0.85, 0.6], "ink": [0.1, 0.2, 0.7]})";
    // Rows a linear image may pad (the layer keeps its own pitch), and wide enough for the panel to open (1000).
    constexpr int kWidth = 1010, kHeight = 600;
    Image shown[2];
    for (int layer = 1; layer >= 0; --layer) {
        SCOPED_TRACE(layer ? "the panel's layer" : "the panel drawn into each frame");
        const std::string shot = (dir / ("shot-" + std::to_string(layer) + ".png")).string();
        std::ofstream(dir / "script.txt") << "wait-idle\nscreenshot " + shot + "\nwait 4\nquit\n";
        ViewerSession session(dir);
        ASSERT_TRUE(session.start_x(160)) << "could not start Xvfb: " << slurp(dir / "xvfb.err");
        session.start_viewer({(dir / "scene.json").string(), "--width", std::to_string(kWidth),
                              "--height", std::to_string(kHeight), "--verbose", "--script",
                              (dir / "script.txt").string(), "--cache-dir", cache},
                             {{"STIPPLE_PANEL_LAYER", layer ? "auto" : "off"}});
        ASSERT_TRUE(session.find_window()) << session.out() << session.err();
        ASSERT_TRUE(wait_for([&] { return session.out().find("screenshot: " + shot) != std::string::npos; }, 120s))
            << session.out() << session.err();
        std::this_thread::sleep_for(1500ms);
        shown[layer] = grab_window(session.display(), session.window(), kWidth, kHeight);
        ASSERT_EQ(session.viewer().wait_exit(60s), 0) << session.out() << session.err();
        ASSERT_EQ(shown[layer].width, kWidth) << "could not read the window back";
        ASSERT_NE(session.out().find("X11 shared memory"), std::string::npos) << session.out();
        const std::string out = session.out();
        const size_t at = out.find("the panel's layer drawn in ");
        if (!layer) {
            EXPECT_EQ(at, std::string::npos) << out;
        } else {
            ASSERT_NE(at, std::string::npos) << out;
            unsigned long long draws = 0, direct = 0;
            long long frames = 0;
            ASSERT_EQ(std::sscanf(out.c_str() + at,
                                  "the panel's layer drawn in %llu of %lld frames (the others laid the layer drawn "
                                  "before over the frame); windows that change every frame drawn into %llu frames",
                                  &draws, &frames, &direct),
                      3)
                << out;
            std::printf("the panel's layer drawn in %llu of %lld frames, the timeline into %llu\n", draws, frames,
                        direct);
            EXPECT_GT(draws, 0u);
            EXPECT_LT(draws, (unsigned long long)frames) << "every frame drew the panel again";
            EXPECT_GT(direct, (unsigned long long)frames / 2) << "the timeline went into the layer";
        }
        // The screenshot is the frame without the panel: the window shows the panel over it.
        const Image frame = read_png(shot);
        ASSERT_EQ(frame.width, kWidth);
        size_t under_panel = 0;
        for (size_t p = 0; p < size_t(kWidth * kHeight); ++p)
            for (int c = 0; c < 3; ++c)
                if (std::abs(int(shown[layer].pixels[4 * p + c]) - int(frame.pixels[frame.channels * p + c])) > 8) {
                    ++under_panel;
                    break;
                }
        std::printf("%s: %zu of %d pixels differ from the frame without it\n", layer ? "layer" : "drawn into the frame",
                    under_panel, kWidth * kHeight);
        EXPECT_GT(double(under_panel), 0.15 * kWidth * kHeight) << "no panel in the window";
    }
    size_t differing = 0;
    for (size_t p = 0; p < size_t(kWidth * kHeight); ++p)
        for (int c = 0; c < 3; ++c)
            if (std::abs(int(shown[1].pixels[4 * p + c]) - int(shown[0].pixels[4 * p + c])) > 8) {
                ++differing;
                break;
            }
    std::printf("the layer against the panel drawn into the frame: %zu of %d pixels differ\n", differing,
                kWidth * kHeight);
    EXPECT_LE(double(differing), 0.01 * kWidth * kHeight) << "the layer shows another panel";
}

// A script's export line names a vector file; anything else is refused before the window opens, in
// one line naming the script and the line.
TEST(CliView, ScriptExportNeedsAVectorPath) {
    auto dir = test::temp_dir("cli-view-export-script");
    const std::string script = (dir / "script.txt").string();
    std::ofstream(script) << "# export the view\nexport view.png\n";
    try {
        app::read_viewer_script(script);
        ADD_FAILURE() << "export view.png was accepted";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(script + ":2: export needs a .svg, .pdf or .csv path"), std::string::npos) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
    std::ofstream(script) << "export view.svg\nexport view.PDF\nexport dots.csv\n";
    EXPECT_EQ(app::read_viewer_script(script).size(), 3u);
    // A screenshot is a PNG, and the script a file (a folder read as an empty script: the window never closed).
    std::ofstream(script) << "screenshot shot.jpg\n";
    for (const auto& [path, phrase] : {std::pair<std::string, std::string>{script, ":1: screenshot needs a .png path"},
                                       {dir.string(), "is a directory, not a script"}}) {
        try {
            app::read_viewer_script(path);
            ADD_FAILURE() << path << " was accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos) << e.what();
        }
    }
}

// A switch is set with true or false, as in a scene file; another word is refused with what was written.
TEST(CliView, ScriptSwitchesTakeTrueOrFalse) {
    auto dir = test::temp_dir("cli-view-switch-script");
    const std::string script = (dir / "script.txt").string();
    std::ofstream(script) << "set 0 contours true\nset 0 toon false\n";
    const std::vector<app::ScriptAction> actions = app::read_viewer_script(script);
    ASSERT_EQ(actions.size(), 2u);
    EXPECT_EQ(actions[0].value, 1.0);
    EXPECT_EQ(actions[1].value, 0.0);
    std::ofstream(script) << "set 0 contours 1\n";
    try {
        app::read_viewer_script(script);
        ADD_FAILURE() << "contours 1 was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(script + ":1: contours: expected true or false, got '1'"), std::string::npos)
            << e.what();
    }
    // A value is named by the key the script wrote, as a switch is (the command line's "--dmax" until 2026-12-07).
    for (const auto& [line, message] : std::vector<std::pair<std::string, std::string>>{
             {"set 0 dmax 99\n", ":1: dmax = 99 is out of range"}, {"set 0 shading_exponent inf\n", ":1: shading_exponent: 'inf'"}}) {
        std::ofstream(script) << line;
        try {
            app::read_viewer_script(script);
            ADD_FAILURE() << line << " was accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(script + message), std::string::npos) << e.what();
        }
    }
}

// What a script cannot mean is refused in one short line: an object number no scene has (1e300 became object
// 0, silently), a script without an action (the window stayed open for ever), and a long line is quoted in
// part (a 20 MB line made a 20 MB message).
TEST(CliView, ScriptLinesThatCannotMeanAnythingAreRefusedShortly) {
    auto dir = test::temp_dir("cli-view-bad-script");
    const std::string script = (dir / "script.txt").string();
    for (const auto& [text, phrase] : std::vector<std::pair<std::string, std::string>>{
             {"set 1e300 dmax 0.3\n", ":1: set needs an object number, got '1e300'"},
             {"set 18446744073709551616 dmax 0.3\n", ":1: set needs an object number, got '18446744073709551616'"},
             {"# only a comment\n\n", ": holds no action (wait S, wait-idle"},
             {"", ": holds no action"},
             {"jump " + std::string(100000, 'x') + "\n", ":1: unknown or incomplete line 'jump xxx"}}) {
        std::ofstream(script) << text;
        try {
            app::read_viewer_script(script);
            ADD_FAILURE() << text.substr(0, 40) << " was accepted";
        } catch (const Error& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find(script + phrase), std::string::npos) << what.substr(0, 300);
            EXPECT_LT(what.size(), 400u);
            EXPECT_EQ(what.find('\n'), std::string::npos);
        }
    }
}

}  // namespace
}  // namespace stipple
