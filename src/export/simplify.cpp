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

namespace {

// Folds are looked for this many points past their turn: a zig-zag folds over a few edges at a time.
constexpr size_t kMaxFoldPoints = 8;
// A turn of more than 150 degrees.
constexpr double kTurnedBack = -0.866;

// Whether p lies within `tolerance` of the segment a-b, beside it (not beyond its ends): a stroke's end
// there adds no ink to the segment's.
bool beside(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b, double tolerance) {
    const glm::dvec2 ab = b - a;
    const double len2 = glm::dot(ab, ab), t = len2 > 0.0 ? glm::dot(p - a, ab) / len2 : -1.0;
    return t >= 0.0 && t <= 1.0 && glm::length(p - (a + t * ab)) <= tolerance;
}

bool turns_back(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    const glm::dvec2 in = b - a, out = c - b;
    const double lengths = glm::length(in) * glm::length(out);
    return lengths > 0.0 && glm::dot(in, out) < kTurnedBack * lengths;
}

// Whether every point of pts[first + 1 .. last - 1] lies within `tolerance` of the segment pts[first]-pts[last].
bool within_chord(const std::vector<glm::dvec2>& pts, size_t first, size_t last, double tolerance) {
    for (size_t i = first + 1; i < last; ++i)
        if (distance_to_segment(pts[i], pts[first], pts[last]) > tolerance) return false;
    return true;
}

}  // namespace

Polyline unfold(const Polyline& line, double tolerance) {
    const std::vector<glm::dvec2>& p = line.points;
    const size_t n = p.size();
    if (n < 3 || !(tolerance > 0.0)) return line;
    Polyline out;
    out.closed = line.closed;
    size_t begin = 0, end = n;  // the stretch kept of an open stroke, without retraced ends
    if (!line.closed) {
        while (end - begin >= 3 && turns_back(p[begin], p[begin + 1], p[begin + 2]) &&
               beside(p[begin], p[begin + 1], p[begin + 2], tolerance))
            ++begin;
        while (end - begin >= 3 && turns_back(p[end - 3], p[end - 2], p[end - 1]) &&
               beside(p[end - 1], p[end - 3], p[end - 2], tolerance))
            --end;
    }
    out.points.push_back(p[begin]);
    size_t last = begin;  // index of the last point kept
    for (size_t k = begin + 1; k < end;) {
        if (k + 1 < end && turns_back(p[last], p[k], p[k + 1])) {
            // The farthest point after the fold that a straight line from the last point kept reaches with
            // every point between within the tolerance.
            size_t reach = 0;
            for (size_t e = k + 2; e < end && e <= k + kMaxFoldPoints; ++e)
                if (within_chord(p, last, e, tolerance)) reach = e;
            if (reach != 0) {
                out.points.push_back(p[reach]);
                last = reach;
                k = reach + 1;
                continue;
            }
        }
        out.points.push_back(p[k]);
        last = k++;
    }
    return out;
}

}  // namespace stipple::plot
