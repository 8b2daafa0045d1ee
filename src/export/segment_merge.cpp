#include "export/segment_merge.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

#include <glm/geometric.hpp>

namespace stipple::plot {

namespace {

uint64_t cell_key(int64_t x, int64_t y) { return (static_cast<uint64_t>(x) << 32) ^ static_cast<uint64_t>(y & 0xffffffff); }

// Gives each endpoint a vertex id; endpoints within `snap` of an earlier vertex reuse it.
class VertexWelder {
public:
    VertexWelder(double snap, std::vector<glm::dvec2>& vertices) : snap_(std::max(snap, 1e-12)), vertices_(vertices) {}

    uint32_t weld(glm::dvec2 p) {
        const int64_t cx = static_cast<int64_t>(std::floor(p.x / snap_)), cy = static_cast<int64_t>(std::floor(p.y / snap_));
        for (int64_t y = cy - 1; y <= cy + 1; ++y)
            for (int64_t x = cx - 1; x <= cx + 1; ++x) {
                const auto found = head_.find(cell_key(x, y));
                for (uint32_t v = found == head_.end() ? kNone : found->second; v != kNone; v = next_[v])
                    if (glm::length(vertices_[v] - p) <= snap_) return v;
            }
        const uint32_t v = static_cast<uint32_t>(vertices_.size());
        vertices_.push_back(p);
        const auto [slot, inserted] = head_.try_emplace(cell_key(cx, cy), v);
        next_.push_back(inserted ? kNone : slot->second);
        slot->second = v;
        return v;
    }

private:
    static constexpr uint32_t kNone = 0xffffffffu;
    double snap_;
    std::vector<glm::dvec2>& vertices_;
    std::unordered_map<uint64_t, uint32_t> head_;  // cell -> its most recent vertex; next_ chains the others
    std::vector<uint32_t> next_;
};

struct DisjointSets {
    std::vector<uint32_t> parent;
    explicit DisjointSets(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
    uint32_t find(uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    }
    void join(uint32_t a, uint32_t b) { parent[find(a)] = find(b); }
};

double distance_to_line(glm::dvec2 p, glm::dvec2 a, glm::dvec2 unit_dir) {
    const glm::dvec2 d = p - a;
    return std::abs(d.x * unit_dir.y - d.y * unit_dir.x);
}

// Whether edges e and f lie on one line (each one's ends near the other's line) and share a
// stretch longer than `tolerance` (touching end to end is not overlapping).
bool overlap_on_one_line(const LineGraph& g, const std::array<uint32_t, 2>& e, const std::array<uint32_t, 2>& f, double tolerance) {
    const glm::dvec2 a = g.vertices[e[0]], b = g.vertices[e[1]], c = g.vertices[f[0]], d = g.vertices[f[1]];
    const glm::dvec2 u = glm::normalize(b - a), w = glm::normalize(d - c);
    if (distance_to_line(c, a, u) > tolerance || distance_to_line(d, a, u) > tolerance) return false;
    if (distance_to_line(a, c, w) > tolerance || distance_to_line(b, c, w) > tolerance) return false;
    const double t_b = glm::dot(b - a, u), t_c = glm::dot(c - a, u), t_d = glm::dot(d - a, u);
    return std::min(t_b, std::max(t_c, t_d)) - std::max(0.0, std::min(t_c, t_d)) > tolerance;
}

// Finds the groups of edges that overlap on one line: a spatial hash of edge boxes proposes
// pairs, disjoint sets gather them.
DisjointSets overlapping_groups(const LineGraph& g, double tolerance) {
    DisjointSets groups(g.edges.size());
    if (g.edges.size() < 2) return groups;
    std::vector<double> lengths;
    for (const auto& e : g.edges) lengths.push_back(glm::length(g.vertices[e[1]] - g.vertices[e[0]]));
    std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
    const double cell = std::max({2.0 * lengths[lengths.size() / 2], 16.0 * tolerance, 1e-9});

    std::unordered_map<uint64_t, std::vector<uint32_t>> cells;
    for (uint32_t i = 0; i < g.edges.size(); ++i) {
        const glm::dvec2 a = g.vertices[g.edges[i][0]], b = g.vertices[g.edges[i][1]];
        const glm::dvec2 lo = (glm::min(a, b) - tolerance) / cell, hi = (glm::max(a, b) + tolerance) / cell;
        const int64_t x0 = static_cast<int64_t>(std::floor(lo.x)), x1 = static_cast<int64_t>(std::floor(hi.x));
        const int64_t y0 = static_cast<int64_t>(std::floor(lo.y)), y1 = static_cast<int64_t>(std::floor(hi.y));
        for (int64_t y = y0; y <= y1; ++y)
            for (int64_t x = x0; x <= x1; ++x) cells[cell_key(x, y)].push_back(i);
    }
    for (const auto& [key, members] : cells)
        for (size_t i = 0; i < members.size(); ++i)
            for (size_t j = i + 1; j < members.size(); ++j)
                if (groups.find(members[i]) != groups.find(members[j]) &&
                    overlap_on_one_line(g, g.edges[members[i]], g.edges[members[j]], tolerance))
                    groups.join(members[i], members[j]);
    return groups;
}

// Replaces each group of overlapping edges by the union of their extents along the group's
// longest edge; the new edges end at existing vertices, so the graph stays connected there. Groups join
// pairwise (each pair within the tolerance of one line), so a chain of pieces folding back along a curve
// can gather into one group: only the members near the longest one's line join its span, and the rest
// are merged the same way around their own longest, and so on (one span for the whole group turned 60
// folds along an arc of radius 200 px into a chord 77 px off it).
std::vector<std::array<uint32_t, 2>> merge_groups(const LineGraph& g, DisjointSets& groups, double tolerance) {
    std::vector<std::vector<uint32_t>> members(g.edges.size());
    for (uint32_t i = 0; i < g.edges.size(); ++i) members[groups.find(i)].push_back(i);
    std::vector<std::array<uint32_t, 2>> merged;
    const auto length = [&](uint32_t e) { return glm::length(g.vertices[g.edges[e][1]] - g.vertices[g.edges[e][0]]); };
    struct Span { double t0, t1; uint32_t v0, v1; };
    std::vector<Span> spans;
    std::vector<uint32_t> rest;
    for (std::vector<uint32_t> group : members) {
        while (!group.empty()) {
            if (group.size() == 1) {
                merged.push_back(g.edges[group[0]]);
                break;
            }
            const uint32_t longest = *std::max_element(group.begin(), group.end(), [&](uint32_t x, uint32_t y) { return length(x) < length(y); });
            const glm::dvec2 origin = g.vertices[g.edges[longest][0]];
            const glm::dvec2 dir = glm::normalize(g.vertices[g.edges[longest][1]] - origin);
            spans.clear();
            rest.clear();
            for (const uint32_t e : group) {
                uint32_t v0 = g.edges[e][0], v1 = g.edges[e][1];
                if (distance_to_line(g.vertices[v0], origin, dir) > tolerance || distance_to_line(g.vertices[v1], origin, dir) > tolerance) {
                    rest.push_back(e);
                    continue;
                }
                double t0 = glm::dot(g.vertices[v0] - origin, dir), t1 = glm::dot(g.vertices[v1] - origin, dir);
                if (t1 < t0) std::swap(t0, t1), std::swap(v0, v1);
                spans.push_back({t0, t1, v0, v1});
            }
            std::sort(spans.begin(), spans.end(), [](const Span& x, const Span& y) { return x.t0 < y.t0; });
            Span current = spans[0];  // the longest edge itself is on its line
            for (size_t k = 1; k <= spans.size(); ++k) {
                if (k < spans.size() && spans[k].t0 <= current.t1 + tolerance) {
                    if (spans[k].t1 > current.t1) current.t1 = spans[k].t1, current.v1 = spans[k].v1;
                    continue;
                }
                if (current.v0 != current.v1) merged.push_back({current.v0, current.v1});
                if (k < spans.size()) current = spans[k];
            }
            group.swap(rest);
        }
    }
    return merged;
}

}  // namespace

LineGraph merge_segments(std::span<const std::array<glm::dvec2, 2>> pieces, const MergeOptions& options) {
    LineGraph graph;
    VertexWelder welder(options.snap_px, graph.vertices);
    for (const auto& piece : pieces) {
        if (!std::isfinite(piece[0].x) || !std::isfinite(piece[0].y) || !std::isfinite(piece[1].x) || !std::isfinite(piece[1].y))
            continue;  // a degenerate projection; nothing to draw
        const uint32_t a = welder.weld(piece[0]), b = welder.weld(piece[1]);
        if (a != b) graph.edges.push_back({std::min(a, b), std::max(a, b)});
    }
    // Exact duplicates first (cheap and common: an edge reported by both of its polygons).
    std::sort(graph.edges.begin(), graph.edges.end());
    graph.edges.erase(std::unique(graph.edges.begin(), graph.edges.end()), graph.edges.end());
    DisjointSets groups = overlapping_groups(graph, options.collinear_px);
    graph.edges = merge_groups(graph, groups, options.collinear_px);
    return graph;
}

}  // namespace stipple::plot
