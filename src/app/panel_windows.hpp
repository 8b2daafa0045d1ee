#pragma once
// Which of the panel's windows are drawn into each frame rather than into the layer laid over it
// (app/panel_layer.hpp). Dear ImGui lists its windows back to front. The layer goes on last, over
// everything drawn into the frame, so a window drawn into the frame must not lie in front of a window
// the layer holds where the two overlap; otherwise all of them go into the layer.
#include <cstddef>
#include <span>
#include <vector>

namespace stipple::app {

struct PanelWindow {
    float box[4] = {};       // what its commands may touch: x0, y0, x1, y1
    int changed_frames = 0;  // frames in a row in which its draw list changed
};

// A window that changed in each of the last two frames: drawn into the frame, for it would be drawn into
// the layer again every frame.
inline bool changes_every_frame(const PanelWindow& window) { return window.changed_frames >= 2; }

inline bool boxes_overlap(const float a[4], const float b[4]) {
    return a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3];
}

// For each window, back to front: whether it is drawn into the frame.
inline std::vector<bool> windows_drawn_into_frame(std::span<const PanelWindow> windows) {
    std::vector<bool> direct(windows.size(), false);
    for (size_t i = 0; i < windows.size(); ++i) {
        if (!changes_every_frame(windows[i])) continue;
        for (size_t j = 0; j < i; ++j)  // a held window behind it that it overlaps: it cannot stay under the layer
            if (!changes_every_frame(windows[j]) && boxes_overlap(windows[i].box, windows[j].box))
                return std::vector<bool>(windows.size(), false);
        direct[i] = true;
    }
    return direct;
}

}  // namespace stipple::app
