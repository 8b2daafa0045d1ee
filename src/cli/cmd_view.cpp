#include <cctype>
#include <cstdio>
#include <filesystem>

#include "app/viewer.hpp"
#include "cli/animation_options.hpp"
#include "cli/args.hpp"
#include "cli/cache_options.hpp"
#include "cli/commands.hpp"
#include "cli/object_options.hpp"
#include "core/error.hpp"
#include "gpu/context.hpp"
#include "io/output_file.hpp"
#include "scene/scene_content.hpp"

namespace stipple::cli {

CommandOptions view_command_options() {
    CommandOptions accepted{object_flags(), object_options()};
    accepted.flags.insert({"--no-vsync", "--no-panel", "--no-count-drawn", "--verbose"});
    accepted.flags.merge(camera_flags());
    accepted.options.merge(cache_options());
    accepted.options.merge(camera_options());
    accepted.options.insert({"--width", "--height", "--device", "--screenshot-dir", "--save-scene", "--benchmark-frames", "--present", "--script", "--frame-log",
                             "--animation", "--time", "--depth-cull", "--depth-raster"});
    return accepted;
}

int run_view(const std::vector<std::string>& argv) {
    const CommandOptions accepted = view_command_options();
    Args args(argv, accepted.flags, accepted.options);
    apply_cache_options(args);

    app::ViewerOptions viewer;
    long long width = args.integer("--width", viewer.width), height = args.integer("--height", viewer.height);
    if (width < 64 || width > 16384 || height < 64 || height > 16384)
        fail("--width/--height must be between 64 and 16384 (got " + std::to_string(width) + "x" +
             std::to_string(height) + ")");
    viewer.width = int(width);
    viewer.height = int(height);
    viewer.vsync = !args.flag("--no-vsync");
    viewer.panel = !args.flag("--no-panel");
    const std::string present = args.get("--present", "auto");
    if (present == "auto") viewer.present = app::PresentMethod::Auto;
    else if (present == "swapchain") viewer.present = app::PresentMethod::Swapchain;
    else if (present == "shm") viewer.present = app::PresentMethod::SharedMemory;
    else fail("--present = " + present + " must be auto, swapchain or shm");
    viewer.count_drawn = !args.flag("--no-count-drawn");
    const std::string depth_cull = args.get("--depth-cull", "auto");
    if (!parse_depth_cull(depth_cull)) fail("--depth-cull = " + depth_cull + " must be auto, on or off");
    viewer.depth_cull = *parse_depth_cull(depth_cull);
    const std::string depth_raster = args.get("--depth-raster", "auto");
    if (!parse_depth_raster(depth_raster)) fail("--depth-raster = " + depth_raster + " must be auto, compute or fixed");
    viewer.depth_raster = *parse_depth_raster(depth_raster);
    viewer.verbose = args.flag("--verbose");
    viewer.device_index = device_index(args);
    viewer.screenshot_dir = args.get("--screenshot-dir", ".");
    viewer.script = args.get("--script", "");
    viewer.frame_log = args.get("--frame-log", "");
    viewer.benchmark_frames = args.integer("--benchmark-frames", 0);  // 0: no benchmark, the window stays
    // 0 given was taken as "no benchmark", and a script that asked for one waited on a window that stayed open.
    if (args.has("--benchmark-frames") && (viewer.benchmark_frames < 1 || viewer.benchmark_frames > 1000000))
        fail("--benchmark-frames = " + std::to_string(viewer.benchmark_frames) + " must be in 1..1000000");

    Scene scene = scene_from_command_line(args, "view");
    viewer.scene_path = args.get("--save-scene", scene.source.empty() ? "stipple-scene.json" : scene.source);
    // Checked now, not when Ctrl+S is pressed after an hour of tuning (a folder failed only then, and x.png took
    // the scene's JSON).
    if (args.has("--save-scene")) {
        std::string ext = std::filesystem::path(viewer.scene_path).extension().string();
        for (char& ch : ext) ch = char(std::tolower(static_cast<unsigned char>(ch)));
        if (ext != ".json") fail("--save-scene " + viewer.scene_path + ": a scene file is named .json");
        check_output_writable("--save-scene", viewer.scene_path);
    }
    // The models, then whether the device can hold their stipples, then the stipples (minutes for a large model
    // at a high density, with a progress bar on the terminal), all before the window opens: made in the viewer
    // once its device was open, they kept the window blank meanwhile; made before any device, one too big for it
    // was refused only after its generation. The viewer's own device comes with its window (the same --device).
    SceneContent content = load_scene_models(scene);
    if (scene.source.empty()) drop_animations_of_static_models(scene, content);
    {
        gpu::ContextOptions probe;
        probe.device_index = viewer.device_index;
        const gpu::Context device(probe);
        check_scene_fits(device, scene, content);
    }
    make_scene_stipples(scene, content);
    viewer.start_time = read_animation_clock(args, any_animated(content.objects)).time;
    if (scene.source.empty() && scene.objects.size() > 1) {
        // Models given side by side on the command line come in any units; line them up.
        std::vector<Sphere> spheres;
        for (const ObjectData& o : content.objects) spheres.push_back(o.bounds);
        arrange_side_by_side(scene, spheres);
    }
    return app::run_viewer(std::move(scene), std::move(content), viewer);
}

}  // namespace stipple::cli
