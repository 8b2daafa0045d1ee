#include "render/polygon_constants.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/packing.hpp>

#include "render/density_formulas.hpp"
#include "render/path_buffers.hpp"
#include "render/shared_types.hpp"
#include "stipple/selection_order.hpp"
#include "stipple/stipple_cache.hpp"

namespace stipple {

namespace {

uint32_t unorm16(float value) { return uint32_t(std::lround(std::clamp(value, 0.0f, 1.0f) * 65535.0f)); }

}  // namespace

std::vector<gpu::TriangleInfo> pack_polygon_constants(const Mesh& mesh, const std::vector<float>& selection,
                                                      glm::vec3 box_min, glm::vec3 box_size) {
    std::vector<gpu::TriangleInfo> infos(mesh.triangle_count());
    const glm::vec3 inverse_size = glm::vec3(1.0f) / glm::max(box_size, glm::vec3(1e-30f));
    for (size_t t = 0; t < infos.size(); ++t) {
        // In double: the squared length of a cross product overflows single precision for triangles
        // beyond about 1e9 units across (the loader accepts coordinates up to mesh.hpp kMaxCoordinate),
        // which made the normal NaN.
        const glm::dvec3 a = mesh.positions[mesh.indices[3 * t]];
        const glm::dvec3 b = mesh.positions[mesh.indices[3 * t + 1]];
        const glm::dvec3 c = mesh.positions[mesh.indices[3 * t + 2]];
        const glm::dvec3 cross = glm::cross(b - a, c - a);
        const double length = glm::length(cross);
        const glm::vec3 normal = length > 0.0 ? glm::vec3(cross / length) : glm::vec3(0.0f, 0.0f, 1.0f);
        const glm::vec3 center = (glm::vec3((a + b + c) / 3.0) - box_min) * inverse_size;
        infos[t].center_xy = unorm16(center.x) | unorm16(center.y) << 16;
        infos[t].center_z_selection = unorm16(center.z) | uint32_t(selection_step(selection[t])) << 16;
        infos[t].normal = glm::packSnorm2x16(formulas::unit_to_octahedral(normal));
        infos[t].area = float(0.5 * length);
    }
    return infos;
}

PolygonConstants compute_polygon_constants(const Mesh& mesh, const StippleSet& stipples, uint64_t seed,
                                           const Bounds* quantisation_box) {
    PolygonConstants polygons;
    polygons.bounds = compute_bounding_sphere(mesh);
    polygons.origin = glm::vec3(mesh.origin);
    const Bounds box = quantisation_box ? *quantisation_box : compute_bounds(mesh);
    polygons.box_min = box.min;
    polygons.box_size = box.max - box.min;
    const std::vector<float> selection = stipples.selection.size() == mesh.triangle_count()
                                             ? stipples.selection
                                             : polygon_selection_values(mesh, stipples, seed);
    polygons.cpu = pack_polygon_constants(mesh, selection, polygons.box_min, polygons.box_size);
    polygons.corner_positions = mesh.positions;
    polygons.corner_indices = mesh.indices;
    return polygons;
}

}  // namespace stipple
