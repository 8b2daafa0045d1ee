#include "render/silhouette_edges.hpp"

#include <algorithm>

namespace stipple {

std::vector<gpu::SilhouetteEdge> build_silhouette_edges(std::span<const uint32_t> indices) {
    struct HalfEdge {
        uint64_t key;  // smaller vertex << 32 | larger vertex
        uint32_t polygon;
    };
    const size_t triangles = indices.size() / 3;
    std::vector<HalfEdge> half_edges;
    half_edges.reserve(3 * triangles);
    for (size_t t = 0; t < triangles; ++t)
        for (int k = 0; k < 3; ++k) {
            uint32_t a = indices[3 * t + k], b = indices[3 * t + (k + 1) % 3];
            if (a == b) continue;  // a degenerate polygon's collapsed side is no edge
            half_edges.push_back({uint64_t(std::min(a, b)) << 32 | std::max(a, b), uint32_t(t)});
        }
    std::sort(half_edges.begin(), half_edges.end(), [](const HalfEdge& x, const HalfEdge& y) {
        return x.key != y.key ? x.key < y.key : x.polygon < y.polygon;
    });

    std::vector<gpu::SilhouetteEdge> edges;
    edges.reserve(half_edges.size() / 2 + 16);
    for (size_t begin = 0; begin < half_edges.size();) {
        size_t end = begin + 1;
        while (end < half_edges.size() && half_edges[end].key == half_edges[begin].key) ++end;
        const uint32_t v0 = uint32_t(half_edges[begin].key >> 32), v1 = uint32_t(half_edges[begin].key);
        for (size_t i = begin; i < end; i += 2) {
            uint32_t second = i + 1 < end ? half_edges[i + 1].polygon : gpu::kNoPolygon;
            edges.push_back({v0, v1, half_edges[i].polygon, second});
        }
        begin = end;
    }
    return edges;
}

}  // namespace stipple
