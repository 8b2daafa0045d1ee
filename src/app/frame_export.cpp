#include "app/frame_export.hpp"

#include <algorithm>
#include <filesystem>

#include "core/error.hpp"
#include "export/plot_file.hpp"
#include "gpu/context.hpp"
#include "render/offscreen.hpp"
#include "scene/scene_content.hpp"

namespace stipple::app {

plot::Drawing capture_drawing(const gpu::Context& context, const Scene& scene, const std::vector<ObjectData>& objects,
                              const FrameView& view) {
    STIPPLE_CHECK(scene.objects.size() == objects.size(), "one ObjectData per scene object");
    RendererOptions options;
    options.record_visible = true;
    StippleRenderer renderer(context, kColorFormat, context.depth_format, options);
    for (size_t i = 0; i < objects.size(); ++i) {
        ObjectParams params = scene.objects[i].params;
        params.density_path = density_on_cpu(params.density_path) ? DensityPath::CpuSplat : DensityPath::Splat;
        renderer.add_object(*objects[i].mesh, *objects[i].stipples, scene.objects[i].transform.to_matrix(), params);
    }
    OffscreenTarget target(context, view.extent);
    target.draw(renderer, view);

    plot::Drawing drawing;
    drawing.width_px = view.extent.width;
    drawing.height_px = view.extent.height;
    drawing.ink = view.ink_color;
    drawing.paper = view.paper_color;
    for (size_t i = 0; i < objects.size(); ++i) {
        const ObjectGpu& object = renderer.object(i);
        drawing.objects.push_back({std::filesystem::path(scene.objects[i].model).stem().string(), object.frame.line_width});
        const std::vector<uint32_t>& first = object.geometry.first_stipple;
        const float radius = stipple_ink_radius(object.params.point_size);  // the same ink as on screen
        for (const gpu::VisibleStipple& s : renderer.read_visible_stipples(i)) {
            // The polygon whose candidates hold this index.
            const uint32_t polygon = uint32_t(std::upper_bound(first.begin(), first.end(), s.index) - first.begin() - 1);
            drawing.dots.push_back({{s.x, s.y}, radius, s.intensity, uint32_t(i), polygon});
        }
    }
    return drawing;
}

plot::PlotStats export_frame(const gpu::Context& context, const Scene& scene, const std::vector<ObjectData>& objects,
                             const FrameView& view, const plot::ExportOptions& options, const std::string& path) {
    const plot::PlotPlan plan = plot::make_plot_plan(capture_drawing(context, scene, objects, view), options);
    plot::write_plot_file(plan, path);
    return plot::plot_stats(plan);
}

}  // namespace stipple::app
