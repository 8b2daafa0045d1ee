// Which of the viewer's panel windows are drawn into each frame, under the layer laid over it last
// (app/panel_windows.hpp): those that change every frame, unless one lies in front of a window the layer
// holds where the two overlap, which would put the held window over it on screen.
#include <gtest/gtest.h>

#include <vector>

#include "app/panel_windows.hpp"

namespace {

using stipple::app::PanelWindow;
using stipple::app::windows_drawn_into_frame;

PanelWindow window(float x0, float y0, float x1, float y1, int changed_frames) {
    PanelWindow w;
    w.box[0] = x0;
    w.box[1] = y0;
    w.box[2] = x1;
    w.box[3] = y1;
    w.changed_frames = changed_frames;
    return w;
}

const PanelWindow kPanel = window(10, 10, 480, 1010, 0);  // still
const PanelWindow kTimeline = window(490, 850, 930, 1000, 5);  // its clock runs: changes every frame

TEST(PanelWindows, AWindowThatChangesEveryFrameBesideTheOthersIsDrawnIntoTheFrame) {
    const std::vector<PanelWindow> windows{kPanel, kTimeline};
    EXPECT_EQ(windows_drawn_into_frame(windows), (std::vector<bool>{false, true}));
}

TEST(PanelWindows, OneChangeIsNotEnough) {
    // Changed once (a hover, the figures' refresh): the layer is drawn again, the window stays in it.
    const std::vector<PanelWindow> windows{kPanel, window(490, 850, 930, 1000, 1)};
    EXPECT_EQ(windows_drawn_into_frame(windows), (std::vector<bool>{false, false}));
}

TEST(PanelWindows, InFrontOfAHeldWindowItOverlapsEverythingGoesIntoTheLayer) {
    const PanelWindow over_the_panel = window(300, 850, 740, 1000, 5);  // dragged over the panel, in front
    const std::vector<PanelWindow> windows{kPanel, over_the_panel};
    EXPECT_EQ(windows_drawn_into_frame(windows), (std::vector<bool>{false, false}));
}

TEST(PanelWindows, BehindAHeldWindowItOverlapsItStaysUnderTheLayer) {
    // Behind the panel: the layer over it is where the panel is on screen anyway.
    const PanelWindow behind = window(300, 850, 740, 1000, 5);
    const std::vector<PanelWindow> windows{behind, kPanel};
    EXPECT_EQ(windows_drawn_into_frame(windows), (std::vector<bool>{true, false}));
}

TEST(PanelWindows, ChangingWindowsMayOverlapEachOther) {
    const std::vector<PanelWindow> windows{kPanel, kTimeline, window(600, 800, 700, 900, 3)};
    EXPECT_EQ(windows_drawn_into_frame(windows), (std::vector<bool>{false, true, true}));
    EXPECT_TRUE(windows_drawn_into_frame(std::vector<PanelWindow>{}).empty());
}

TEST(PanelWindows, BoxesThatOnlyTouchDoNotOverlap) {
    const std::vector<PanelWindow> windows{kPanel, window(480, 10, 700, 200, 4)};
    EXPECT_EQ(windows_drawn_into_frame(windows), (std::vector<bool>{false, true}));
}

}  // namespace
