#include "core/printf_string.hpp"
#include "cli/cmd_bench_plot.hpp"

#include <cstdio>

#include "app/frame_export.hpp"
#include "core/timing.hpp"
#include "export/order_speed.hpp"
#include "export/page.hpp"
#include "export/plot_plan.hpp"
#include "export/plot_stats.hpp"
#include "gpu/context.hpp"
#include "scene/frame_sequence.hpp"
#include "scene/scene_content.hpp"

namespace stipple::cli {

namespace {

// What `stipple render bunny.obj -o x.svg` plans: the frame's visible stipples on an A4 page.
bench::PlotOrderFigures bunny_plot(const std::filesystem::path& model, uint32_t width, uint32_t height, int device,
                                   uint32_t* validation_messages) {
    Scene scene;
    scene.objects.push_back({model.string(), {}, ObjectParams{}});
    const SceneContent content = load_scene_content(scene);
    const Sphere bounds = scene_bounds(scene, content.objects);
    const VkExtent2D extent{width, height};
    const OrbitCamera camera = frame_cameras(scene, bounds, float(width) / float(height), 0, std::nullopt).front();
    const FrameView view = scene_frame_view(scene, camera, bounds, extent);

    gpu::ContextOptions context_options;
    context_options.device_index = device;
    const gpu::Context context(context_options);
    bench::PlotOrderFigures f;
    auto start = Clock::now();
    const plot::Drawing drawing = app::capture_drawing(context, scene, content.objects, view);
    f.capture_seconds = seconds_since(start);
    plot::ExportOptions options;
    options.page = plot::parse_page("A4");
    start = Clock::now();
    const plot::PlotPlan plan = plot::make_plot_plan(drawing, options);
    f.order_seconds = seconds_since(start);
    const plot::PlotStats stats = plot::plot_stats(plan);
    f.dots = stats.dots;
    f.travel_ratio = stats.travel_ratio();
    *validation_messages = context.validation_message_count();
    return f;
}

}  // namespace

bench::PlotOrderRow measure_plot_order_row(size_t dots, bool bunny_view, const std::filesystem::path& models_dir,
                                           uint32_t width, uint32_t height, int device,
                                           const std::function<void(const std::string&)>& log) {
    bench::PlotOrderRow row;
    const plot::OrderSpeed speed = plot::measure_order_speed(dots);
    row.blue_noise = bench::PlotOrderFigures{speed.points.size(), speed.plot_order_s, speed.ratio(),
                                             speed.bound_mm > 0.0 ? speed.random_mm / speed.bound_mm : 0.0, 0.0};
    log(printf_string("plot order: %zu blue-noise dots ordered in %.3f s, pen-up travel %.3f x its lower bound (random order %.1f x)",
               row.blue_noise->dots, row.blue_noise->order_seconds, row.blue_noise->travel_ratio,
               row.blue_noise->random_ratio));
    if (!bunny_view) {
        row.bunny_note = "not measured in this run (--quick, or --models without --plot-dots)";
        return row;
    }
    const std::filesystem::path bunny = models_dir / "stanford-bunny.obj";
    if (!std::filesystem::is_regular_file(bunny)) {
        row.bunny_note = "the scan " + bunny.string() + " is not there";
        log("plot order: no bunny figure (" + row.bunny_note + ")");
        return row;
    }
    row.bunny_view = bunny_plot(bunny, width, height, device, &row.validation_messages);
    const bench::PlotOrderFigures& f = *row.bunny_view;
    log(printf_string("plot order: the bunny's default view, %zu visible stipples (captured in %.2f s), planned in %.3f s, "
               "pen-up travel %.3f x its lower bound",
               f.dots, f.capture_seconds, f.order_seconds, f.travel_ratio));
    return row;
}

}  // namespace stipple::cli
