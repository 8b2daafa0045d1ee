#include "export/polylines.hpp"

#include <cmath>

#include <glm/geometric.hpp>

namespace stipple::plot {

double polyline_length(const Polyline& line) {
    double length = 0.0;
    for (size_t i = 1; i < line.points.size(); ++i) length += glm::length(line.points[i] - line.points[i - 1]);
    if (line.closed && line.points.size() > 1) length += glm::length(line.points.front() - line.points.back());
    return length;
}

namespace {

class Chainer {
public:
    explicit Chainer(const LineGraph& graph) : graph_(graph), used_(graph.edges.size(), 0) {
        // Edges at each vertex (compressed rows).
        first_.assign(graph.vertices.size() + 1, 0);
        for (const auto& e : graph.edges) ++first_[e[0] + 1], ++first_[e[1] + 1];
        for (size_t v = 0; v < graph.vertices.size(); ++v) first_[v + 1] += first_[v];
        incident_.resize(2 * graph.edges.size());
        std::vector<uint32_t> fill(first_.begin(), first_.end() - 1);
        for (uint32_t e = 0; e < graph.edges.size(); ++e) incident_[fill[graph.edges[e][0]]++] = e, incident_[fill[graph.edges[e][1]]++] = e;
        unused_ = first_;  // unused_[v]: count of unused edges at v, kept below
        for (size_t v = 0; v < graph.vertices.size(); ++v) unused_[v] = first_[v + 1] - first_[v];
    }

    std::vector<Polyline> run() {
        // Open strokes first: each walk from a vertex with an odd count of unused edges ends at
        // another such vertex, so a component with 2k of them gets exactly k open strokes.
        std::vector<std::vector<uint32_t>> strokes;
        for (uint32_t v = 0; v < graph_.vertices.size(); ++v)
            while (unused_[v] % 2 == 1) strokes.push_back(walk(v));
        // Then what is left is loops (every vertex has an even count): each loop that touches a
        // stroke is spliced into it where they meet (Hierholzer), so it costs no pen lift; a loop
        // touching none becomes a closed stroke of its own, into which later loops splice in turn.
        std::vector<uint8_t> closed(strokes.size(), 0);
        uint32_t next_start = 0;
        for (size_t s = 0;; ++s) {
            if (s == strokes.size()) {
                while (next_start < graph_.vertices.size() && unused_[next_start] == 0) ++next_start;
                if (next_start == graph_.vertices.size()) break;
                strokes.push_back(walk(next_start));
                strokes.back().pop_back();  // a loop: back at its start, which is not repeated
                closed.push_back(1);
            }
            for (size_t k = 0; k < strokes[s].size(); ++k)
                while (unused_[strokes[s][k]] > 0) {
                    std::vector<uint32_t> loop = walk(strokes[s][k]);  // starts and ends at strokes[s][k]
                    strokes[s].insert(strokes[s].begin() + static_cast<std::ptrdiff_t>(k) + 1, loop.begin() + 1, loop.end());
                }
        }
        std::vector<Polyline> lines(strokes.size());
        for (size_t s = 0; s < strokes.size(); ++s) {
            for (const uint32_t v : strokes[s]) lines[s].points.push_back(graph_.vertices[v]);
            lines[s].closed = closed[s] != 0;
        }
        return lines;
    }

private:
    // The unused edge at v that turns least from `heading` (any unused edge when heading is zero).
    uint32_t next_edge(uint32_t v, glm::dvec2 heading) const {
        uint32_t best = kNone;
        double best_cos = -2.0;
        for (uint32_t k = first_[v]; k < first_[v + 1]; ++k) {
            const uint32_t e = incident_[k];
            if (used_[e]) continue;
            if (heading == glm::dvec2(0.0)) return e;
            const glm::dvec2 out = glm::normalize(graph_.vertices[other(e, v)] - graph_.vertices[v]);
            const double c = glm::dot(out, heading);
            if (c > best_cos) best_cos = c, best = e;
        }
        return best;
    }
    uint32_t other(uint32_t e, uint32_t v) const { return graph_.edges[e][0] == v ? graph_.edges[e][1] : graph_.edges[e][0]; }

    // Follows unused edges from `start` until none is left at the current vertex; the vertices visited.
    std::vector<uint32_t> walk(uint32_t start) {
        std::vector<uint32_t> path{start};
        uint32_t v = start;
        glm::dvec2 heading(0.0);
        for (uint32_t e = next_edge(v, heading); e != kNone; e = next_edge(v, heading)) {
            used_[e] = 1;
            const uint32_t w = other(e, v);
            --unused_[v], --unused_[w];
            heading = glm::normalize(graph_.vertices[w] - graph_.vertices[v]);
            v = w;
            path.push_back(v);
        }
        return path;
    }

    static constexpr uint32_t kNone = 0xffffffffu;
    const LineGraph& graph_;
    std::vector<uint8_t> used_;
    std::vector<uint32_t> first_, incident_, unused_;
};

}  // namespace

std::vector<Polyline> chain_edges(const LineGraph& graph) { return Chainer(graph).run(); }

}  // namespace stipple::plot
