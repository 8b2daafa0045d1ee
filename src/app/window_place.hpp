#pragma once
// Keeps a panel window where the user left it across a shrink of the viewer's window. Dear ImGui moves a
// window into a smaller display and leaves it there when the display grows again: after a shrink to 200 x 150
// and back to 1280 x 1024 the timeline lay over the panel's light, paper and ink fields (a tester).
#include <imgui.h>

namespace stipple::app {

class WindowPlace {
public:
    // Before ImGui::Begin: where the display changed size, back to the place kept, if it fits.
    void before_begin(ImVec2 display) {
        if (known_ && !same(display, display_) && kept_.x + kMinVisible < display.x && kept_.y + kMinVisible < display.y)
            ImGui::SetNextWindowPos(kept_, ImGuiCond_Always);
    }
    // After ImGui::Begin: a move while the display kept its size is the user's, and kept; one that comes with a
    // change of the display's size is Dear ImGui's clamping, and is not.
    void after_begin(ImVec2 display) {
        const ImVec2 pos = ImGui::GetWindowPos();
        if (!known_ || (same(display, display_) && !same(pos, last_)))
            kept_ = pos, known_ = true;
        last_ = pos;
        display_ = display;
    }

private:
    static constexpr float kMinVisible = 40.0f;  // of the window inside the display, in pixels
    static bool same(ImVec2 a, ImVec2 b) { return a.x == b.x && a.y == b.y; }
    bool known_ = false;
    ImVec2 kept_, last_, display_;
};

}  // namespace stipple::app
