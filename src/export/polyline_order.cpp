#include "export/polyline_order.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>

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

void weld_touching_strokes(std::vector<Polyline>& lines, double gap_mm, double fold_mm) {
    if (!(gap_mm > 0.0)) return;
    // End 2l is open stroke l's first point, 2l + 1 its last; closed and empty strokes have none.
    const uint32_t count = static_cast<uint32_t>(lines.size());
    const auto open = [&](uint32_t l) { return !lines[l].closed && !lines[l].points.empty(); };
    const auto end_point = [&](uint32_t end) {
        const Polyline& line = lines[end / 2];
        return end % 2 == 0 ? line.points.front() : line.points.back();
    };
    // Pairs of ends of different strokes closer than the gap, found through cells of the gap's size.
    std::unordered_map<uint64_t, std::vector<uint32_t>> cells;
    const auto cell_of = [&](const glm::dvec2& p) { return glm::i64vec2(glm::floor(p / gap_mm)); };
    const auto key = [](glm::i64vec2 c) { return (uint64_t(uint32_t(c.x)) << 32) | uint32_t(c.y); };
    for (uint32_t l = 0; l < count; ++l)
        if (open(l))
            for (uint32_t end : {2 * l, 2 * l + 1}) cells[key(cell_of(end_point(end)))].push_back(end);
    struct Pair {
        double distance;
        uint32_t a, b;
    };
    std::vector<Pair> pairs;
    for (const auto& [cell_key, ends] : cells)
        for (uint32_t a : ends) {
            const glm::i64vec2 c = cell_of(end_point(a));
            for (int64_t dy = -1; dy <= 1; ++dy)
                for (int64_t dx = -1; dx <= 1; ++dx) {
                    const auto found = cells.find(key(c + glm::i64vec2(dx, dy)));
                    if (found == cells.end()) continue;
                    for (uint32_t b : found->second) {
                        if (b <= a || b / 2 == a / 2) continue;
                        const double d = glm::length(end_point(a) - end_point(b));
                        if (d < gap_mm) pairs.push_back({d, a, b});
                    }
                }
        }
    if (pairs.empty()) return;
    // Nearest first, each end once, never two ends of one chain (that would close it).
    std::sort(pairs.begin(), pairs.end(), [](const Pair& p, const Pair& q) {
        return p.distance != q.distance ? p.distance < q.distance : (p.a != q.a ? p.a < q.a : p.b < q.b);
    });
    std::vector<uint32_t> chain(count), link(2 * size_t(count), UINT32_MAX);
    std::iota(chain.begin(), chain.end(), 0u);
    const auto root = [&](uint32_t l) {
        while (chain[l] != l) l = chain[l] = chain[chain[l]];
        return l;
    };
    for (const Pair& p : pairs) {
        if (link[p.a] != UINT32_MAX || link[p.b] != UINT32_MAX || root(p.a / 2) == root(p.b / 2)) continue;
        link[p.a] = p.b;
        link[p.b] = p.a;
        chain[root(p.a / 2)] = root(p.b / 2);
    }
    // Each chain walked from a stroke with a free end, every stroke entered at its linked end.
    std::vector<Polyline> welded;
    std::vector<uint8_t> done(count, 0), was_welded;
    for (uint32_t l = 0; l < count; ++l) {
        if (done[l]) continue;
        if (!open(l) || (link[2 * l] == UINT32_MAX && link[2 * l + 1] == UINT32_MAX)) {
            done[l] = 1;
            welded.push_back(std::move(lines[l]));
            was_welded.push_back(0);
            continue;
        }
        if (link[2 * l] != UINT32_MAX && link[2 * l + 1] != UINT32_MAX) continue;  // inside a chain: from its end
        Polyline line;
        uint32_t at = l, entry = link[2 * l] == UINT32_MAX ? 2 * l : 2 * l + 1;  // the free end first
        while (true) {
            done[at] = 1;
            std::vector<glm::dvec2>& points = lines[at].points;
            if (entry % 2 == 1) std::reverse(points.begin(), points.end());
            const bool same_point = !line.points.empty() && line.points.back() == points.front();
            line.points.insert(line.points.end(), points.begin() + (same_point ? 1 : 0), points.end());
            const uint32_t exit = entry ^ 1u;
            if (link[exit] == UINT32_MAX) break;
            entry = link[exit];
            at = entry / 2;
        }
        welded.push_back(std::move(line));
        was_welded.push_back(1);
    }
    // As join_close_strokes: folds within `fold_mm` where the pieces met are drawn once.
    for (size_t i = 0; i < welded.size(); ++i)
        if (was_welded[i]) welded[i] = unfold(welded[i], fold_mm);
    lines = std::move(welded);
}

void join_close_strokes(std::vector<Polyline>& lines, double gap_mm, double fold_mm) {
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
    // drew that stretch three times, a knob on paper. Folds within `fold_mm` are drawn once.
    for (size_t i = 0; i < joined.size(); ++i)
        if (was_joined[i]) joined[i] = unfold(joined[i], fold_mm);
    lines = std::move(joined);
}

}  // namespace stipple::plot
