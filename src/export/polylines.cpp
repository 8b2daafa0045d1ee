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
        std::vector<Polyline> lines;
        for (uint32_t v = 0; v < graph_.vertices.size(); ++v)
            if ((first_[v + 1] - first_[v]) % 2 == 1)
                while (unused_[v] > 0) lines.push_back(walk(v));
        for (uint32_t v = 0; v < graph_.vertices.size(); ++v)
            while (unused_[v] > 0) lines.push_back(walk(v));
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

    Polyline walk(uint32_t start) {
        Polyline line;
        line.points.push_back(graph_.vertices[start]);
        uint32_t v = start;
        glm::dvec2 heading(0.0);
        for (uint32_t e = next_edge(v, heading); e != kNone; e = next_edge(v, heading)) {
            used_[e] = 1;
            const uint32_t w = other(e, v);
            --unused_[v], --unused_[w];
            heading = glm::normalize(graph_.vertices[w] - graph_.vertices[v]);
            v = w;
            line.points.push_back(graph_.vertices[v]);
        }
        // Back where it began: a loop, drawn without repeating its first point.
        if (v == start && line.points.size() >= 4) {
            line.points.pop_back();
            line.closed = true;
        }
        return line;
    }

    static constexpr uint32_t kNone = 0xffffffffu;
    const LineGraph& graph_;
    std::vector<uint8_t> used_;
    std::vector<uint32_t> first_, incident_, unused_;
};

}  // namespace

std::vector<Polyline> chain_edges(const LineGraph& graph) { return Chainer(graph).run(); }

}  // namespace stipple::plot
