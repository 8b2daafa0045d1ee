// The viewer's panel, drawn headless by Dear ImGui (no window, no GPU): how it opens in a small window.
#include <gtest/gtest.h>

#include <imgui.h>

#include <string>
#include <vector>

#include "app/panel.hpp"

namespace {

using namespace stipple;

// The panel's height after a few frames of a `width` x 512 window (ImGui fits its height to the content
// over the first frames), `messages` given from frame `message_frame` on, `errors` of them errors.
float panel_height(uint32_t width, const std::vector<std::string>& messages = {}, int message_frame = 0, uint64_t errors = 0) {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(float(width), 512.0f);
    io.DeltaTime = 1.0f / 60.0f;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);  // a font atlas, never uploaded
    Scene scene;
    app::PanelFigures figures;
    figures.extent = {width, 512};
    app::ExportPanelState export_state;
    float height = 0.0f;
    for (int frame = 0; frame < 6; ++frame) {
        if (frame == message_frame) {
            figures.messages = messages;
            figures.errors_said += errors;
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

// The panel shows the viewer's messages: a new error unfolds it, a confirmation does not.
TEST(AppPanel, ANewErrorUnfoldsThePanel) {
    EXPECT_LT(panel_height(640, {"scene saved: x.json"}, 3), 40.0f);
    EXPECT_GT(panel_height(640, {"error: x.svg: cannot write"}, 3, 1), 150.0f);
}

}  // namespace
