// `stipple view` end to end, as a person would use it: the default scene in a real X11 window (Xvfb,
// drawn by lavapipe) driven by real input events from xdotool. A drag orbits, the wheel zooms, S saves
// screenshots, Ctrl+S saves the scene, a drag on the panel leaves the camera alone, H and V hide the
// panel and switch vsync; the window survives 20 rapid resizes and a minimize/restore;
// Q quits with exit code 0 and without a single Vulkan validation message.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <sstream>
#include <thread>

#include "anim/procedural_rigs.hpp"
#include <tinyxml2.h>

#include "app/viewer_script.hpp"
#include "core/error.hpp"
#include "io/png_io.hpp"
#include "mesh/ply_writer.hpp"
#include "mesh/primitives.hpp"
#include "support/run_command.hpp"
#include "scene/scene_json.hpp"
#include "support/anim_files.hpp"
#include "support/test_paths.hpp"

// Last: X11's headers define None, Bool, Status...
#include <X11/Xlib.h>
#include <X11/Xutil.h>

namespace stipple {
namespace {

using namespace std::chrono_literals;

bool have_tool(const std::string& name) { return std::system(("command -v " + name + " >/dev/null 2>&1").c_str()) == 0; }

std::string slurp(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// A child process with its own environment additions and output files, killed if the test ends early.
class Child {
public:
    Child(const std::vector<std::string>& argv, const std::vector<std::pair<std::string, std::string>>& env,
          const std::filesystem::path& out, const std::filesystem::path& err) {
        pid_ = fork();
        if (pid_ == 0) {
            for (const auto& [k, v] : env) setenv(k.c_str(), v.c_str(), 1);
            int o = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            int e = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            int n = open("/dev/null", O_RDONLY);
            dup2(n, 0), dup2(o, 1), dup2(e, 2);
            std::vector<char*> args;
            for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
            args.push_back(nullptr);
            execvp(args[0], args.data());
            _exit(127);
        }
    }
    ~Child() {
        if (!running()) return;
        // SIGTERM first, so that Xvfb removes its socket and lock file; SIGKILL if it lingers.
        kill(pid_, SIGTERM);
        for (int i = 0; i < 40 && running(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
        if (running()) {
            kill(pid_, SIGKILL);
            waitpid(pid_, nullptr, 0);
        }
    }
    bool running() {
        if (pid_ <= 0 || exited_) return false;
        int status = 0;
        if (waitpid(pid_, &status, WNOHANG) == pid_) {
            exited_ = true;
            status_ = status;
        }
        return !exited_;
    }
    // Exit code after waiting up to `timeout`; -1 if it is still running (then it is killed).
    int wait_exit(std::chrono::seconds timeout) {
        auto end = std::chrono::steady_clock::now() + timeout;
        while (running() && std::chrono::steady_clock::now() < end) std::this_thread::sleep_for(50ms);
        if (running()) return -1;
        return WIFEXITED(status_) ? WEXITSTATUS(status_) : 128 + WTERMSIG(status_);
    }
    void terminate() {
        if (running()) kill(pid_, SIGTERM);
    }

private:
    pid_t pid_ = -1;
    bool exited_ = false;
    int status_ = 0;
};

bool wait_for(const std::function<bool()>& condition, std::chrono::milliseconds timeout) {
    auto end = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < end) {
        if (condition()) return true;
        std::this_thread::sleep_for(100ms);
    }
    return condition();
}

size_t count_of(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

size_t ink_pixels(const Image& image) {
    size_t n = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) n += luminance(image, x, y) < 128;
    return n;
}

class ViewerSession {
public:
    explicit ViewerSession(const std::filesystem::path& dir) : dir_(dir) {}

    // An unused display number: no socket and no lock file. Tests that ctest may run at the same time
    // start from different numbers, so they never race for one.
    bool start_x(int first_display = 87) {
        for (int n = first_display; n < first_display + 100; ++n) {
            if (std::filesystem::exists("/tmp/.X11-unix/X" + std::to_string(n)) ||
                std::filesystem::exists("/tmp/.X" + std::to_string(n) + "-lock"))
                continue;
            display_ = ":" + std::to_string(n);
            xvfb_ = std::make_unique<Child>(
                // -noreset: otherwise the server resets when its last client (the readiness probe below)
                // disconnects, and a viewer connecting during the reset fails to open the display.
                std::vector<std::string>{"Xvfb", display_, "-screen", "0", "1280x1024x24", "-nolisten", "tcp",
                                         "-noreset"},
                std::vector<std::pair<std::string, std::string>>{}, dir_ / "xvfb.out", dir_ / "xvfb.err");
            if (wait_for([&] { return xdotool("getmouselocation").find("x:") != std::string::npos; }, 10s)) return true;
            xvfb_.reset();
        }
        return false;
    }

    void start_viewer(const std::vector<std::string>& args,
                      const std::vector<std::pair<std::string, std::string>>& extra_env = {}) {
        std::vector<std::pair<std::string, std::string>> env{{"DISPLAY", display_}, {"STIPPLE_VALIDATION", "1"}};
        env.insert(env.end(), extra_env.begin(), extra_env.end());
        if (!std::getenv("XDG_RUNTIME_DIR")) {
            std::filesystem::create_directories(dir_ / "xdg");
            chmod((dir_ / "xdg").c_str(), 0700);
            env.push_back({"XDG_RUNTIME_DIR", (dir_ / "xdg").string()});
        }
        std::vector<std::string> argv{STIPPLE_EXECUTABLE, "view"};
        argv.insert(argv.end(), args.begin(), args.end());
        viewer_ = std::make_unique<Child>(argv, env, dir_ / "view.out", dir_ / "view.err");
    }

    std::string xdotool(const std::string& args) {
        std::string cmd = "DISPLAY=" + display_ + " xdotool " + args + " 2>/dev/null";
        std::string out;
        if (FILE* p = popen(cmd.c_str(), "r")) {
            char buffer[256];
            while (fgets(buffer, sizeof(buffer), p)) out += buffer;
            pclose(p);
        }
        return out;
    }

    std::string out() const { return slurp(dir_ / "view.out"); }
    std::string err() const { return slurp(dir_ / "view.err"); }
    Child& viewer() { return *viewer_; }

    // Keys reach the focused window; without a window manager the test gives the focus itself.
    void focus() {
        xdotool("windowfocus " + window_ + " mousemove --window " + window_ + " 900 500");
        std::this_thread::sleep_for(200ms);
    }

    bool find_window() {
        return wait_for(
            [&] {
                std::string found = xdotool("search --name '^stipple - '");
                window_ = found.substr(0, found.find('\n'));
                return !window_.empty() || !viewer_->running();
            },
            40s) &&
               !window_.empty();
    }
    const std::string& window() const { return window_; }
    const std::string& display() const { return display_; }

    // Presses S and waits for the viewer to report the PNG it wrote.
    std::string screenshot() {
        size_t before = count_of(out(), "screenshot: ");
        xdotool("key s");
        if (!wait_for([&] { return count_of(out(), "screenshot: ") > before; }, 20s)) return "";
        std::string text = out();
        size_t at = text.rfind("screenshot: ") + 12;
        return text.substr(at, text.find('\n', at) - at);
    }

private:
    std::filesystem::path dir_;
    std::string display_;
    std::string window_;
    std::unique_ptr<Child> xvfb_;   // declared first: destroyed last
    std::unique_ptr<Child> viewer_;
};

TEST(CliView, DrivenByRealInputUnderXvfb) {
    for (const char* tool : {"Xvfb", "xdotool"})
        if (!have_tool(tool)) GTEST_SKIP() << tool << " is not installed (apt-get install xvfb xdotool); viewer not tested";
    auto dir = test::temp_dir("cli-view");
    ViewerSession session(dir);
    ASSERT_TRUE(session.start_x()) << "could not start Xvfb: " << slurp(dir / "xvfb.err");
    session.start_viewer({"--screenshot-dir", (dir / "shots").string(), "--save-scene", (dir / "saved.json").string()});
    ASSERT_TRUE(session.find_window()) << "no window appeared\n" << session.err();
    session.focus();

    // The default scene, drawn: a screenshot at window resolution with stipples on paper.
    std::string shot1 = session.screenshot();
    ASSERT_FALSE(shot1.empty()) << "no screenshot\n" << session.out() << session.err();
    Image before = read_png(shot1);
    EXPECT_EQ(before.width, 1280);
    EXPECT_EQ(before.height, 1024);
    size_t ink_before = ink_pixels(before);
    EXPECT_GT(ink_before, 20000u) << "the screenshot shows no stipples";
    EXPECT_LT(ink_before, size_t(before.width) * before.height / 2) << "mostly ink: not a stipple drawing";

    // A left drag orbits: another view of the object.
    std::string drag = "mousedown 1";
    for (int i = 0; i < 8; ++i) drag += " sleep 0.05 mousemove_relative -- 25 6";
    session.xdotool(drag + " sleep 0.1 mouseup 1");
    std::string shot2 = session.screenshot();
    ASSERT_FALSE(shot2.empty());
    Image orbited = read_png(shot2);
    EXPECT_GT(fraction_differing(before, orbited, 8), 0.03) << "the drag did not change the view";

    // The wheel zooms in: the object grows on screen, and with it the inked area (tone stays, §2.3).
    session.xdotool("click --repeat 3 --delay 80 4");
    std::string shot3 = session.screenshot();
    ASSERT_FALSE(shot3.empty());
    Image zoomed = read_png(shot3);
    EXPECT_GT(fraction_differing(orbited, zoomed, 8), 0.03) << "the wheel did not change the view";
    EXPECT_GT(ink_pixels(zoomed), ink_pixels(orbited) * 11 / 10) << "zooming in should enlarge the object";

    // Ctrl+S: the current state as a scene file that loads again.
    session.xdotool("key ctrl+s");
    ASSERT_TRUE(wait_for([&] { return session.out().find("scene saved: ") != std::string::npos; }, 10s)) << session.err();
    Scene saved = load_scene((dir / "saved.json").string());
    ASSERT_EQ(saved.objects.size(), 1u);
    EXPECT_TRUE(saved.camera.world_distance.has_value());
    EXPECT_NE(saved.camera.yaw_deg, 0.0f) << "the orbit should be in the saved camera";

    // A drag that starts on the panel's title bar moves the panel, not the camera (input ImGui wants is
    // not the viewer's): the drawing stays exactly as it was.
    session.xdotool("mousemove --window " + session.window() +
                    " 150 18 sleep 0.7 mousedown 1 sleep 0.2 mousemove_relative -- 60 0 sleep 0.2 mousemove_relative -- "
                    "90 30 sleep 0.2 mouseup 1 sleep 0.2 mousemove --window " +
                    session.window() + " 900 500");
    std::string shot_panel = session.screenshot();
    ASSERT_FALSE(shot_panel.empty());
    EXPECT_EQ(fraction_differing(zoomed, read_png(shot_panel), 0), 0.0) << "a drag on the panel moved the camera";

    // H hides the panel, V switches vsync off (a new swapchain in another present mode).
    session.xdotool("key h sleep 0.3 key v");

    // 20 rapid resizes, then a minimize and restore (what a window manager does: iconify, unmap, map).
    std::string resizes;
    for (int i = 0; i < 20; ++i)
        resizes += " windowsize " + session.window() + " " + std::to_string(500 + 37 * i) + " " +
                   std::to_string(400 + 23 * (i % 7)) + " sleep 0.02";
    session.xdotool(resizes + " windowsize " + session.window() + " 1000 760");
    session.xdotool("windowminimize " + session.window() + " windowunmap " + session.window());
    EXPECT_TRUE(wait_for([&] { return session.out().find("drawing paused") != std::string::npos; }, 10s))
        << "the viewer did not notice it was hidden\n" << session.out();
    std::this_thread::sleep_for(500ms);
    session.xdotool("windowmap " + session.window());
    EXPECT_TRUE(wait_for([&] { return session.out().find("drawing resumed") != std::string::npos; }, 10s))
        << session.out();
    ASSERT_TRUE(session.viewer().running()) << "the viewer died\n" << session.err();
    session.focus();

    // Still drawing, at the new window size.
    std::string shot4 = session.screenshot();
    ASSERT_FALSE(shot4.empty()) << session.out() << session.err();
    Image resized = read_png(shot4);
    EXPECT_EQ(resized.width, 1000);
    EXPECT_EQ(resized.height, 760);
    EXPECT_GT(ink_pixels(resized), 10000u);

    // Q quits cleanly.
    session.xdotool("key q");
    int code = session.viewer().wait_exit(30s);
    EXPECT_EQ(code, 0) << session.err();
    std::string err = session.err();
    EXPECT_EQ(err.find("validation"), std::string::npos) << err;
    EXPECT_EQ(err.find("error"), std::string::npos) << err;
}

// Issue 14: a D_max change on the 871k-triangle model makes new stipples in the background while the
// window keeps drawing the old ones; the frames keep coming (no gap over 250 ms), and the final image is
// the one an offline render with the new parameters gives.
TEST(CliView, RegeneratesInTheBackgroundWithoutFreezing) {
    for (const char* tool : {"Xvfb", "xdotool"})
        if (!have_tool(tool)) GTEST_SKIP() << tool << " is not installed (apt-get install xvfb xdotool); viewer not tested";
    auto dir = test::temp_dir("cli-view-background");
    const std::string model = (dir / "sphere-871k.ply").string();
    write_ply_binary(model, make_uv_sphere(871'414));  // the paper's largest row, the dragon's polygon count
    std::ofstream(dir / "script.txt") << "wait 2\nset 0 dmax 0.5\nwait-idle\nwait 0.5\nscreenshot " +
                                             (dir / "final.png").string() + "\nwait 0.5\nquit\n";
    const std::string cache = (dir / "cache").string();
    ViewerSession session(dir);
    ASSERT_TRUE(session.start_x()) << "could not start Xvfb: " << slurp(dir / "xvfb.err");
    session.start_viewer({model, "--width", "640", "--height", "512", "--no-panel", "--script",
                          (dir / "script.txt").string(), "--frame-log", (dir / "frames.log").string(), "--cache-dir",
                          cache});
    const int code = session.viewer().wait_exit(300s);
    ASSERT_EQ(code, 0) << session.out() << session.err();
    EXPECT_NE(session.out().find("new stipples: "), std::string::npos) << session.out();

    // Each line: milliseconds since start, 1 while the background worker had work. Had the stipples been
    // made on the UI thread, no frame would be presented while the work ran and one gap would span all of
    // it. The figures are relative to the work's own duration, so a loaded machine (CI's two cores, tests
    // run side by side) slows both alike instead of failing the test.
    std::vector<double> times;
    std::vector<int> busy;
    std::ifstream log(dir / "frames.log");
    for (double t; log >> t;) {
        int b = 0;
        log >> b;
        times.push_back(t);
        busy.push_back(b);
    }
    ASSERT_GT(times.size(), 10u);
    double work_start = -1.0, work_end = -1.0, worst = 0.0, worst_at = 0.0;
    size_t frames_during_work = 0;
    for (size_t i = 0; i < times.size(); ++i) {
        if (!busy[i]) continue;
        if (work_start < 0.0) work_start = i > 0 ? times[i - 1] : times[i];
        work_end = times[i];
        ++frames_during_work;
    }
    ASSERT_GE(work_start, 0.0) << "no frame was presented while the new stipples were made";
    for (size_t i = 1; i < times.size(); ++i) {
        if (times[i - 1] < work_start) continue;  // shader compilation and the first upload come before
        if (times[i] - times[i - 1] > worst) worst = times[i] - times[i - 1], worst_at = times[i] - times[0];
    }
    const double work_ms = work_end - work_start;
    std::printf("%zu frames in %.1f s; background work %.0f ms with %zu frames; longest gap from then on %.0f ms "
                "(at %.1f s)\n",
                times.size(), (times.back() - times.front()) / 1000.0, work_ms, frames_during_work, worst,
                worst_at / 1000.0);
    EXPECT_GE(frames_during_work, 10u) << "the window stopped drawing while new stipples were made";
    EXPECT_LE(worst, 0.25 * work_ms) << "one frame took a quarter of the background work's time: the window froze";

    const test::CommandResult offline = test::run_stipple({"render", model, "--dmax", "0.5", "--width", "640", "--height",
                                                           "512", "-o", (dir / "offline.png").string(), "--cache-dir", cache});
    ASSERT_EQ(offline.exit_code, 0) << offline.err;
    const Image shown = read_png((dir / "final.png").string()), rendered = read_png((dir / "offline.png").string());
    EXPECT_EQ(fraction_differing(shown, rendered, 0), 0.0) << "the viewer shows another image than the offline render";
}

TEST(CliView, AnimationPlaysAndPauses) {
    // An animated model plays in the viewer (its timeline's clock follows wall time), Space pauses it
    // (the drawing then stays exactly still) and resumes it.
    for (const char* tool : {"Xvfb", "xdotool"})
        if (!have_tool(tool)) GTEST_SKIP() << tool << " is not installed (apt-get install xvfb xdotool); viewer not tested";
    auto dir = test::temp_dir("cli-view-animation");
    const std::string model = test::write_rig(anim::rigs::bending_cylinder(), "cli-view-animation-model", "cylinder");
    ViewerSession session(dir);
    ASSERT_TRUE(session.start_x(300)) << "could not start Xvfb: " << slurp(dir / "xvfb.err");
    session.start_viewer({model, "--dmax", "0.05", "--width", "480", "--height", "400", "--screenshot-dir",
                          (dir / "shots").string()});
    ASSERT_TRUE(session.find_window()) << "no window appeared\n" << session.err();
    session.focus();

    auto shot = [&] {
        std::string path = session.screenshot();
        EXPECT_FALSE(path.empty()) << session.out() << session.err();
        return path.empty() ? Image{} : read_png(path);
    };
    // Moving: some later screenshot differs from a reference one. Several tries, 400 ms apart: near
    // the ends of the bend the pose changes little over one interval (0.13% of pixels was seen on a
    // loaded machine), while a stopped drawing never changes at all.
    auto moves_after = [&](const Image& reference) {
        double most = 0.0;
        for (int attempt = 0; attempt < 5 && most <= 0.002; ++attempt) {
            std::this_thread::sleep_for(400ms);
            most = std::max(most, fraction_differing(reference, shot(), 8));
        }
        return most;
    };
    const Image playing_a = shot();
    EXPECT_GT(moves_after(playing_a), 0.002) << "the animation did not move";

    session.xdotool("key space");
    std::this_thread::sleep_for(300ms);
    const Image paused_a = shot();
    std::this_thread::sleep_for(400ms);
    const Image paused_b = shot();
    EXPECT_EQ(fraction_differing(paused_a, paused_b, 0), 0.0) << "paused, the drawing must not change";

    session.xdotool("key space");
    EXPECT_GT(moves_after(paused_b), 0.002) << "Space did not resume the animation";

    session.xdotool("key q");
    EXPECT_EQ(session.viewer().wait_exit(30s), 0) << session.err();
    const std::string err = session.err();
    EXPECT_EQ(err.find("validation"), std::string::npos) << err;
    EXPECT_EQ(err.find("error"), std::string::npos) << err;
}

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
// window closes (the quit used to close it first, and the file never appeared).
TEST(CliView, ScriptScreenshotThenQuitWritesIt) {
    for (const char* tool : {"Xvfb", "xdotool"})
        if (!have_tool(tool)) GTEST_SKIP() << tool << " is not installed (apt-get install xvfb xdotool); viewer not tested";
    auto dir = test::temp_dir("cli-view-screenshot-quit");
    const std::string shot = (dir / "shot.png").string();
    std::ofstream(dir / "script.txt") << "wait-idle\nscreenshot " + shot + "\nquit\n";
    ViewerSession session(dir);
    ASSERT_TRUE(session.start_x()) << "could not start Xvfb: " << slurp(dir / "xvfb.err");
    session.start_viewer({"--width", "320", "--height", "256", "--no-panel", "--script", (dir / "script.txt").string(),
                          "--cache-dir", (dir / "cache").string()});
    ASSERT_EQ(session.viewer().wait_exit(300s), 0) << session.out() << session.err();
    ASSERT_TRUE(std::filesystem::exists(shot)) << session.out() << session.err();
    const Image image = read_png(shot);
    EXPECT_EQ(image.width, 320);
    EXPECT_GT(ink_pixels(image), 200u) << "the screenshot shows no stipples";
}

// A script's screenshot that cannot be written is an error (exit code 1), not a message in a run that passes.
TEST(CliView, ScriptScreenshotNotWrittenFailsTheRun) {
    for (const char* tool : {"Xvfb", "xdotool"})
        if (!have_tool(tool)) GTEST_SKIP() << tool << " is not installed (apt-get install xvfb xdotool); viewer not tested";
    auto dir = test::temp_dir("cli-view-screenshot-fails");
    std::ofstream(dir / "script.txt") << "wait-idle\nscreenshot /dev/null/shot.png\nquit\n";
    ViewerSession session(dir);
    ASSERT_TRUE(session.start_x()) << "could not start Xvfb: " << slurp(dir / "xvfb.err");
    session.start_viewer({"--width", "320", "--height", "256", "--no-panel", "--script", (dir / "script.txt").string(),
                          "--cache-dir", (dir / "cache").string()});
    EXPECT_EQ(session.viewer().wait_exit(300s), 1) << session.out() << session.err();
    EXPECT_NE(session.err().find("/dev/null/shot.png: cannot write PNG"), std::string::npos) << session.err();
}

TEST(CliView, ExportsTheViewAsSvg) {
    for (const char* tool : {"Xvfb", "xdotool"})
        if (!have_tool(tool)) GTEST_SKIP() << tool << " is not installed (apt-get install xvfb xdotool); viewer not tested";
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
    EXPECT_EQ(width_view, "210mm");  // A4 portrait, the CLI's default page
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
    for (const char* tool : {"Xvfb", "xdotool"})
        if (!have_tool(tool)) GTEST_SKIP() << tool << " is not installed (apt-get install xvfb xdotool); viewer not tested";
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
    for (const char* tool : {"Xvfb", "xdotool"})
        if (!have_tool(tool)) GTEST_SKIP() << tool << " is not installed (apt-get install xvfb xdotool); viewer not tested";
    auto dir = test::temp_dir("cli-view-panel-layer");
    const std::string cache = (dir / "cache").string();
    // Animated at speed 0: the timeline's clock runs (its window changes every frame), the drawing stays.
    const std::string model = test::write_rig(anim::rigs::bending_cylinder(), "cli-view-panel-layer-model", "cylinder");
    std::ofstream(dir / "scene.json") << R"({"objects": [{"model": ")" << model << R"(", "params": {"dmax": 0.05},
                                             "animation": {"speed": 0, "start": 0.4}}],
                                             "paper": [1, 0.85, 0.6], "ink": [0.1, 0.2, 0.7]})";
    constexpr int kWidth = 962, kHeight = 600;  // rows a linear image may pad: the layer keeps its own pitch
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

size_t lines_in(const std::filesystem::path& path) {
    std::ifstream in(path);
    return size_t(std::count(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>(), '\n'));
}

// The viewer draws on demand: with nothing moving and nothing touched it presents no frames (a software
// GPU would otherwise keep both cores busy drawing the same picture), and input wakes it at once.
TEST(CliView, SleepsWhileNothingChangesAndWakesOnInput) {
    for (const char* tool : {"Xvfb", "xdotool"})
        if (!have_tool(tool)) GTEST_SKIP() << tool << " is not installed (apt-get install xvfb xdotool); viewer not tested";
    auto dir = test::temp_dir("cli-view-idle");
    write_ply_binary((dir / "sphere.ply").string(), make_uv_sphere(4000));
    const std::filesystem::path log = dir / "frames.log";
    ViewerSession session(dir);
    ASSERT_TRUE(session.start_x(170)) << "could not start Xvfb: " << slurp(dir / "xvfb.err");
    session.start_viewer({(dir / "sphere.ply").string(), "--width", "320", "--height", "256", "--frame-log",
                          log.string(), "--cache-dir", (dir / "cache").string()});
    ASSERT_TRUE(session.find_window()) << session.out() << session.err();
    ASSERT_TRUE(wait_for([&] { return lines_in(log) > 0; }, 60s)) << session.out() << session.err();
    // Frames for a second after the start and after each event (the panel's hover effects), then none.
    auto frames_in = [&](std::chrono::milliseconds span) {
        const size_t before = lines_in(log);
        std::this_thread::sleep_for(span);
        return lines_in(log) - before;
    };
    std::this_thread::sleep_for(2500ms);
    const size_t idle_before = frames_in(2000ms);
    session.focus();
    session.xdotool("key Left key Left key Left");  // orbits
    const size_t after_input = frames_in(800ms);
    std::this_thread::sleep_for(2500ms);
    const size_t idle_after = frames_in(2000ms);
    std::printf("frames in 2 s idle: %zu; in 0.8 s after three key presses: %zu; in 2 s idle again: %zu\n",
                idle_before, after_input, idle_after);
    EXPECT_LE(idle_before, 1u) << "the viewer keeps drawing an unchanged picture";
    EXPECT_GE(after_input, 2u) << "input did not wake the viewer";
    EXPECT_LE(idle_after, 1u) << "the viewer did not go back to sleep";
    session.xdotool("key q");
    EXPECT_EQ(session.viewer().wait_exit(30s), 0) << session.err();
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

}  // namespace
}  // namespace stipple
