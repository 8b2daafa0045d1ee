#include "stipple/quality.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

#include <nanoflann.hpp>

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

namespace {

// The points in plane coordinates, for nanoflann.
struct PlanePoints {
    std::vector<glm::vec2> p;
    size_t kdtree_get_point_count() const { return p.size(); }
    float kdtree_get_pt(size_t i, size_t d) const { return p[i][int(d)]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const { return false; }
};

}  // namespace

HexagonalOrder hexagonal_order(const std::vector<glm::vec3>& points, const glm::vec3& normal, int windows,
                               double margin) {
    HexagonalOrder order;
    if (points.size() < 7 || windows < 1 || !(glm::length(normal) > 0.0f)) return order;
    // A frame of the plane: u, v perpendicular to the normal.
    const glm::vec3 n = glm::normalize(normal);
    const glm::vec3 helper = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 u = glm::normalize(glm::cross(n, helper)), v = glm::cross(n, u);
    PlanePoints plane;
    plane.p.reserve(points.size());
    glm::vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const glm::vec3& p : points) {
        plane.p.emplace_back(glm::dot(p, u), glm::dot(p, v));
        lo = glm::min(lo, plane.p.back()), hi = glm::max(hi, plane.p.back());
    }
    using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, PlanePoints>, PlanePoints, 2>;
    Tree tree(2, plane, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    tree.buildIndex();
    const glm::vec2 extent = hi - lo, inner_lo = lo + float(margin) * extent, inner_hi = hi - float(margin) * extent;
    std::vector<std::complex<double>> window_sum(size_t(windows) * windows);
    std::vector<size_t> window_count(window_sum.size(), 0);
    double local_sum = 0.0;
    size_t centres = 0;
    for (size_t i = 0; i < plane.p.size(); ++i) {
        const glm::vec2 p = plane.p[i];
        if (glm::any(glm::lessThan(p, inner_lo)) || glm::any(glm::greaterThan(p, inner_hi))) continue;
        uint32_t nearest[7];
        float distance2[7];
        const float query[2] = {p.x, p.y};
        if (tree.knnSearch(query, 7, nearest, distance2) < 7) continue;
        std::complex<double> psi(0.0);
        for (int k = 0; k < 7; ++k) {
            if (nearest[k] == i) continue;  // itself (among equals, any one of them)
            const glm::vec2 d = plane.p[nearest[k]] - p;
            psi += std::polar(1.0, 6.0 * std::atan2(double(d.y), double(d.x)));
        }
        psi /= 6.0;
        local_sum += std::abs(psi);
        ++centres;
        const glm::vec2 cell = (p - lo) / extent * float(windows);
        const size_t w = size_t(std::clamp(int(cell.y), 0, windows - 1)) * windows + size_t(std::clamp(int(cell.x), 0, windows - 1));
        window_sum[w] += psi, ++window_count[w];
    }
    if (centres == 0) return order;
    order.local = local_sum / double(centres);
    size_t used = 0;
    for (size_t w = 0; w < window_sum.size(); ++w)
        if (window_count[w] > 0) order.windowed += std::abs(window_sum[w] / double(window_count[w])), ++used;
    order.windowed /= double(used);
    return order;
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
