#pragma once
// The viewer's state (app/viewer.hpp runs it): the window, the device, the scene and what the panel and
// the timeline show. viewer.cpp opens it and runs the loop, the script, the input and the panel's
// requests; viewer_frame.cpp draws and presents one frame.
#include <chrono>
#include <cstdio>
#include <deque>
#include <map>
#include <memory>
#include <optional>

#include "app/background_work.hpp"
#include "app/camera_control.hpp"
#include "app/export_panel.hpp"
#include "app/live_scene.hpp"
#include "app/overlay.hpp"
#include "app/panel.hpp"
#include "app/screenshot.hpp"
#include "app/swapchain.hpp"
#include "app/timeline.hpp"
#include "app/viewer.hpp"
#include "app/viewer_script.hpp"
#include "app/window.hpp"
#include "gpu/context.hpp"
#include "render/stipple_renderer.hpp"

namespace stipple::app {

using Clock = std::chrono::steady_clock;

// After an event, frames are drawn for this long before the viewer sleeps (Dear ImGui's hover effects and
// tooltips take a few frames and a delay); while background work runs, one frame each kProgressInterval.
constexpr std::chrono::milliseconds kSettle{1000};
constexpr std::chrono::milliseconds kProgressInterval{100};
constexpr long long kWarmupFrames = 10;  // --benchmark-frames: the first frames compile shaders, fault in memory

inline double ms_between(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
}

// Owns the surface so that it is destroyed after the swapchain and before the instance.
struct Surface {
    Surface(const gpu::Context& context, const Window& window)
        : instance(context.instance), handle(window.create_surface(context.instance)) {}
    ~Surface() { vkDestroySurfaceKHR(instance, handle, nullptr); }
    VkInstance instance;
    VkSurfaceKHR handle;
};

class Viewer {
public:
    Viewer(Scene scene, SceneContent content, const ViewerOptions& options);
    ~Viewer();
    Viewer(const Viewer&) = delete;
    Viewer& operator=(const Viewer&) = delete;

    int run();

private:
    void frame();
    bool wants_frame_now();     // something moves, was touched, or runs a script or a benchmark
    bool progress_due() const;  // background work's progress bar is due a frame
    void finish_previous_frame();
    void handle_input(const Input& input, float aspect);
    void handle_requests(const PanelRequests& requests, float aspect);
    // The window's columns the open panel leaves free, where "frame all" puts the scene (columns_left_free).
    glm::vec2 free_columns() const;
    bool ensure_swapchain();
    void record(uint32_t image_index);
    void message(const std::string& text, bool error = false);
    void save_scene();
    void print_swapchain() const;
    void apply_finished_work();
    void run_script();
    void print_panel_draws(const char* prefix) const;
    bool export_view(const std::string& path, const plot::ExportOptions& options);

    ViewerOptions options_;
    Window window_;
    gpu::Context context_;
    Surface surface_;
    Swapchain swapchain_;
    StippleRenderer renderer_;
    LiveScene live_;
    ScreenshotCapture screenshot_;
    std::unique_ptr<Overlay> overlay_;
    VkCommandBuffer cb_ = VK_NULL_HANDLE;
    VkFence frame_done_ = VK_NULL_HANDLE;
    VkSemaphore acquired_ = VK_NULL_HANDLE;

    OrbitCamera camera_;
    bool vsync_;
    bool panel_visible_;
    std::string present_mode_;  // what the panel shows (Figures::present_mode points into it)
    bool recreate_ = false;
    bool submitted_ = false;  // a frame is in flight (its fence is pending)
    bool paused_ = false;
    PanelFigures figures_;
    glm::vec4 panel_rect_{0.0f};
    bool panel_open_ = false;         // unfolded, as last drawn
    // Until the panel has been drawn twice (its first frame's size and fold are not settled yet): then, if it
    // is open, the view moves beside it (frame_at_open), framed at this many times the framing distance where the
    // scene's camera is framed (no target or world distance of its own).
    int panel_frames_until_open_view_ = 2;
    std::optional<float> open_distance_multiple_;
    glm::vec2 panel_display_{0.0f};   // the window's size in the panel rectangle's pixels
    Timeline timeline_;
    glm::vec4 timeline_rect_{0.0f};
    std::optional<Clock::time_point> last_frame_;  // when the timeline last moved on
    std::deque<std::string> messages_;
    uint64_t errors_said_ = 0;  // every error message so far (PanelFigures::errors_said)
    std::vector<size_t> pending_regeneration_;
    BackgroundWork work_{context_};  // after live_ and context_; destroyed first (joins its worker)
    std::vector<ScriptAction> script_;
    size_t script_at_ = 0;
    std::optional<Clock::time_point> script_wait_until_;
    bool script_failed_ = false;
    int script_set_line_ = 0;  // the script's last `set` line run (a refusal comes when the setting is applied)
    bool script_set_unapplied_ = false;  // a `set` run since the last frame applied the settings
    int script_action_line_ = 0;  // the line of the action running now, while it runs (its errors name it)
    FILE* frame_log_ = nullptr;
    Clock::time_point started_ = Clock::now();
    std::optional<size_t> pending_removal_;
    ExportPanelState export_state_;
    std::optional<ExportRequest> pending_export_;  // from the panel; done between frames
    long long frames_drawn_ = 0;
    std::map<std::string, double> bench_gpu_ms_;  // summed over the benchmark's frames
    int bench_samples_ = 0;
    Clock::time_point fps_start_ = Clock::now();
    int fps_frames_ = 0;
    // The panel's figures change twice a second, with the fps: GPU and CPU times averaged over the frames
    // collected since (a panel that changes every frame would be drawn again every frame, app/panel_layer.hpp).
    FrameStats collected_;  // the last frame collected (finish_previous_frame)
    std::vector<std::pair<std::string, double>> gpu_ms_sums_;
    int gpu_ms_frames_ = 0;
    double cpu_ms_sum_ = 0.0;
    // Drawing on demand (wants_frame_now): the window's activity count last seen, the time until which
    // frames are drawn (after an event, a message, finished work), the last frame drawn, whether the loop slept.
    uint64_t seen_activity_ = 0;
    Clock::time_point draw_until_ = Clock::now() + kSettle;
    Clock::time_point last_drawn_{};
    bool idled_ = false;
};

}  // namespace stipple::app
