#include "render/silhouette_edges.hpp"

#include <algorithm>
#include <cstring>
#include <unordered_map>

namespace stipple {

std::vector<uint32_t> weld_by_position(std::span<const glm::vec3> positions) {
    struct Key {
        uint32_t bits[3];
        bool operator==(const Key& other) const { return std::memcmp(bits, other.bits, sizeof bits) == 0; }
    };
    struct Hash {
        size_t operator()(const Key& k) const {
            return (size_t(k.bits[0]) * 0x9E3779B97F4A7C15ull) ^ (size_t(k.bits[1]) * 0xC2B2AE3D27D4EB4Full) ^
                   (size_t(k.bits[2]) * 0x165667B19E3779F9ull);
        }
    };
    std::unordered_map<Key, uint32_t, Hash> first;
    first.reserve(positions.size());
    std::vector<uint32_t> representative(positions.size());
    for (size_t v = 0; v < positions.size(); ++v) {
        glm::vec3 p = positions[v] + glm::vec3(0.0f);  // -0 and +0 are one position
        Key key;
        std::memcpy(key.bits, &p, sizeof key.bits);
        representative[v] = first.emplace(key, uint32_t(v)).first->second;
    }
    return representative;
}

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
