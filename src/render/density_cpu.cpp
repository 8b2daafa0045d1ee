#include "render/density_cpu.hpp"

#include <cmath>
#include <cstring>
#include <vector>

#include "core/parallel.hpp"
#include "render/density_formulas.hpp"
#include "render/object_gpu.hpp"
#include "render/path_buffers.hpp"

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
        uint32_t drawn = formulas::drawn_stipple_count(densities[t], first_stipple[t + 1] - first_stipple[t]);
        if (drawn == 0) continue;
        // The rule of shaders/draw_commands.comp: join the previous draw while the polygon before drew
        // all of its candidates (its range then ends where this one starts), at most kMaxMergedPolygons.
        bool merges = t > 0 && t % gpu::kMaxMergedPolygons != 0 && count > 0;
        if (merges) {
            uint32_t previous = formulas::drawn_stipple_count(densities[t - 1], first_stipple[t] - first_stipple[t - 1]);
            merges = previous > 0 && previous == first_stipple[t] - first_stipple[t - 1];
        }
        if (merges)
            commands[count - 1].vertex_count += drawn;
        else
            commands[count++] = {drawn, 1u, first_stipple[t], 0u};
    }
    return count;
}

double run_cpu_density(ObjectGpu& object, const gpu::FrameUniforms& frame) {
    const ObjectGeometry& geometry = object.geometry;
    ObjectFrame& state = object.frame;
    std::vector<float> densities(geometry.triangle_count);
    auto* draws = static_cast<gpu::TriangleDraw*>(state.draw_staging.mapped());
    // Both cores: the GPU work of this frame has not been submitted yet, so the CPU is otherwise idle.
    parallel_for_chunks(densities.size(), 16384, [&](size_t, size_t begin, size_t end) {
        std::span<float> part(densities.data() + begin, end - begin);
        compute_densities_cpu(std::span(object.polygons.cpu).subspan(begin, end - begin),
                              std::span(geometry.first_stipple).subspan(begin, end - begin + 1), frame, state.uniforms,
                              part);
        for (size_t t = begin; t < end; ++t) draws[t] = {densities[t], geometry.first_stipple[t]};
    });
    double sum = 0.0;
    for (float d : densities) sum += d;
    if (draws_by_splat(object.params.density_path)) {
        auto* list = reinterpret_cast<uint32_t*>(static_cast<std::byte*>(state.draw_staging.mapped()) +
                                                 staged_list_offset(object));
        uint32_t* items = list + sizeof(gpu::DrawnPolygons) / sizeof(uint32_t);
        uint32_t count = 0;  // work items: runs of kSplatChunk drawn stipples (gpu::DrawnPolygons)
        for (uint32_t t = 0; t < geometry.triangle_count; ++t) {
            if (!(densities[t] > 0.0f)) continue;
            const uint32_t first = geometry.first_stipple[t];
            const uint32_t drawn = formulas::drawn_stipple_count(densities[t], geometry.first_stipple[t + 1] - first);
            for (uint32_t k = 0; k < drawn; k += gpu::kSplatChunk) items[count++] = first + k;
        }
        const uint32_t group = gpu::kDensityWorkgroupSize;
        const gpu::DrawnPolygons header{(count + group - 1) / group, 1u, 1u, count};
        std::memcpy(list, &header, sizeof header);
        state.cpu_drawn_polygons = count;
        state.cpu_command_count = 0;
    } else {
        auto* commands = static_cast<gpu::DrawCommand*>(state.cpu_commands.mapped());
        state.cpu_command_count =
            build_draw_commands(densities, geometry.first_stipple, std::span(commands, geometry.triangle_count));
        state.cpu_commands.flush();
    }
    state.draw_staging.flush();
    return sum;
}

}  // namespace stipple
