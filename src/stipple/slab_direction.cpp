#include "stipple/slab_direction.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/parallel.hpp"

namespace stipple {

double SlabRule::wanted_width(double object_size) const {
    return std::max(object_size / slabs, min_slab_searches * search_cap * spacing);
}

float SlabRule::split_extent(double object_size) const {
    return static_cast<float>(0.5 * (wanted_width(object_size) - search_cap * spacing));
}

double SlabRule::slab_count(double object_size) const { return std::ceil(object_size / wanted_width(object_size)); }

namespace {

constexpr size_t kChunk = 4096;  // triangles per chunk of the parallel passes
constexpr int kAcross = 4;       // directions tried across the cut triangles' common one

// The centroid of triangle t's stipples (the same float arithmetic wherever it is needed: nothing per
// triangle is kept but the chosen direction's centre and extent, 8 bytes a triangle, as before 2026-12-05).
glm::vec3 centroid(std::span<const glm::vec3> positions, std::span<const uint32_t> first, size_t t) {
    const uint32_t b = first[t], e = first[t + 1];
    glm::vec3 sum(0.0f);
    for (uint32_t i = b; i < e; ++i) sum += positions[i];
    return sum / float(e - b);
}

// How many stipples lie in triangles reaching farther than split[k] along directions[k] from their
// centroids, for up to four directions in one pass (counts summed per chunk, in chunk order).
template <size_t N>
std::array<uint64_t, N> stipples_cut(const std::array<glm::vec3, N>& directions, const std::array<float, N>& split,
                                     std::span<const glm::vec3> positions, std::span<const uint32_t> first) {
    const size_t triangles = first.size() - 1;
    std::vector<std::array<uint64_t, N>> per_chunk((triangles + kChunk - 1) / kChunk);
    parallel_for_chunks(triangles, kChunk, [&](size_t chunk, size_t begin, size_t end) {
        std::array<uint64_t, N> cut{};
        for (size_t t = begin; t < end; ++t) {
            const uint32_t b = first[t], e = first[t + 1];
            if (b == e) continue;
            const glm::vec3 m = centroid(positions, first, t);
            std::array<float, N> reach{};
            for (uint32_t i = b; i < e; ++i)
                for (size_t k = 0; k < N; ++k) reach[k] = std::max(reach[k], std::abs(glm::dot(positions[i] - m, directions[k])));
            for (size_t k = 0; k < N; ++k)
                if (reach[k] > split[k]) cut[k] += e - b;
        }
        per_chunk[chunk] = cut;
    });
    std::array<uint64_t, N> total{};
    for (const std::array<uint64_t, N>& cut : per_chunk)
        for (size_t k = 0; k < N; ++k) total[k] += cut[k];
    return total;
}

// The stipples' least coordinate along unit direction d, and their span.
std::pair<float, double> span_along(glm::vec3 d, std::span<const glm::vec3> positions) {
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (const glm::vec3& p : positions) lo = std::min(lo, glm::dot(p, d)), hi = std::max(hi, glm::dot(p, d));
    return {lo, double(hi) - double(lo)};
}

// The direction the triangles reaching farther than `split` along d share: the principal eigenvector of
// the sum, weighted by their counts, of r r^T over the unit vectors r from their centroids to their
// farthest stipples (power iteration). Zero when there is none.
glm::vec3 cut_triangles_direction(glm::vec3 d, float split, std::span<const glm::vec3> positions,
                                  std::span<const uint32_t> first) {
    glm::mat3 spread(0.0f);
    for (size_t t = 0; t + 1 < first.size(); ++t) {
        const uint32_t b = first[t], e = first[t + 1];
        if (b == e) continue;
        const glm::vec3 m = centroid(positions, first, t);
        float along = 0.0f;
        glm::vec3 reach(0.0f);
        for (uint32_t i = b; i < e; ++i) {
            const glm::vec3 r = positions[i] - m;
            along = std::max(along, std::abs(glm::dot(r, d)));
            if (glm::dot(r, r) > glm::dot(reach, reach)) reach = r;
        }
        if (along > split && glm::dot(reach, reach) > 0.0f) {
            const glm::vec3 r = glm::normalize(reach);
            spread += float(e - b) * glm::outerProduct(r, r);
        }
    }
    glm::vec3 along = spread[0] + spread[1] + spread[2] + glm::vec3(1e-3f, 2e-3f, 3e-3f);  // not across it
    for (int i = 0; i <= 32; ++i) {
        const float norm = glm::length(along);
        if (!(norm > 0.0f) || !std::isfinite(norm)) return glm::vec3(0.0f);
        along /= norm;
        if (i < 32) along = spread * along;
    }
    return along;
}

}  // namespace

SlabDirection choose_slab_direction(std::span<const glm::vec3> positions, std::span<const uint32_t> first,
                                    const SlabRule& rule) {
    SlabDirection choice;
    if (positions.empty() || first.size() < 2) return choice;
    const size_t triangles = first.size() - 1;
    glm::vec3 lo = positions[0], hi = positions[0];
    for (const glm::vec3& p : positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const glm::vec3 size = hi - lo;

    // The axes, longest first (ties by x, y, z). One across which the object is too thin for two slabs (a
    // plane seen edge-on: nothing cut, one slab, one core) is not taken while the longest gives two.
    std::array<int, 3> axes = {0, 1, 2};
    std::stable_sort(axes.begin(), axes.end(), [&](int a, int b) { return size[a] > size[b]; });
    const double fewest_slabs = std::min(2.0, rule.slab_count(size[axes[0]]));
    std::array<glm::vec3, 3> unit{};
    std::array<float, 3> split{};
    for (int k = 0; k < 3; ++k) unit[k][axes[k]] = 1.0f, split[k] = rule.split_extent(size[axes[k]]);
    const std::array<uint64_t, 3> cut = stipples_cut(unit, split, positions, first);
    int best = 0;
    for (int k = 1; k < 3; ++k)
        if (rule.slab_count(size[axes[k]]) >= fewest_slabs && cut[k] < cut[best]) best = k;
    choice.direction = unit[best];
    choice.lo = lo[axes[best]];
    choice.size = size[axes[best]];
    choice.cut_stipples = cut[best];

    // Slivers along no axis (a CAD part's tilted pipe) are cut by every axis: the directions across the
    // cut triangles' common direction are tried, and the one cutting the fewest taken where it cuts at
    // most half what the axis does (a cylinder's fanned caps are cut about the same across any direction
    // of their plane; an axis keeps its exact coordinates). With one slab a cut triangle is one piece anyway.
    if (choice.cut_stipples > 0 && fewest_slabs >= 2.0) {
        const glm::vec3 along = cut_triangles_direction(choice.direction, split[best], positions, first);
        if (along != glm::vec3(0.0f)) {
            const glm::vec3 a = glm::abs(along);
            const glm::vec3 least = a.x <= a.y && a.x <= a.z ? glm::vec3(1, 0, 0) : (a.y <= a.z ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1));
            const glm::vec3 u0 = glm::normalize(glm::cross(along, least)), u1 = glm::cross(along, u0);
            std::array<glm::vec3, kAcross> across{};
            std::array<float, kAcross> across_split{};
            std::array<std::pair<float, double>, kAcross> spans{};
            for (int k = 0; k < kAcross; ++k) {
                const double angle = 3.141592653589793 * k / kAcross;
                across[k] = float(std::cos(angle)) * u0 + float(std::sin(angle)) * u1;
                spans[k] = span_along(across[k], positions);
                across_split[k] = rule.split_extent(spans[k].second);
            }
            const std::array<uint64_t, kAcross> across_cut = stipples_cut(across, across_split, positions, first);
            int fewest = -1;
            for (int k = 0; k < kAcross; ++k)
                if (rule.slab_count(spans[k].second) >= fewest_slabs && (fewest < 0 || across_cut[k] < across_cut[fewest]))
                    fewest = k;
            if (fewest >= 0 && 2 * across_cut[fewest] <= choice.cut_stipples) {
                choice.direction = across[fewest];
                choice.lo = spans[fewest].first;
                choice.size = spans[fewest].second;
                choice.cut_stipples = across_cut[fewest];
            }
        }
    }

    // The chosen direction's centre and reach per triangle, for the slabs.
    choice.centre.assign(triangles, 0.0f);
    choice.extent.assign(triangles, 0.0f);
    parallel_for_chunks(triangles, kChunk, [&](size_t, size_t begin, size_t end) {
        for (size_t t = begin; t < end; ++t) {
            if (first[t] == first[t + 1]) continue;
            const glm::vec3 m = centroid(positions, first, t);
            choice.centre[t] = glm::dot(m, choice.direction);
            for (uint32_t i = first[t]; i < first[t + 1]; ++i)
                choice.extent[t] = std::max(choice.extent[t], std::abs(glm::dot(positions[i] - m, choice.direction)));
        }
    });
    return choice;
}

}  // namespace stipple
