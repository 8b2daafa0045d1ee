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
    if (n <= 3) {
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

    // Ear clipping over a ring of the corners left. Only a reflex corner (or a flat one) can lie inside an
    // ear of a simple polygon, so the ear test visits those alone, and only those in the cells of a grid
    // that the ear's box touches: a comb of 10,000 teeth is cut in a fraction of a second where testing
    // every corner cost the cube of the corners. Clipping only ever turns a reflex corner convex (its
    // neighbours are the only corners whose angle changes), so the grid is built once and corners that
    // stop being reflex are skipped.
    std::vector<size_t> prev(n), next(n);
    for (size_t i = 0; i < n; ++i) prev[i] = (i + n - 1) % n, next[i] = (i + 1) % n;
    std::vector<uint8_t> reflex(n, 0);  // 0 as well once a corner is clipped
    auto update = [&](size_t b) { reflex[b] = orientation(point[prev[b]], point[b], point[next[b]]) <= 0.0; };
    size_t reflex_count = 0;
    glm::dvec2 lo = point[0], hi = point[0];
    for (size_t i = 0; i < n; ++i) {
        update(i);
        reflex_count += reflex[i];
        lo = glm::min(lo, point[i]), hi = glm::max(hi, point[i]);
    }
    // About one reflex corner a cell, the cells about square.
    const glm::dvec2 extent = glm::max(hi - lo, glm::dvec2(1e-300));
    const double aspect = extent.x / extent.y;
    const auto cells_along = [&](double share) {
        return size_t(std::clamp(std::ceil(std::sqrt(double(reflex_count) * share)), 1.0, double(std::max<size_t>(reflex_count, 1))));
    };
    const size_t nx = cells_along(aspect), ny = cells_along(1.0 / aspect);
    const glm::dvec2 scale = glm::dvec2(double(nx), double(ny)) / extent;
    auto cell = [&](glm::dvec2 p) {
        const glm::dvec2 c = glm::floor((p - lo) * scale);
        return glm::ivec2(std::clamp(int(std::min(c.x, 2e9)), 0, int(nx) - 1), std::clamp(int(std::min(c.y, 2e9)), 0, int(ny) - 1));
    };
    std::vector<uint32_t> cell_start(nx * ny + 1, 0), in_cell(reflex_count);
    for (size_t i = 0; i < n; ++i)
        if (reflex[i]) {
            const glm::ivec2 c = cell(point[i]);
            ++cell_start[size_t(c.y) * nx + size_t(c.x) + 1];
        }
    for (size_t k = 0; k < nx * ny; ++k) cell_start[k + 1] += cell_start[k];
    {
        std::vector<uint32_t> fill(cell_start.begin(), cell_start.end() - 1);
        for (size_t i = 0; i < n; ++i)
            if (reflex[i]) {
                const glm::ivec2 c = cell(point[i]);
                in_cell[fill[size_t(c.y) * nx + size_t(c.x)]++] = uint32_t(i);
            }
    }
    uint64_t budget = kEarTestBudget;  // a polygon that crosses itself may find no ear for long
    auto is_ear = [&](size_t b) {
        const size_t a = prev[b], c = next[b];
        --budget;
        if (orientation(point[a], point[b], point[c]) <= 0.0) return false;  // reflex or flat
        const glm::ivec2 c0 = cell(glm::min(point[a], glm::min(point[b], point[c])));
        const glm::ivec2 c1 = cell(glm::max(point[a], glm::max(point[b], point[c])));
        for (int y = c0.y; y <= c1.y; ++y)
            for (uint32_t k = cell_start[size_t(y) * nx + size_t(c0.x)]; k < cell_start[size_t(y) * nx + size_t(c1.x) + 1]; ++k) {
                const size_t p = in_cell[k];
                if (!reflex[p] || p == a || p == b || p == c) continue;
                if (budget > 0) --budget;
                if (point[p] == point[a] || point[p] == point[b] || point[p] == point[c]) continue;
                if (orientation(point[a], point[b], point[p]) >= 0.0 && orientation(point[b], point[c], point[p]) >= 0.0 &&
                    orientation(point[c], point[a], point[p]) >= 0.0)
                    return false;  // a corner inside (or on the edge of) the would-be ear
            }
        return true;
    };
    size_t left = n, at = 0, tried = 0;
    while (left > 3 && tried < left && budget > 0) {
        if (is_ear(at)) {
            emit(prev[at], at, next[at]);
            next[prev[at]] = next[at];
            prev[next[at]] = prev[at];
            reflex[at] = 0;
            update(prev[at]);
            update(next[at]);
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
