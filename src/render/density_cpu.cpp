#include "render/density_cpu.hpp"

#include <cmath>

#include "render/density_formulas.hpp"

namespace stipple {

void compute_densities_cpu(std::span<const gpu::TriangleInfo> triangles, std::span<const uint32_t> first_stipple,
                           const gpu::FrameUniforms& frame, const gpu::ObjectUniforms& object,
                           std::span<float> densities) {
    const formulas::DensityParams params = formulas::density_params(frame, object);
    for (size_t t = 0; t < triangles.size(); ++t) {
        float candidates = float(first_stipple[t + 1] - first_stipple[t]);
        densities[t] = formulas::polygon_density(formulas::polygon_view(triangles[t], candidates, object), params);
    }
}

uint32_t build_draw_commands(std::span<const float> densities, std::span<const uint32_t> first_stipple,
                             std::span<gpu::DrawCommand> commands) {
    uint32_t count = 0;
    for (size_t t = 0; t < densities.size(); ++t) {
        uint32_t drawn = uint32_t(std::ceil(densities[t]));
        if (drawn == 0) continue;
        // The rule of shaders/draw_commands.comp: join the previous draw while the polygon before drew
        // all of its candidates (its range then ends where this one starts), at most kMaxMergedPolygons.
        bool merges = t > 0 && t % gpu::kMaxMergedPolygons != 0 && count > 0;
        if (merges) {
            uint32_t previous = uint32_t(std::ceil(densities[t - 1]));
            merges = previous > 0 && previous == first_stipple[t] - first_stipple[t - 1];
        }
        if (merges)
            commands[count - 1].vertex_count += drawn;
        else
            commands[count++] = {drawn, 1u, first_stipple[t], 0u};
    }
    return count;
}

}  // namespace stipple
