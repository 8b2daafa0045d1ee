#include "export/nearest_alive_grid.hpp"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

namespace stipple::plot {

NearestAliveGrid::NearestAliveGrid(std::span<const glm::dvec2> points) : points_(points) {
    const size_t n = points.size();
    slot_.assign(n, kNone);
    cell_of_.assign(n, 0);
    alive_count_ = n;
    glm::dvec2 lo(0.0), hi(0.0);
    if (n > 0) {
        lo = hi = points[0];
        for (const glm::dvec2& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
    }
    origin_ = lo;
    const glm::dvec2 extent = hi - lo;
    // About two points a cell over the bounding box; a degenerate (flat) box gets cells along its
    // long side. The cell count stays within a few times the point count either way.
    const double area = extent.x * extent.y;
    const double longest = std::max(extent.x, extent.y);
    cell_ = area > 0.0 ? std::sqrt(2.0 * area / static_cast<double>(std::max<size_t>(n, 1)))
                       : (longest > 0.0 ? 2.0 * longest / static_cast<double>(std::max<size_t>(n, 1)) : 1.0);
    cell_ = std::max(cell_, longest * 1e-6 + 1e-12);
    cols_ = std::max(1, static_cast<int>(std::min(extent.x / cell_, 4.0 * n + 1.0)) + 1);
    rows_ = std::max(1, static_cast<int>(std::min(extent.y / cell_, 4.0 * n + 1.0)) + 1);
    while (static_cast<double>(cols_) * rows_ > 8.0 * n + 16.0) {  // only a flat box gets here
        cell_ *= 2.0;
        cols_ = static_cast<int>(extent.x / cell_) + 1;
        rows_ = static_cast<int>(extent.y / cell_) + 1;
    }

    const size_t cells = static_cast<size_t>(cols_) * rows_;
    cell_alive_.assign(cells, 0);
    row_alive_.assign(rows_, 0);
    for (size_t i = 0; i < n; ++i) {
        const int x = std::clamp(static_cast<int>((points[i].x - origin_.x) / cell_), 0, cols_ - 1);
        const int y = std::clamp(static_cast<int>((points[i].y - origin_.y) / cell_), 0, rows_ - 1);
        cell_of_[i] = static_cast<uint32_t>(y) * cols_ + x;
        ++cell_alive_[cell_of_[i]];
        ++row_alive_[y];
    }
    cell_start_.assign(cells + 1, 0);
    for (size_t c = 0; c < cells; ++c) cell_start_[c + 1] = cell_start_[c] + cell_alive_[c];
    items_.resize(n);
    std::vector<uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
    for (size_t i = 0; i < n; ++i) {
        slot_[i] = fill[cell_of_[i]]++;
        items_[slot_[i]] = static_cast<uint32_t>(i);
    }
}

void NearestAliveGrid::remove(uint32_t i) {
    const uint32_t slot = slot_[i];
    if (slot == kNone) return;
    // Swap the last live point of the cell into the hole, so live points stay packed.
    const uint32_t cell = cell_of_[i];
    const uint32_t last = cell_start_[cell] + --cell_alive_[cell];
    const uint32_t moved = items_[last];
    items_[slot] = moved;
    slot_[moved] = slot;
    items_[last] = i;
    slot_[i] = kNone;
    --row_alive_[cell / cols_];
    --alive_count_;
}

void NearestAliveGrid::scan_cell(int x, int y, glm::dvec2 q, uint32_t& best, double& best_d2) const {
    const uint32_t cell = static_cast<uint32_t>(y) * cols_ + x;
    const uint32_t begin = cell_start_[cell], end = begin + cell_alive_[cell];
    for (uint32_t s = begin; s < end; ++s) {
        const uint32_t i = items_[s];
        const glm::dvec2 d = points_[i] - q;
        const double d2 = d.x * d.x + d.y * d.y;
        if (d2 < best_d2 || (d2 == best_d2 && i < best)) best = i, best_d2 = d2;
    }
}

uint32_t NearestAliveGrid::nearest(glm::dvec2 q) const {
    if (alive_count_ == 0) return kNone;
    // q's cell, possibly outside the grid. Every cell on the square ring r around it is at least
    // (r - 1) cells away from q, which bounds the search once a candidate is known.
    const glm::dvec2 rel = (q - origin_) / cell_;
    const double limit = 1e8;  // keeps the cell index an int for any q
    const int qx = static_cast<int>(std::floor(std::clamp(rel.x, -limit, limit)));
    const int qy = static_cast<int>(std::floor(std::clamp(rel.y, -limit, limit)));
    const int first_ring = std::max({0, -qx, qx - (cols_ - 1), -qy, qy - (rows_ - 1)});
    const int last_ring = std::max({qx, cols_ - 1 - qx, qy, rows_ - 1 - qy});

    uint32_t best = kNone;
    double best_d2 = std::numeric_limits<double>::infinity();
    for (int r = first_ring; r <= last_ring; ++r) {
        if (best != kNone) {
            const double reach = (r - 1) * cell_;
            if (reach > 0.0 && reach * reach >= best_d2) break;
        }
        const int y0 = std::max(0, qy - r), y1 = std::min(rows_ - 1, qy + r);
        const int x0 = std::max(0, qx - r), x1 = std::min(cols_ - 1, qx + r);
        for (int y = y0; y <= y1; ++y) {
            if (row_alive_[y] == 0) continue;
            if (y == qy - r || y == qy + r) {
                for (int x = x0; x <= x1; ++x) scan_cell(x, y, q, best, best_d2);
            } else {
                if (qx - r >= 0) scan_cell(qx - r, y, q, best, best_d2);
                if (r > 0 && qx + r < cols_) scan_cell(qx + r, y, q, best, best_d2);
            }
        }
    }
    return best;
}

}  // namespace stipple::plot
