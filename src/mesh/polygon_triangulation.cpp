#include "mesh/polygon_triangulation.hpp"

#include <algorithm>
#include <cmath>

namespace stipple {

namespace {

double orientation(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

}  // namespace

bool triangulate_polygon(std::span<const glm::vec3> positions, std::span<const uint32_t> corners,
                         std::span<uint32_t> triangles) {
    const size_t n = corners.size();
    size_t written = 0;
    auto emit = [&](size_t a, size_t b, size_t c) {
        triangles[written++] = corners[a];
        triangles[written++] = corners[b];
        triangles[written++] = corners[c];
    };
    auto fan = [&] {
        for (size_t i = 1; i + 1 < n; ++i) emit(0, i, i + 1);
    };
    if (n <= 3 || n > kMaxEarClippedCorners) {
        fan();
        return false;
    }

    // The plane it spans (Newell's normal), and the polygon in it, counter-clockwise.
    glm::dvec3 normal(0.0);
    for (size_t i = 0; i < n; ++i) {
        const glm::dvec3 p(positions[corners[i]]), q(positions[corners[(i + 1) % n]]);
        normal += glm::dvec3((p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y));
    }
    const glm::dvec3 magnitude = glm::abs(normal);
    const int axis =
        magnitude.x >= magnitude.y && magnitude.x >= magnitude.z ? 0 : (magnitude.y >= magnitude.z ? 1 : 2);
    if (!(magnitude[axis] > 0.0) || !std::isfinite(magnitude[axis])) {
        fan();  // no area, or not finite (validate_mesh reports the coordinates)
        return false;
    }
    int u = (axis + 1) % 3, v = (axis + 2) % 3;
    if (normal[axis] < 0.0) std::swap(u, v);
    std::vector<glm::dvec2> point(n);
    for (size_t i = 0; i < n; ++i) point[i] = glm::dvec2(positions[corners[i]][u], positions[corners[i]][v]);

    bool convex = true;
    for (size_t i = 0; i < n && convex; ++i)
        convex = orientation(point[i], point[(i + 1) % n], point[(i + 2) % n]) >= 0.0;
    if (convex) {
        fan();
        return false;
    }

    // Ear clipping over a ring of the corners left.
    std::vector<size_t> prev(n), next(n);
    for (size_t i = 0; i < n; ++i) prev[i] = (i + n - 1) % n, next[i] = (i + 1) % n;
    auto is_ear = [&](size_t b) {
        const size_t a = prev[b], c = next[b];
        if (orientation(point[a], point[b], point[c]) <= 0.0) return false;  // reflex or flat
        for (size_t p = next[c]; p != a; p = next[p]) {
            if (point[p] == point[a] || point[p] == point[b] || point[p] == point[c]) continue;
            if (orientation(point[a], point[b], point[p]) >= 0.0 && orientation(point[b], point[c], point[p]) >= 0.0 &&
                orientation(point[c], point[a], point[p]) >= 0.0)
                return false;  // a corner inside (or on the edge of) the would-be ear
        }
        return true;
    };
    size_t left = n, at = 0, tried = 0;
    while (left > 3 && tried < left) {
        if (is_ear(at)) {
            emit(prev[at], at, next[at]);
            next[prev[at]] = next[at];
            prev[next[at]] = prev[at];
            at = prev[at];
            --left;
            tried = 0;
        } else {
            at = next[at];
            ++tried;
        }
    }
    // The last triangle, or, where no ear was left (a polygon crossing itself), a fan of the rest.
    for (size_t b = next[at]; next[b] != at; b = next[b]) emit(at, b, next[b]);
    return true;
}

}  // namespace stipple
