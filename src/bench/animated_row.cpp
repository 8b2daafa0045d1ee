#include "core/printf_string.hpp"
#include "bench/animated_row.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include "anim/procedural_rigs.hpp"
#include "core/error.hpp"
#include "gpu/context.hpp"
#include "render/camera.hpp"
#include "render/stipple_renderer.hpp"
#include "stipple/object_data.hpp"

namespace stipple::bench {

namespace {

constexpr double kAnimationFps = 30.0;  // animation seconds advance 1/30 per timed frame

struct Timing {
    double frame_ms = 0.0, gpu_ms = 0.0, deform_ms = 0.0;
    std::string passes;  // "deform 6.05 density 1.20 ...": the median of each pass
};

// Warm-up and timed frames as the cells time them; an animated object moves on 1/30 s per frame.
Timing time_frames(OffscreenTarget& target, StippleRenderer& renderer, const FrameView& view, const BenchOptions& options) {
    std::vector<double> frame_ms, gpu_ms, deform_ms;
    std::map<std::string, std::vector<double>> per_pass;
    std::vector<std::string> order;
    const int total = options.warmup + options.frames;
    for (int i = 0; i < total; ++i) {
        if (renderer.is_animated(0)) renderer.set_animation(0, 0, double(i) / kAnimationFps);
        const double ms = target.draw(renderer, view);
        if (i < options.warmup) continue;
        frame_ms.push_back(ms);
        double sum = 0.0, deform = 0.0;
        for (const auto& [pass, pass_ms] : renderer.stats().gpu_ms) {
            sum += pass_ms;
            if (pass == "skinning" || pass == "polygons") deform += pass_ms;  // the deformation pass's two halves
            if (!per_pass.count(pass)) order.push_back(pass);
            per_pass[pass].push_back(pass_ms);
        }
        gpu_ms.push_back(sum);
        deform_ms.push_back(deform);
    }
    std::string passes;
    for (const std::string& pass : order) passes += printf_string(" %s %.2f", pass.c_str(), median(per_pass[pass]));
    return {median(frame_ms), median(gpu_ms), median(deform_ms), passes};
}

int64_t counted_drawn(const gpu::Context& context, OffscreenTarget& target, const ObjectData& model,
                      const StippleSet& stipples, const FrameView& view, bool animated) {
    StippleRenderer renderer(context, kColorFormat, context.depth_format, RendererOptions{true});
    renderer.add_object(*model.mesh, stipples, glm::mat4(1.0f), ObjectParams{}, animated ? model.motion : anim::Motion{});
    target.draw(renderer, view);
    return renderer.stats().drawn_stipples;
}

}  // namespace

CylinderSize cylinder_size(uint32_t triangles) {
    CylinderSize size;
    size.segments = triangles >= 50'000 ? 256 : 64;
    const uint32_t caps = 2 * size.segments;
    const uint32_t per_ring = 2 * size.segments;
    size.rings = std::max<uint32_t>(2, (std::max(triangles, caps) - caps + per_ring - 1) / per_ring);
    return size;
}

AnimatedRow run_animated_row(const gpu::Context& context, OffscreenTarget& target, const BenchOptions& options,
                             const Logger& log) {
    const CylinderSize size = cylinder_size(options.animated_triangles);
    anim::rigs::CylinderOptions cylinder;
    cylinder.rings = size.rings;
    cylinder.segments = size.segments;
    const std::filesystem::path path =
        options.cache_dir / printf_string("animated-cylinder-%ux%u.glb", size.rings, size.segments);
    std::error_code ec;
    std::filesystem::create_directories(options.cache_dir, ec);
    anim::rigs::bending_cylinder(cylinder).write(path.string());

    const ObjectData model = load_model_data(path.string());
    if (!model.motion) fail_file(path.string(), "the generated cylinder has no animation");
    const ObjectParams params;  // the defaults, as every row
    check_generation_fits_memory(path.string(), planned_stipple_count(model, params.generation));
    const auto animated_stipples = make_stipples(model, params.generation);
    const auto static_stipples = make_stipples(*model.mesh, params.generation);  // the same surface, no headroom

    AnimatedRow row;
    row.model = printf_string("bending cylinder, 2 joints (%u rings x %u segments)", size.rings, size.segments);
    row.triangles = model.mesh->triangle_count();
    row.vertices = model.mesh->vertex_count();
    row.static_candidates = static_stipples->size();
    row.animated_candidates = animated_stipples->size();
    row.max_area_ratio = model.motion.headroom->max_ratio;

    const float aspect = float(target.extent().width) / float(target.extent().height);
    FrameView view;  // the standard view of every row, framed on every pose
    view.extent = target.extent();
    view.camera = camera_matrices(frame_sphere(model.bounds, aspect, kViewDistance, kViewYawDeg, kViewPitchDeg), aspect,
                                  model.bounds);

    row.static_drawn = counted_drawn(context, target, model, *static_stipples, view, false);
    row.animated_drawn = counted_drawn(context, target, model, *animated_stipples, view, true);
    {
        StippleRenderer renderer(context, kColorFormat, context.depth_format);
        renderer.add_object(*model.mesh, *static_stipples, glm::mat4(1.0f), params);
        const Timing t = time_frames(target, renderer, view, options);
        row.static_frame_ms = t.frame_ms;
        row.static_gpu_ms = t.gpu_ms;
        log("  static passes (GPU ms):" + t.passes);
    }
    {
        StippleRenderer renderer(context, kColorFormat, context.depth_format);
        renderer.add_object(*model.mesh, *animated_stipples, glm::mat4(1.0f), params, model.motion);
        const Timing t = time_frames(target, renderer, view, options);
        row.animated_frame_ms = t.frame_ms;
        row.animated_gpu_ms = t.gpu_ms;
        row.deform_gpu_ms = t.deform_ms;
        log("  animated passes (GPU ms):" + t.passes);
    }
    log(printf_string("animated row: %s, %llu triangles, %llu vertices; candidates %llu static, %llu with headroom "
               "(largest stretch %.2fx); drawn %lld static, %lld animated",
               row.model.c_str(), (unsigned long long)row.triangles, (unsigned long long)row.vertices,
               (unsigned long long)row.static_candidates, (unsigned long long)row.animated_candidates,
               double(row.max_area_ratio), (long long)row.static_drawn, (long long)row.animated_drawn));
    log(printf_string("  static   %8.2f ms/frame (%.1f fps), GPU %.2f ms", row.static_frame_ms, 1000.0 / row.static_frame_ms,
               row.static_gpu_ms));
    log(printf_string("  animated %8.2f ms/frame (%.1f fps), GPU %.2f ms of which deformation %.2f ms (%.1f%% of the GPU frame)",
               row.animated_frame_ms, 1000.0 / row.animated_frame_ms, row.animated_gpu_ms, row.deform_gpu_ms,
               100.0 * row.deform_share()));
    return row;
}

}  // namespace stipple::bench
