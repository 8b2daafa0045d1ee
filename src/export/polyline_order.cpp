#include "export/polyline_order.hpp"

#include <algorithm>
#include <cstdint>

#include <glm/geometric.hpp>

#include "export/nearest_alive_grid.hpp"
#include "export/simplify.hpp"

namespace stipple::plot {

void order_polylines(std::vector<Polyline>& lines, glm::dvec2& pen) {
    // Entry points: both ends of an open stroke, every point of a closed one.
    std::vector<glm::dvec2> entries;
    std::vector<uint32_t> entry_line, entry_point;
    std::vector<uint32_t> first_entry(lines.size() + 1, 0);
    for (uint32_t l = 0; l < lines.size(); ++l) {
        first_entry[l] = static_cast<uint32_t>(entries.size());
        const Polyline& line = lines[l];
        if (line.points.empty()) continue;
        const auto add = [&](uint32_t p) {
            entries.push_back(line.points[p]);
            entry_line.push_back(l);
            entry_point.push_back(p);
        };
        if (line.closed) {
            for (uint32_t p = 0; p < line.points.size(); ++p) add(p);
        } else {
            add(0);
            if (line.points.size() > 1) add(static_cast<uint32_t>(line.points.size() - 1));
        }
    }
    first_entry[lines.size()] = static_cast<uint32_t>(entries.size());

    NearestAliveGrid free_ends(entries);
    std::vector<Polyline> ordered;
    ordered.reserve(lines.size());
    for (uint32_t e = free_ends.nearest(pen); e != NearestAliveGrid::kNone; e = free_ends.nearest(pen)) {
        const uint32_t l = entry_line[e];
        for (uint32_t k = first_entry[l]; k < first_entry[l + 1]; ++k) free_ends.remove(k);
        Polyline line = std::move(lines[l]);
        if (line.closed) {
            std::rotate(line.points.begin(), line.points.begin() + entry_point[e], line.points.end());
            pen = line.points.front();
        } else {
            if (entry_point[e] != 0) std::reverse(line.points.begin(), line.points.end());
            pen = line.points.back();
        }
        ordered.push_back(std::move(line));
    }
    lines = std::move(ordered);
}

void join_close_strokes(std::vector<Polyline>& lines, double gap_mm) {
    std::vector<Polyline> joined;
    std::vector<uint8_t> was_joined;
    joined.reserve(lines.size());
    for (Polyline& line : lines) {
        if (line.points.empty()) continue;
        if (!joined.empty()) {
            Polyline& last = joined.back();
            if (!last.closed && !line.closed && glm::length(line.points.front() - last.points.back()) < gap_mm) {
                const bool same_point = line.points.front() == last.points.back();
                last.points.insert(last.points.end(), line.points.begin() + (same_point ? 1 : 0), line.points.end());
                was_joined.back() = 1;
                continue;
            }
        }
        joined.push_back(std::move(line));
        was_joined.push_back(0);
    }
    // Pieces that overlap where they meet (a contour's visible pieces, each ending a little past where the next
    // begins along the zig-zag) make the joined stroke step back over its last stretch and on again: the pen
    // drew that stretch three times, a knob on paper. Folds within half the pen's width are drawn once.
    for (size_t i = 0; i < joined.size(); ++i)
        if (was_joined[i]) joined[i] = unfold(joined[i], 0.5 * gap_mm);
    lines = std::move(joined);
}

}  // namespace stipple::plot
