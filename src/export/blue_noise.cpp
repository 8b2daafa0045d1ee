#include "export/blue_noise.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace stipple::plot {

std::vector<glm::dvec2> poisson_disc_points(double width, double height, double spacing, uint32_t seed) {
    std::vector<glm::dvec2> points;
    if (!(width > 0.0) || !(height > 0.0) || !(spacing > 0.0)) return points;
    // A background grid of cells spacing/sqrt(2) wide holds at most one point each.
    const double cell = spacing / std::sqrt(2.0);
    const int cols = static_cast<int>(std::ceil(width / cell)), rows = static_cast<int>(std::ceil(height / cell));
    std::vector<int32_t> grid(static_cast<size_t>(cols) * rows, -1);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto cell_of = [&](glm::dvec2 p) {
        return glm::ivec2(std::min(cols - 1, static_cast<int>(p.x / cell)), std::min(rows - 1, static_cast<int>(p.y / cell)));
    };
    const auto fits = [&](glm::dvec2 p) {
        if (p.x < 0.0 || p.y < 0.0 || p.x >= width || p.y >= height) return false;
        const glm::ivec2 c = cell_of(p);
        for (int y = std::max(0, c.y - 2); y <= std::min(rows - 1, c.y + 2); ++y)
            for (int x = std::max(0, c.x - 2); x <= std::min(cols - 1, c.x + 2); ++x) {
                const int32_t other = grid[static_cast<size_t>(y) * cols + x];
                if (other < 0) continue;
                const glm::dvec2 d = points[other] - p;
                if (d.x * d.x + d.y * d.y < spacing * spacing) return false;
            }
        return true;
    };
    const auto add = [&](glm::dvec2 p) {
        const glm::ivec2 c = cell_of(p);
        grid[static_cast<size_t>(c.y) * cols + c.x] = static_cast<int32_t>(points.size());
        points.push_back(p);
    };

    add({unit(rng) * width, unit(rng) * height});
    std::vector<uint32_t> active{0};
    constexpr int kTries = 30;
    while (!active.empty()) {
        const size_t pick = static_cast<size_t>(unit(rng) * active.size()) % active.size();
        const glm::dvec2 centre = points[active[pick]];
        bool placed = false;
        for (int t = 0; t < kTries && !placed; ++t) {
            const double angle = 2.0 * std::numbers::pi * unit(rng);
            const double r = spacing * (1.0 + unit(rng));
            const glm::dvec2 p = centre + r * glm::dvec2(std::cos(angle), std::sin(angle));
            if (fits(p)) add(p), active.push_back(static_cast<uint32_t>(points.size() - 1)), placed = true;
        }
        if (!placed) {
            active[pick] = active.back();
            active.pop_back();
        }
    }
    return points;
}

double poisson_disc_spacing(double width, double height, size_t count) {
    // Dart throwing with 30 tries fills about 0.625 points per spacing^2.
    return std::sqrt(0.625 * width * height / static_cast<double>(std::max<size_t>(count, 1)));
}

}  // namespace stipple::plot
