#include "render/density_cpu.hpp"

#include <cmath>
#include <cstring>
#include <vector>

#include "gpu/pipelines.hpp"
#include "core/parallel.hpp"
#include "render/density_formulas.hpp"
#include "render/object_gpu.hpp"
#include "render/path_buffers.hpp"

namespace {
// min_area is given for the default D_max (polygon_density_terms): the two must move together.
static_assert(stipple::formulas::kMinAreaDensity == stipple::GenerationParams{}.dmax, "kMinAreaDensity is the default D_max");
}  // namespace

namespace stipple {

void compute_densities_cpu(std::span<const gpu::TriangleInfo> triangles, std::span<const uint32_t> first_stipple,
                           size_t first_triangle, std::span<const glm::vec3> positions,
                           std::span<const uint32_t> indices, const gpu::FrameUniforms& frame,
                           const gpu::ObjectUniforms& object, std::span<float> densities,
                           std::span<glm::vec2> bounds) {
    const formulas::DensityParams params = formulas::density_params(frame, object);
    const bool cull = (object.flags.x & gpu::kFlagCullOutsideView) != 0u;
    const glm::vec2 slack = formulas::view_cull_slack(glm::vec2(frame.viewport), object.shading.y);
    for (size_t t = 0; t < triangles.size(); ++t) {
        float candidates = float(first_stipple[t + 1] - first_stipple[t]);
        const formulas::PolygonView view = formulas::polygon_view(triangles[t], candidates, object);
        const formulas::PolygonDensity terms = formulas::polygon_density_terms(view, params);
        densities[t] = formulas::selected_density(terms, view.selection);
        bounds[t] = glm::vec2(densities[t]);
        const uint32_t* corner = &indices[3 * (first_triangle + t)];
        if (cull) {  // as the density pass: wholly outside the view
            const glm::mat4& mvp = object.model_view_proj;
            const uint32_t center_bits =
                formulas::clip_outside_bits(mvp * glm::vec4(formulas::polygon_center_object(triangles[t], object), 1.0f), slack);
            if (center_bits != 0u &&
                formulas::triangle_outside_view(center_bits, mvp * glm::vec4(positions[corner[0]], 1.0f),
                                                mvp * glm::vec4(positions[corner[1]], 1.0f), mvp * glm::vec4(positions[corner[2]], 1.0f),
                                                slack)) {
                densities[t] = 0.0f;
                bounds[t] = glm::vec2(0.0f);
                continue;
            }
        }
        if (formulas::may_carry_gradient(terms, view, params, densities[t])) {  // as the density pass and its gradient pass
            auto in_view = [&](uint32_t i) { return glm::vec3(object.model_view * glm::vec4(positions[i], 1.0f)); };
            const glm::vec3 a = in_view(corner[0]), b = in_view(corner[1]), c = in_view(corner[2]);
            densities[t] = formulas::large_polygon_density(formulas::large_polygon_stored_density(terms, densities[t]), a, b,
                                                           c, params);
            bounds[t] = formulas::polygon_density_bounds(densities[t], a, b, c, params);
            if (bounds[t].x != bounds[t].y) continue;  // each stipple decided where it lies (drawn_intensity)
        }
        // Drawn flat: its last stipple solid or absent (solid_dots_density).
        densities[t] = formulas::solid_dots_density(densities[t], candidates, view.selection, params.flags);
        bounds[t] = glm::vec2(densities[t]);
    }
}

double run_cpu_density(ObjectGpu& object, const gpu::FrameUniforms& frame, uint32_t max_groups_x) {
    const ObjectGeometry& geometry = object.geometry;
    ObjectFrame& state = object.frame;
    std::vector<float> densities(geometry.triangle_count);
    std::vector<glm::vec2> bounds(geometry.triangle_count);
    auto* draws = static_cast<gpu::TriangleDraw*>(state.draw_staging.mapped());
    // Both cores: the GPU work of this frame has not been submitted yet, so the CPU is otherwise idle.
    parallel_for_chunks(densities.size(), 16384, [&](size_t, size_t begin, size_t end) {
        std::span<float> part(densities.data() + begin, end - begin);
        compute_densities_cpu(std::span(object.polygons.cpu).subspan(begin, end - begin),
                              std::span(geometry.first_stipple).subspan(begin, end - begin + 1), begin,
                              object.polygons.corner_positions, object.polygons.corner_indices, frame, state.uniforms,
                              part, std::span(bounds).subspan(begin, end - begin));
        for (size_t t = begin; t < end; ++t)
            draws[t] = {densities[t], geometry.first_stipple[t], bounds[t].x, bounds[t].y};
    });
    double sum = 0.0;
    for (float d : densities) sum += d;
    auto* list = reinterpret_cast<uint32_t*>(static_cast<std::byte*>(state.draw_staging.mapped()) +
                                             staged_list_offset(object));
    uint32_t count = 0;
    // Each polygon that draws this frame: its first candidate, its drawn stipples and its splat dots' side.
    const float point_size = object.frame.uniforms.shading.y;
    auto for_each_drawing_polygon = [&](auto&& visit) {
        for (uint32_t t = 0; t < geometry.triangle_count; ++t) {
            if (!(densities[t] > 0.0f)) continue;
            const uint32_t first = geometry.first_stipple[t], candidates = geometry.first_stipple[t + 1] - first;
            // To the most density any of its stipples sees (the vertex shader and the splat cull the rest).
            visit(first, formulas::drawn_stipple_count(bounds[t].y, candidates),
                  formulas::splat_dot_side(point_size, bounds[t].y, float(candidates)));
        }
    };
    if (draws_by_splat(object.params.density_path)) {  // runs of splat_run_length drawn stipples
        uint32_t* items = list + sizeof(gpu::DrawnPolygons) / sizeof(uint32_t);
        for_each_drawing_polygon([&](uint32_t first, uint32_t drawn, float side) {
            const uint32_t run = formulas::splat_run_length(drawn, side, point_size);
            for (uint32_t k = 0; k < drawn; k += run) items[count++] = first + k;
        });
        const uint32_t group = gpu::kDensityWorkgroupSize;
        const gpu::GroupGrid grid = gpu::split_groups((uint64_t(count) + group - 1) / group, max_groups_x);
        const gpu::DrawnPolygons header{grid.x, grid.y, 1u, count};
        std::memcpy(list, &header, sizeof header);
    } else {
        uint32_t* stipples = list + sizeof(gpu::DrawCommand) / sizeof(uint32_t);  // the survivors, drawn as one
        for_each_drawing_polygon([&](uint32_t first, uint32_t drawn, float) {
            for (uint32_t k = 0; k < drawn; ++k) stipples[count++] = first + k;
        });
        const gpu::DrawCommand header{count, 1u, 0u, 0u};
        std::memcpy(list, &header, sizeof header);
    }
    state.cpu_listed = count;
    state.draw_staging.flush();
    return sum;
}

}  // namespace stipple
