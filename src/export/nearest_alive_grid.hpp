#pragma once
// The nearest point not yet taken, among a fixed set from which points are taken one by one: the
// step of a nearest-neighbour tour once a point's own neighbours are all visited, and of ordering
// polylines by their nearest end.
//
// A uniform grid (about two points a cell) rather than nanoflann: nanoflann's trees cannot forget
// a point except by skipping it during the search, so late in a tour, when the neighbourhood of the
// pen is all visited, each search wades through the dead points of a dense tree (see
// tools/plot_order_speed, which times both). The grid keeps each cell's live points packed at its
// front and counts the live points of every cell and row, so dead cells and rows cost one test.
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

namespace stipple::plot {

class NearestAliveGrid {
public:
    static constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

    explicit NearestAliveGrid(std::span<const glm::dvec2> points);

    // The live point nearest to q (any q, inside the points' bounds or not), or kNone if none is left.
    uint32_t nearest(glm::dvec2 q) const;
    // Takes point i out (it is never returned again); taking a point twice is harmless.
    void remove(uint32_t i);
    bool alive(uint32_t i) const { return slot_[i] != kNone; }
    size_t alive_count() const { return alive_count_; }

private:
    // Looks at the live points of one cell, keeping the nearest in best/best_d2.
    void scan_cell(int x, int y, glm::dvec2 q, uint32_t& best, double& best_d2) const;

    std::span<const glm::dvec2> points_;
    glm::dvec2 origin_{0.0};
    double cell_ = 1.0;
    int cols_ = 1, rows_ = 1;
    std::vector<uint32_t> cell_start_;  // cell c's points: items_[cell_start_[c] .. + cell_alive_[c]) are live
    std::vector<uint32_t> cell_alive_;
    std::vector<uint32_t> row_alive_;
    std::vector<uint32_t> items_;
    std::vector<uint32_t> slot_;       // where point i sits in items_, kNone once removed
    std::vector<uint32_t> cell_of_;
    size_t alive_count_ = 0;
};

}  // namespace stipple::plot
