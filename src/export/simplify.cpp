#include "export/simplify.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

namespace stipple::plot {

double distance_to_segment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

namespace {

// Marks the points of pts[first..last] that Douglas-Peucker keeps (first and last always).
void mark_kept(const std::vector<glm::dvec2>& pts, size_t first, size_t last, double tolerance, std::vector<uint8_t>& keep) {
    keep[first] = keep[last] = 1;
    std::vector<std::pair<size_t, size_t>> stack{{first, last}};  // no recursion: strokes can be long
    while (!stack.empty()) {
        const auto [a, b] = stack.back();
        stack.pop_back();
        double worst = -1.0;
        size_t worst_at = a;
        for (size_t i = a + 1; i < b; ++i) {
            const double d = distance_to_segment(pts[i], pts[a], pts[b]);
            if (d > worst) worst = d, worst_at = i;
        }
        if (worst > tolerance) {
            keep[worst_at] = 1;
            stack.push_back({a, worst_at});
            stack.push_back({worst_at, b});
        }
    }
}

}  // namespace

Polyline simplify(const Polyline& line, double tolerance) {
    const size_t n = line.points.size();
    if (n < 3) return line;
    std::vector<glm::dvec2> pts = line.points;
    std::vector<uint8_t> keep(n + 1, 0);
    if (line.closed) {
        // Walk the loop as an open stroke from point 0 back to point 0, pinned at the point
        // farthest from it, so that the loop cannot collapse into its chord.
        pts.push_back(pts[0]);
        size_t far = 0;
        for (size_t i = 1; i < n; ++i)
            if (glm::length(pts[i] - pts[0]) > glm::length(pts[far] - pts[0])) far = i;
        if (far == 0) far = n / 2;
        mark_kept(pts, 0, far, tolerance, keep);
        mark_kept(pts, far, n, tolerance, keep);
    } else {
        mark_kept(pts, 0, n - 1, tolerance, keep);
    }
    Polyline out;
    out.closed = line.closed;
    for (size_t i = 0; i < n; ++i)
        if (keep[i]) out.points.push_back(pts[i]);
    return out;
}

}  // namespace stipple::plot
