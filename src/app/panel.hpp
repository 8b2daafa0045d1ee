#pragma once
// The Dear ImGui panel: every per-object parameter of the paper, the light and colours, and live
// figures of the last frame. It edits the scene in place; what cannot happen inside a widget
// (new stipples, removing an object, files, screenshots) comes back as requests.
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "app/export_panel.hpp"
#include "render/stipple_renderer.hpp"
#include "scene/scene.hpp"

namespace stipple::app {

struct PanelFigures {
    // Refreshed twice a second: times averaged over the frames since, counts of the last frame.
    double fps = 0.0;
    double cpu_frame_ms = 0.0;  // CPU time of a frame: input, panel, prepare, record, submit
    FrameStats stats;           // GPU times per pass, drawn stipples
    std::string device;
    VkExtent2D extent{};
    const char* present_mode = "";
    bool vsync = true;
    bool orthographic = false;  // the camera's projection
    bool can_disable_vsync = false;
    float max_point_size = 64.0f;
    std::string scene_path;       // where "save scene" writes
    std::string screenshot_dir;
    std::vector<std::string> messages;  // newest last: errors and confirmations
    uint64_t errors_said = 0;           // errors among every message said so far (a new one unfolds the panel)
    std::string work_label;   // background work running now ("" when idle), e.g. "new stipples for stanford-bunny.obj"
    double work_fraction = 0.0;
    size_t work_queued = 0;
};

struct PanelRequests {
    bool screenshot = false;
    bool save_scene = false;
    bool frame_all = false;
    bool toggle_projection = false;  // perspective <-> orthographic
    bool toggle_vsync = false;
    bool hide = false;
    std::vector<size_t> regenerate;  // objects whose generation parameters were committed
    std::optional<size_t> remove;
    std::optional<ExportRequest> export_view;  // "export SVG/PDF" pressed
    glm::vec4 rect{0.0f};  // the panel's x, y, width, height in window pixels this frame
    bool open = false;     // unfolded (folded, it is its title bar alone)
    glm::vec2 display{0.0f};  // the window's size in the same pixels as `rect` (ImGui's display)
};

// `names`: one label per scene object (its model file). `export_state`: the export section's fields.
PanelRequests draw_panel(Scene& scene, const std::vector<std::string>& names, const PanelFigures& figures,
                         ExportPanelState& export_state);

}  // namespace stipple::app
