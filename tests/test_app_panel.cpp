// The viewer's panel, drawn headless by Dear ImGui (no window, no GPU): how it opens in a small window.
#include <gtest/gtest.h>

#include <imgui.h>

#include <string>
#include <vector>

#include "anim/procedural_rigs.hpp"
#include "app/key_latch.hpp"
#include "app/panel.hpp"
#include "app/param_widgets.hpp"
#include "app/timeline.hpp"
#include "app/window_place.hpp"
#include "params/param_table.hpp"
#include "scene/scene_content.hpp"
#include "support/anim_files.hpp"

namespace {

using namespace stipple;

// A Dear ImGui context without a window or a renderer: a display of `size` at 60 frames a second, its font atlas
// built (never uploaded).
ImGuiIO& start_headless_imgui(ImVec2 size = ImVec2(800.0f, 600.0f)) {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = size;
    io.DeltaTime = 1.0f / 60.0f;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    return io;
}

// The panel's height after a few frames of a `width` x 512 window (ImGui fits its height to the content
// over the first frames), `messages` given from frame `message_frame` on, `errors` of them errors.
// `click_at`: the mouse pressed there in frame 3, moved by `drag` while held in frame 4, released in frame 5.
float panel_height(uint32_t width, const std::vector<std::string>& messages = {}, int message_frame = 0, uint64_t errors = 0,
                   ImVec2 click_at = ImVec2(-1.0f, -1.0f), ImVec2 drag = ImVec2(0.0f, 0.0f)) {
    ImGuiIO& io = start_headless_imgui(ImVec2(float(width), 512.0f));
    Scene scene;
    app::PanelFigures figures;
    figures.extent = {width, 512};
    app::ExportPanelState export_state;
    float height = 0.0f;
    for (int frame = 0; frame < 8; ++frame) {
        if (frame == message_frame) {
            figures.messages = messages;
            figures.errors_said += errors;
        }
        if (click_at.x >= 0.0f) {
            io.MousePos = frame >= 4 ? ImVec2(click_at.x + drag.x, click_at.y + drag.y) : click_at;
            io.MouseDown[0] = frame == 3 || frame == 4;
        }
        ImGui::NewFrame();
        height = app::draw_panel(scene, {}, figures, export_state).rect.w;
        ImGui::Render();
    }
    ImGui::DestroyContext();
    return height;
}

// At 640 x 512 the open panel covered three quarters of the drawing: a window narrower than 1000 px
// starts with it folded to its title bar; a wider one, open.
TEST(AppPanel, ANarrowWindowStartsWithThePanelFolded) {
    const float narrow = panel_height(640), wide = panel_height(1280);
    std::printf("panel height: %.0f px in a 640-px window, %.0f in a 1280-px one\n", narrow, wide);
    EXPECT_LT(narrow, 40.0f) << "the title bar alone";
    EXPECT_GT(wide, 150.0f) << "open";
}

// A click on the folded panel's title opens it (only a click on its arrow did, where the README said "click it
// to open"); a drag on the title moves it and leaves it folded.
TEST(AppPanel, AClickOnTheFoldedTitleOpensThePanel) {
    EXPECT_GT(panel_height(640, {}, 0, 0, ImVec2(120.0f, 20.0f)), 150.0f);
    EXPECT_LT(panel_height(640, {}, 0, 0, ImVec2(120.0f, 20.0f), ImVec2(40.0f, 10.0f)), 40.0f);
    // Its arrow opens it too (Dear ImGui's own toggle, which the title's click must not undo).
    EXPECT_GT(panel_height(640, {}, 0, 0, ImVec2(20.0f, 19.0f)), 150.0f);
    EXPECT_LT(panel_height(640), 40.0f);
}

// The panel shows the viewer's messages: a new error unfolds it, a confirmation does not.
TEST(AppPanel, ANewErrorUnfoldsThePanel) {
    EXPECT_LT(panel_height(640, {"scene saved: x.json"}, 3), 40.0f);
    EXPECT_GT(panel_height(640, {"error: x.svg: cannot write"}, 3, 1), 150.0f);
}

// Whether a click at (x, y) presses "frame all (F)" in a 1280 x 1024 window, with `passes` GPU passes timed and
// background work running or not (the mouse pressed in frame 3, released in frame 5).
bool click_frames_all(float x, float y, size_t passes, bool working) {
    ImGuiIO& io = start_headless_imgui(ImVec2(1280.0f, 1024.0f));
    Scene scene;
    app::PanelFigures figures;
    figures.extent = {1280, 1024};
    for (size_t i = 0; i < passes; ++i) figures.stats.gpu_ms.emplace_back("pass" + std::to_string(i), 1.0 + double(i));
    if (working) {
        figures.work_label = "new stipples for stanford-bunny.obj";
        figures.work_fraction = 0.4;
        figures.work_queued = 2;
    }
    app::ExportPanelState export_state;
    bool pressed = false;
    for (int frame = 0; frame < 7; ++frame) {
        io.MousePos = ImVec2(x, y);
        io.MouseDown[0] = frame == 3 || frame == 4;
        ImGui::NewFrame();
        pressed |= app::draw_panel(scene, {}, figures, export_state).frame_all;
        ImGui::Render();
    }
    ImGui::DestroyContext();
    return pressed;
}

// The controls stay where they are when the GPU's passes change (turning lines on added two timing rows above
// every control: a walkthrough's click aimed at the toon box landed on a label) or background work starts (its
// progress bar and queue line pushed them down while new stipples were made, right after a slider's release).
TEST(AppPanel, TheControlsStayPutWhenPassesOrWorkAppear) {
    std::vector<float> on_button;  // heights at which a click presses "frame all" with three passes, no work
    for (float y = 30.0f; y < 500.0f; y += 3.0f)
        if (click_frames_all(40.0f, y, 3, false)) on_button.push_back(y);
    ASSERT_FALSE(on_button.empty()) << "no click presses frame all";
    std::printf("\"frame all\" under the mouse from y = %.0f to %.0f\n", double(on_button.front()), double(on_button.back()));
    for (const float y : on_button) {
        EXPECT_TRUE(click_frames_all(40.0f, y, 9, false)) << "nine passes timed: moved from y = " << y;
        EXPECT_TRUE(click_frames_all(40.0f, y, 0, true)) << "work running: moved from y = " << y;
    }
}

// D_max typed into its slider (focused, as Ctrl+click does), then Enter pressed and released between two frames, as
// xdotool gives it and as a keystroke falls in a heavy scene at a few frames a second: Dear ImGui 1.86 reads
// keys as states once a frame and never saw that Enter down, so the value was never committed (no new
// stipples). The viewer's KeyLatch holds such a key down for one frame. Returns whether the edit was
// committed, and the value the parameter holds.
std::pair<bool, float> type_and_enter(bool latched) {
    constexpr int kEnter = 257;  // GLFW_KEY_ENTER, the backend's key code (io.KeyMap)
    ImGuiIO& io = start_headless_imgui();
    io.KeyMap[ImGuiKey_Enter] = kEnter;
    const ParamSpec& dmax = *find_param("dmax");
    ObjectParams params;
    app::KeyLatch latch;
    bool committed = false;
    for (int frame = 0; frame < 6; ++frame) {
        if (frame == 2)
            for (const char c : std::string("0.21")) io.AddInputCharacter(c);
        if (frame == 3) {  // the backend's callback, a press then a release, before the frame reads them
            io.KeysDown[kEnter] = true;
            latch.pressed(kEnter);
            io.KeysDown[kEnter] = false;
        }
        if (latched) latch.apply(io.KeysDown, IM_ARRAYSIZE(io.KeysDown), [](int) { return false; });
        ImGui::NewFrame();
        ImGui::Begin("panel");
        if (frame == 0) ImGui::SetKeyboardFocusHere();  // the slider becomes a text field
        committed |= app::draw_param_widget(dmax, params, dmax.max).committed;
        ImGui::End();
        ImGui::Render();
    }
    ImGui::DestroyContext();
    return {committed, params.generation.dmax};
}

// The latch alone: a quick press is down for one frame; pressed again while latched, up for a frame then down
// again (two presses, not one long one); presses made while the panel was hidden are forgotten.
TEST(AppPanel, TheKeyLatchHoldsEachQuickPressForOneFrame) {
    bool down[8] = {};
    app::KeyLatch latch;
    const auto released = [](int) { return false; };
    std::string seen;  // key 3's state, frame by frame
    const auto frame = [&] {
        latch.apply(down, 8, released);
        seen += down[3] ? '1' : '0';
    };
    latch.pressed(3);  // press and release before frame 1
    frame();
    latch.pressed(3);  // again, before frame 2
    frame();
    frame();
    frame();
    latch.pressed(3);
    latch.forget();  // the panel hidden for that frame
    frame();
    EXPECT_EQ(seen, "10100");
}

// D_max's field with 0.3 typed in it, then Ctrl+A pressed and released between two frames (Ctrl, A, A up, Ctrl up, as
// xdotool key ctrl+a gives them), then 2.5 typed and Enter: the latch held both keys down for a frame, but the
// backend had set Ctrl up at its release, so Dear ImGui saw a bare A, nothing was selected, and the typed
// characters joined the old text (0.32 committed). Returns the value committed.
float select_all_and_type(bool modifiers_from_keys) {
    constexpr int kEnter = 257, kA = 65, kCtrl = 341;  // GLFW_KEY_ENTER, GLFW_KEY_A, GLFW_KEY_LEFT_CONTROL
    ImGuiIO& io = start_headless_imgui();
    io.KeyMap[ImGuiKey_Enter] = kEnter;
    io.KeyMap[ImGuiKey_A] = kA;
    const ParamSpec& dmax = *find_param("dmax");
    ObjectParams params;
    params.generation.dmax = 0.21f;
    app::KeyLatch latch;
    // The backend's key callback: the key's state, then the modifiers from the states, as it sets them.
    auto event = [&](int key, bool down) {
        io.KeysDown[key] = down;
        if (down) latch.pressed(key);
        io.KeyCtrl = io.KeysDown[kCtrl];
    };
    for (int frame = 0; frame < 9; ++frame) {
        if (frame == 2)  // the field's text selected on focus: typed over, the cursor after it
            for (const char c : std::string("0.3")) io.AddInputCharacter(c);
        if (frame == 3) {
            event(kCtrl, true), event(kA, true), event(kA, false), event(kCtrl, false);
        }
        if (frame == 5)
            for (const char c : std::string("2.5")) io.AddInputCharacter(c);
        if (frame == 6) event(kEnter, true), event(kEnter, false);
        latch.apply(io.KeysDown, IM_ARRAYSIZE(io.KeysDown), [](int) { return false; });
        if (modifiers_from_keys) app::KeyLatch::set_modifiers(io.KeysDown, io.KeyCtrl, io.KeyShift, io.KeyAlt, io.KeySuper);
        ImGui::NewFrame();
        ImGui::Begin("panel");
        if (frame == 0) ImGui::SetKeyboardFocusHere();  // the slider becomes a text field
        app::draw_param_widget(dmax, params, dmax.max);
        ImGui::End();
        ImGui::Render();
    }
    ImGui::DestroyContext();
    return params.generation.dmax;
}

TEST(AppPanel, AQuickCtrlABetweenTwoFramesSelectsTheField) {
    const float lost = select_all_and_type(false);
    EXPECT_NE(lost, 2.5f) << "without the modifiers from the latched keys Dear ImGui misses the Ctrl: the test no longer shows it";
    const float typed = select_all_and_type(true);
    EXPECT_FLOAT_EQ(typed, 2.5f);
    std::printf("0.3 typed in the field, Ctrl+A between frames, 2.5 typed: without the modifiers D_max %.3g, with them %.3g\n",
                double(lost), double(typed));
}

// The timeline's window at its place in a 1280 x 1024 viewer, the viewer shrunk to 200 x 150 (Dear ImGui moves
// the window into it) and grown back; then moved by the user at that size. Returns the window's place after the
// growth, and after the move.
std::pair<ImVec2, ImVec2> shrink_and_grow(bool kept) {
    ImGuiIO& io = start_headless_imgui();
    app::WindowPlace place;
    ImVec2 pos, moved;
    const ImVec2 sizes[] = {{1280, 1024}, {1280, 1024}, {200, 150}, {200, 150}, {200, 150}, {1280, 1024}, {1280, 1024},
                            {1280, 1024}, {1280, 1024}};
    for (int frame = 0; frame < 9; ++frame) {
        io.DisplaySize = sizes[frame];
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(490, 850), ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowSize(ImVec2(440, 120), ImGuiCond_FirstUseEver);
        if (frame == 7) ImGui::SetNextWindowPos(ImVec2(300, 400), ImGuiCond_Always);  // as a drag by the user moves it
        if (kept) place.before_begin(io.DisplaySize);
        ImGui::Begin("timeline");
        if (kept) place.after_begin(io.DisplaySize);
        if (frame == 6) pos = ImGui::GetWindowPos();
        if (frame == 8) moved = ImGui::GetWindowPos();
        ImGui::End();
        ImGui::Render();
    }
    ImGui::DestroyContext();
    return {pos, moved};
}

TEST(AppPanel, AWindowReturnsToItsPlaceWhenTheViewerGrowsAgain) {
    const auto [lost, lost_moved] = shrink_and_grow(false);
    EXPECT_TRUE(lost.x != 490.0f || lost.y != 850.0f) << "Dear ImGui no longer leaves it where the shrink put it: the test shows nothing";
    const auto [back, moved] = shrink_and_grow(true);
    EXPECT_FLOAT_EQ(back.x, 490.0f);
    EXPECT_FLOAT_EQ(back.y, 850.0f);
    EXPECT_FLOAT_EQ(moved.x, 300.0f);  // the user's own move stays
    EXPECT_FLOAT_EQ(moved.y, 400.0f);
    std::printf("timeline at (490, 850), the viewer shrunk and grown: without the kept place at (%.0f, %.0f), with it (%.0f, %.0f)\n",
                double(lost.x), double(lost.y), double(back.x), double(back.y));
}

// The panel's height after each stretch of frames at a display (and frame) height, 1280 wide: {height, frames}.
std::vector<float> panel_heights_over(const std::vector<std::pair<float, int>>& stretches) {
    ImGuiIO& io = start_headless_imgui(ImVec2(1280.0f, stretches.front().first));
    Scene scene;
    app::PanelFigures figures;
    app::ExportPanelState export_state;
    std::vector<float> after;
    for (const auto& [height, frames] : stretches) {
        io.DisplaySize = ImVec2(1280.0f, height);
        figures.extent = {1280, uint32_t(height)};
        float h = 0.0f;
        for (int frame = 0; frame < frames; ++frame) {
            ImGui::NewFrame();
            h = app::draw_panel(scene, {}, figures, export_state).rect.w;
            ImGui::Render();
        }
        after.push_back(h);
    }
    ImGui::DestroyContext();
    return after;
}

// A viewer made 300 px high, grown for one frame, then made 50 px high and grown again: the frame at full
// height let the panel fit its content again, which Dear ImGui does over a few frames and caps at the
// display, so in the 50-px display it became 100 px (its least), under the 200-px floor of its height
// limit, which therefore did not count it as clamped, and it stayed 100 px high in the full window (the
// figures alone, the rest behind a scroll bar).
TEST(AppPanel, ThePanelGrowsBackAfterAVeryLowWindow) {
    const std::vector<float> h = panel_heights_over({{1024.0f, 6}, {300.0f, 6}, {1024.0f, 1}, {50.0f, 6}, {1024.0f, 6}});
    EXPECT_GT(h[0], 300.0f);
    EXPECT_LE(h[3], 200.0f);
    EXPECT_FLOAT_EQ(h[4], h[0]) << "after 300: " << h[1] << ", after 50: " << h[3];
}

// The timeline holds a row for each animated object: with twelve of them it ran below a 1024-px window's edge,
// the last rows out of reach. It stays inside the window, at most half its height, its rows scrolled; with one
// object it sits at the window's foot as before.
TEST(AppPanel, TheTimelineOfManyAnimatedObjectsStaysInTheWindow) {
    const std::string rig = test::write_rig(anim::rigs::bending_cylinder(), "app-panel-timeline", "bend");
    for (const size_t animated : {size_t(1), size_t(12)}) {
        Scene scene;
        for (size_t i = 0; i < animated; ++i) scene.objects.push_back({rig, {}, {}, {}});
        const SceneContent content = load_scene_models(scene);
        start_headless_imgui(ImVec2(1280.0f, 1024.0f));
        app::Timeline timeline;
        glm::vec4 rect(0.0f);
        for (int frame = 0; frame < 6; ++frame) {
            ImGui::NewFrame();
            rect = timeline.draw(scene, content.objects, std::vector<std::string>(animated, "bend.glb"), glm::vec2(1280.0f, 1024.0f));
            ImGui::Render();
        }
        ImGui::DestroyContext();
        std::printf("%zu animated objects: timeline at y %.0f, %.0f high\n", animated, double(rect.y), double(rect.w));
        EXPECT_GT(rect.w, 100.0f) << animated;
        EXPECT_LE(rect.y + rect.w, 1024.0f) << animated << " animated objects: the timeline runs below the window";
        EXPECT_LE(rect.w, animated == 1 ? 200.0f : 512.0f) << animated;
    }
}

TEST(AppPanel, AnEnterBetweenTwoFramesCommitsTheTypedValue) {
    const auto [lost, lost_value] = type_and_enter(false);
    EXPECT_FALSE(lost) << "without the latch Dear ImGui 1.86 misses the Enter: the test no longer shows the problem";
    const auto [committed, value] = type_and_enter(true);
    EXPECT_TRUE(committed);
    EXPECT_FLOAT_EQ(value, 0.21f);
    std::printf("typed 0.21, Enter between frames: without the latch committed %d (D_max %.3g), with it %d (%.3g)\n",
                int(lost), double(lost_value), int(committed), double(value));
}

}  // namespace
