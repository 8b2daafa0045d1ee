#include "stipple/quality.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/parallel.hpp"
#include "stipple/point_grid.hpp"

namespace stipple {

double normalized_nn_distance(const std::vector<glm::vec3>& points, double surface_area) {
    const size_t n = points.size();
    if (n < 2 || !(surface_area > 0.0)) return 0.0;
    const double spacing = std::sqrt(2.0 / (std::sqrt(3.0) * static_cast<double>(n) / surface_area));

    // Cells of about the spacing: the nearest neighbour is usually within the 27 cells around a
    // point; the search widens ring by ring until the best distance is provably final.
    PointGrid grid;
    grid.build(points, static_cast<float>(spacing));
    const float cell = grid.cell_size();

    const size_t chunk = 4096;
    const size_t chunks = (n + chunk - 1) / chunk;
    std::vector<double> partial(chunks, 0.0);
    parallel_for_chunks(n, chunk, [&](size_t c, size_t begin, size_t end) {
        std::vector<uint32_t> buckets;
        double sum = 0.0;
        for (size_t i = begin; i < end; ++i) {
            const glm::vec3 p = points[i];
            const glm::ivec3 home = grid.cell_of(p);
            float best2 = std::numeric_limits<float>::infinity();
            for (int ring = 1;; ++ring) {
                // Everything within ring * cell of p lies in the cells within `ring` of home.
                grid.buckets_in_box(home - glm::ivec3(ring), home + glm::ivec3(ring), buckets);
                for (uint32_t b : buckets) {
                    for (uint32_t s = grid.bucket_begin(b); s < grid.bucket_end(b); ++s) {
                        if (grid.sorted_index(s) == i) continue;
                        const glm::vec3 d = grid.sorted_position(s) - p;
                        best2 = std::min(best2, glm::dot(d, d));
                    }
                }
                const float reach = static_cast<float>(ring) * cell;
                if (best2 <= reach * reach) break;
                // Every bucket visited: nothing closer can exist (also ends the loop for NaN input).
                if (buckets.size() >= grid.bucket_count()) break;
            }
            sum += std::sqrt(static_cast<double>(best2));
        }
        partial[c] = sum;
    });
    double total = 0.0;
    for (double s : partial) total += s;  // chunk order: deterministic
    return total / static_cast<double>(n) / spacing;
}

std::vector<glm::vec3> prefix_at_fraction(const StippleSet& stipples, double fraction) {
    std::vector<glm::vec3> out;
    const size_t triangles = stipples.first.empty() ? 0 : stipples.first.size() - 1;
    for (size_t t = 0; t < triangles; ++t) {
        const uint32_t n = stipples.count(t);
        for (uint32_t k = 0; k < n && k + 0.5 < fraction * n; ++k) out.push_back(stipples.positions[stipples.first[t] + k]);
    }
    return out;
}

}  // namespace stipple
