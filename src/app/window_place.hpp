#pragma once
// Keeps a panel window where the user left it across a shrink of the viewer's window. Dear ImGui moves a
// window into a smaller display and leaves it there when the display grows again: after a shrink to 200 x 150
// and back to 1280 x 1024 the timeline lay over the panel's light, paper and ink fields (a tester).
#include <imgui.h>

#include <algorithm>

namespace stipple::app {

class WindowPlace {
public:
    // Before ImGui::Begin: where the display changed size, back to the place kept, moved in as far as the window
    // needs to lie whole inside the display (never past its top left corner), if enough of it is then seen.
    void before_begin(ImVec2 display) {
        if (!known_ || same(display, display_)) return;
        ImVec2 place(std::max(0.0f, std::min(kept_.x, display.x - size_.x)), std::max(0.0f, std::min(kept_.y, display.y - size_.y)));
        if (place.x + kMinVisible < display.x && place.y + kMinVisible < display.y) ImGui::SetNextWindowPos(place, ImGuiCond_Always);
    }
    // After ImGui::Begin: a move while the display kept its size is the user's, and kept; one that comes with a
    // change of the display's size is Dear ImGui's clamping, and is not.
    void after_begin(ImVec2 display) {
        const ImVec2 pos = ImGui::GetWindowPos();
        if (!known_ || (same(display, display_) && !same(pos, last_)))
            kept_ = pos, known_ = true;
        last_ = pos;
        size_ = ImGui::GetWindowSize();
        display_ = display;
    }

private:
    static constexpr float kMinVisible = 40.0f;  // of the window inside the display, in pixels
    static bool same(ImVec2 a, ImVec2 b) { return a.x == b.x && a.y == b.y; }
    bool known_ = false;
    ImVec2 kept_, last_, size_, display_;
};

}  // namespace stipple::app
