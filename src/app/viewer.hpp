#pragma once
// `stipple view`: a window showing a scene, turned with the mouse and keyboard, tuned with the panel.
#include <string>

#include "render/depth_raster.hpp"
#include "render/depth_triangles.hpp"
#include "scene/scene.hpp"
#include "scene/scene_content.hpp"

namespace stipple::app {

// How frames reach the window: Vulkan's swapchain, or X11 shared memory (app/x11_shared_memory.hpp);
// Auto takes shared memory on a CPU device where the X server allows it.
enum class PresentMethod { Auto, Swapchain, SharedMemory };

struct ViewerOptions {
    int width = 1280;
    int height = 1024;
    bool vsync = true;
    PresentMethod present = PresentMethod::Auto;
    bool panel = true;
    bool count_drawn = true;          // the panel's drawn-stipple count (a GPU atomic per drawn stipple)
    DepthCull depth_cull = DepthCull::Auto;  // the depth pass's triangle lists (render/depth_triangles.hpp)
    DepthRaster depth_raster = DepthRaster::Auto;  // the depth pass as compute (render/depth_raster.hpp)
    std::string screenshot_dir = ".";
    std::string scene_path = "stipple-scene.json";  // where "save scene" writes
    long long benchmark_frames = 0;   // > 0: draw this many frames after a warm-up, print the mean fps, exit
    int device_index = -1;
    bool verbose = false;
    std::string script;     // --script: timed actions (viewer_script.hpp)
    std::string frame_log;  // --frame-log: one line per presented frame: milliseconds since start, 1 if background work ran
    double start_time = 0.0;          // the animation timeline's clock at the start (--time)
};

// Opens the window and runs until it is closed (Escape, Q or the window manager). Returns the exit
// code: 0, or 2 when Vulkan validation reported anything. Throws stipple::Error on failures. `content`
// comes with its stipples made (cmd_view checks the device first: check_scene_fits).
int run_viewer(Scene scene, SceneContent content, const ViewerOptions& options);

}  // namespace stipple::app
