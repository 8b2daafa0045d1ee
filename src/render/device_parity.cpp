#include "render/device_parity.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

#include "core/error.hpp"
#include "gpu/context.hpp"
#include "render/camera.hpp"
#include "render/offscreen.hpp"
#include "render/stipple_renderer.hpp"
#include "render/tone_survey.hpp"

namespace stipple {

std::vector<ParityView> parity_views(int yaws, const std::vector<DensityPath>& paths) {
    std::vector<ParityView> views;
    for (DensityPath path : paths)
        for (float pitch : {15.0f, -20.0f})
            for (int i = 0; i < yaws; ++i) views.push_back({360.0f * float(i) / float(yaws), pitch, path});
    return views;
}

DeviceRun run_parity_views(const gpu::Context& context, const Mesh& mesh, const StippleSet& stipples,
                           const Sphere& bounds, const ObjectParams& params, VkExtent2D extent,
                           const std::vector<ParityView>& views, const anim::Motion& motion) {
    RendererOptions options;
    options.count_drawn = true;
    StippleRenderer renderer(context, kColorFormat, context.depth_format, options);
    renderer.add_object(mesh, stipples, glm::mat4(1.0f), params, motion);
    OffscreenTarget target(context, extent);
    const float aspect = float(extent.width) / float(extent.height);
    DeviceRun run;
    run.device = context.device_name;
    for (const ParityView& v : views) {
        renderer.params(0).density_path = v.path;
        FrameView view;
        view.extent = extent;
        view.camera = camera_matrices(frame_sphere(bounds, aspect, 1.0f, v.yaw_deg, v.pitch_deg), aspect, bounds);
        const RenderedFrame frame = target.render(renderer, view);
        ParitySample sample;
        sample.drawn = renderer.stats().drawn_stipples;
        sample.mean_ink = measure_ink(frame).mean();
        sample.mask = renderer.drawn_mask(0);
        run.samples.push_back(std::move(sample));
    }
    return run;
}

namespace {

double relative(double a, double b) {
    if (a == b) return 0.0;
    return std::abs(a - b) / std::max(std::abs(a), 1e-12);
}

}  // namespace

ParityReport compare_parity(const DeviceRun& a, const DeviceRun& b, const std::vector<ParityView>& views) {
    STIPPLE_CHECK(a.samples.size() == views.size() && b.samples.size() == views.size(),
                  "compare_parity: one sample per view on each device");
    ParityReport report;
    for (size_t i = 0; i < views.size(); ++i) {
        const ParitySample& sa = a.samples[i];
        const ParitySample& sb = b.samples[i];
        ParityRow row;
        row.view = views[i];
        row.drawn_a = sa.drawn;
        row.drawn_b = sb.drawn;
        row.count_difference = relative(double(sa.drawn), double(sb.drawn));
        size_t only_one = 0;
        for (size_t w = 0; w < std::max(sa.mask.size(), sb.mask.size()); ++w) {
            const uint32_t wa = w < sa.mask.size() ? sa.mask[w] : 0u, wb = w < sb.mask.size() ? sb.mask[w] : 0u;
            only_one += size_t(std::popcount(wa ^ wb));
        }
        row.set_difference = sa.drawn > 0 ? double(only_one) / double(sa.drawn) : double(only_one);
        row.ink_a = sa.mean_ink;
        row.ink_b = sb.mean_ink;
        row.ink_difference = relative(sa.mean_ink, sb.mean_ink);
        report.worst_count = std::max(report.worst_count, row.count_difference);
        report.worst_set = std::max(report.worst_set, row.set_difference);
        report.worst_ink = std::max(report.worst_ink, row.ink_difference);
        report.rows.push_back(row);
    }
    return report;
}

}  // namespace stipple
