#pragma once
// The distances the progressive order reads (progressive_order.cpp): each stipple of a slab keeps the
// squared distance to its nearest placed stipple, and every placed stipple pushes its distance to the
// stipples within its reach, in runs of neighbouring grid slots with a SIMD kernel chosen once for the
// machine (each variant does the same IEEE operations, so the order does not depend on it).
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "stipple/point_grid.hpp"

namespace stipple {

// The most stipples one placed stipple pushes its distance to. A surface puts a few thousand within the
// widest reach (progressive_order.cpp: kSearchCap spacings, cells of kPushCell); more means faces piled
// on each other.
constexpr size_t kMaxPushed = 65536;

// The own stipples of one slab in a static grid, each with the squared distance to its nearest
// placed stipple. Stipples are named by their slot in the grid (spatial order), so that a push
// writes runs of neighbouring slots rather than scattered memory.
class PushGrid {
public:
    // Cells of kPushCell spacings hold ~40 stipples: a bucket for every 8 stipples is plenty.
    PushGrid(std::span<const glm::vec3> points, float cell) : size_(points.size()) {
        grid_.build(points, cell, 1.0 / 8.0);
    }

    // Every stipple as far from any placed one as can be. Separate from the constructor so that these
    // 4 bytes a stipple are allocated once the positions the grids were built from are freed.
    void start_distances() { nearest_.assign(size_, std::numeric_limits<float>::max()); }

    // The index in `points` of a slot's stipple.
    uint32_t point_of(uint32_t slot) const { return grid_.sorted_index(slot); }
    // point_of is not needed once the caller has named the stipples by slot.
    void release_points() { grid_.release_index(); }
    float nearest(uint32_t slot) const { return nearest_[slot]; }
    void prefetch_nearest(uint32_t slot) const { __builtin_prefetch(&nearest_[slot]); }
    void release_nearest() { std::vector<float>().swap(nearest_); }
    glm::vec3 position(uint32_t slot) const { return grid_.sorted_position(slot); }

    // nearest = min(nearest, |q - p|^2) for the stipples q of the cells within `reach` of p (a
    // superset of those closer than reach; the extra ones are harmless, see the top of progressive_order.cpp).
    void push(const glm::vec3& p, float reach);

private:
    size_t size_;  // points
    PointGrid grid_;
    std::vector<float> nearest_;  // by slot
    std::vector<PointGrid::Run> runs_;  // push's, kept for their memory
};

}  // namespace stipple
