#include "stipple/selection_order.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <unordered_map>

#include "core/hash.hpp"

namespace stipple {

namespace {

// Ranked centroids in cubic cells of the current level's radius.
class RankedGrid {
public:
    RankedGrid(float cell, size_t expected) : inv_cell_(1.0f / cell), radius2_(cell * cell) { cells_.reserve(expected); }

    void insert(const glm::vec3& p) { cells_[key(cell_of(p))].push_back(p); }

    bool any_within(const glm::vec3& p) const {
        glm::ivec3 c = cell_of(p);
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    auto it = cells_.find(key(c + glm::ivec3(dx, dy, dz)));
                    if (it == cells_.end()) continue;
                    for (const glm::vec3& q : it->second)
                        if (glm::dot(q - p, q - p) < radius2_) return true;
                }
        return false;
    }

private:
    glm::ivec3 cell_of(const glm::vec3& p) const { return glm::ivec3(glm::floor(p * inv_cell_)); }
    static uint64_t key(const glm::ivec3& c) {
        return (uint64_t(uint32_t(c.x) & 0x1FFFFF) << 42) | (uint64_t(uint32_t(c.y) & 0x1FFFFF) << 21) |
               uint64_t(uint32_t(c.z) & 0x1FFFFF);
    }
    float inv_cell_;
    float radius2_;
    std::unordered_map<uint64_t, std::vector<glm::vec3>> cells_;
};

// Triangles in classes of about the same area (within kClassRatio of the class's smallest); in each
// class of n the k-th in the order of `scaled` (the blue-noise rank) gets a value in [k / n, (k + 1) / n),
// at a place in that step drawn per triangle. So every class holds exactly uniform values whatever
// the spread of triangle sizes (a lone large triangle among tiny ones included), P(value < p) = p for a
// triangle of any size, and the probabilistic selection's expected ink is the owed ink; within a class
// the blue-noise order is kept, so the selected triangles stay evenly spread.
void calibrate_by_area(const std::vector<double>& areas, const std::vector<double>& scaled, uint64_t seed,
                       std::vector<float>& values) {
    constexpr double kClassRatio = 1.19;  // 2^(1/4): p varies by under 10% across a class
    const size_t count = areas.size();
    std::vector<uint32_t> by_area(count);
    std::iota(by_area.begin(), by_area.end(), 0u);
    std::sort(by_area.begin(), by_area.end(),
              [&](uint32_t a, uint32_t b) { return areas[a] < areas[b] || (areas[a] == areas[b] && a < b); });
    const uint64_t key = mix64(seed ^ 0x53454C4543540001ull);
    size_t begin = 0;
    while (begin < count) {
        size_t end = begin;
        const double limit = areas[by_area[begin]] * kClassRatio;
        while (end < count && areas[by_area[end]] <= limit) ++end;
        std::sort(by_area.begin() + std::ptrdiff_t(begin), by_area.begin() + std::ptrdiff_t(end),
                  [&](uint32_t a, uint32_t b) { return scaled[a] < scaled[b] || (scaled[a] == scaled[b] && a < b); });
        const double n = double(end - begin);
        for (size_t k = begin; k < end; ++k) {
            const uint32_t t = by_area[k];
            const double within = double(mix64(key ^ t) >> 11) * 0x1p-53;
            const double value = std::min((double(k - begin) + within) / n, 1.0 - 1.0 / 16777216.0);
            values[t] = float(std::floor(value * 16777216.0)) * (1.0f / 16777216.0f);  // a multiple of 2^-24
        }
        begin = end;
    }
}

}  // namespace

std::vector<float> polygon_selection_values(const Mesh& mesh, uint64_t seed) {
    const size_t count = mesh.triangle_count();
    std::vector<float> values(count, 0.0f);
    if (count == 0) return values;

    std::vector<glm::vec3> centroids(count);
    for (size_t t = 0; t < count; ++t)
        centroids[t] = (mesh.positions[mesh.indices[3 * t]] + mesh.positions[mesh.indices[3 * t + 1]] +
                        mesh.positions[mesh.indices[3 * t + 2]]) / 3.0f;
    const double area = std::max(total_area(mesh), 1e-30);

    std::vector<uint32_t> remaining(count);
    std::iota(remaining.begin(), remaining.end(), 0u);
    std::mt19937_64 rng(seed ^ 0x9E3779B97F4A7C15ull);
    std::shuffle(remaining.begin(), remaining.end(), rng);

    std::vector<uint32_t> ranked;
    ranked.reserve(count);
    // Level L aims at 2^L ranked centroids: Poisson-disc radius 0.75 x the hexagonal spacing of that
    // many points. Each level examines at most 8x its target, so the whole order costs O(count).
    for (size_t target = 1; target < count && !remaining.empty(); target *= 2) {
        float radius = float(0.75 * std::sqrt(2.0 * area / (std::sqrt(3.0) * double(target))));
        RankedGrid grid(radius, target * 2);
        for (uint32_t t : ranked) grid.insert(centroids[t]);
        size_t budget = std::min(remaining.size(), 8 * target);
        std::vector<uint32_t> rejected;
        for (size_t i = 0; i < budget; ++i) {
            uint32_t t = remaining[i];
            if (grid.any_within(centroids[t])) {
                rejected.push_back(t);
            } else {
                ranked.push_back(t);
                grid.insert(centroids[t]);
            }
        }
        // Unexamined centroids go first at the next level, then the rejected ones.
        std::vector<uint32_t> next(remaining.begin() + budget, remaining.end());
        next.insert(next.end(), rejected.begin(), rejected.end());
        remaining.swap(next);
    }
    ranked.insert(ranked.end(), remaining.begin(), remaining.end());

    // The ranking is about uniform over the surface's area, so a triangle a times the mean area reaches a
    // given rank about a times as often as the mean one: rank / count x relative area is close to uniform
    // for every triangle. Only close: a triangle far smaller than the mean has a value below its relative
    // area whatever its rank (it would be selected for certain once p passes that), and one far larger is
    // ranked before its regular share once its region runs out of centroids. So the value is made exactly
    // uniform where it matters, among triangles of about the same area (calibrate_by_area).
    const double mean_area = area / double(count);
    std::vector<double> areas(count);
    std::vector<double> scaled(count);
    for (size_t rank = 0; rank < count; ++rank) {
        uint32_t t = ranked[rank];
        areas[t] = triangle_area(mesh, t);
        scaled[t] = double(rank) / double(count) * areas[t] / mean_area;
    }
    calibrate_by_area(areas, scaled, seed, values);
    return values;
}

}  // namespace stipple
