#include "mesh/polygon_triangulation.hpp"

#include <algorithm>
#include <cmath>

namespace stipple {

namespace {

double orientation(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

}  // namespace

Triangulated triangulate_polygon(std::span<const glm::vec3> positions, std::span<const uint32_t> corners,
                                 std::span<uint32_t> triangles, uint64_t budget) {
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
        return Triangulated::fanned;
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
        return Triangulated::fanned;
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
        return Triangulated::fanned;
    }

    // Ear clipping over a ring of the corners left.
    std::vector<size_t> prev(n), next(n);
    for (size_t i = 0; i < n; ++i) prev[i] = (i + n - 1) % n, next[i] = (i + 1) % n;
    size_t left = n, at = 0;
    auto clip = [&](size_t b) {
        emit(prev[b], b, next[b]);
        next[prev[b]] = next[b];
        prev[next[b]] = prev[b];
        --left;
    };
    auto turn = [&](size_t b) { return orientation(point[prev[b]], point[b], point[next[b]]); };
    // First the flat corners (on a straight edge, or the tip of a spike of no width): each is cut off as a
    // triangle of no area, which leaves the polygon's shape as it was. A face whose edges are finely
    // divided (a CAD export's, 75k corners on the straight sides of an L) then costs no more than its
    // true corners.
    {
        std::vector<size_t> flat;
        for (size_t i = 0; i < n; ++i)
            if (turn(i) == 0.0) flat.push_back(i);
        std::vector<uint8_t> gone(n, 0);
        while (!flat.empty() && left > 3) {
            const size_t b = flat.back();
            flat.pop_back();
            if (gone[b] || turn(b) != 0.0) continue;
            const size_t a = prev[b], c = next[b];
            clip(b);
            gone[b] = 1;
            at = a;
            for (size_t x : {a, c})
                if (turn(x) == 0.0) flat.push_back(x);
        }
    }
    // Only a reflex corner can lie inside an ear of a simple polygon, so the ear test visits those alone,
    // and only those in the cells of a grid that the ear's box touches: a comb of 10,000 teeth is cut in
    // a fraction of a second where testing every corner cost the cube of the corners. Clipping an ear of a
    // simple polygon only ever turns a reflex corner convex (its neighbours are the only corners whose angle
    // changes); such a corner leaves its cell at once. A corner cut where no ear was found (a polygon crossing
    // itself) can turn a neighbour reflex: those few are kept in a list of their own, which every ear test reads.
    std::vector<uint8_t> reflex(n, 0);
    size_t reflex_count = 0;
    glm::dvec2 lo = point[at], hi = point[at];
    {
        size_t b = at;
        do {
            reflex[b] = turn(b) < 0.0;
            reflex_count += reflex[b];
            lo = glm::min(lo, point[b]), hi = glm::max(hi, point[b]);
            b = next[b];
        } while (b != at);
    }
    // About one reflex corner a cell, the cells about square.
    const glm::dvec2 extent = glm::max(hi - lo, glm::dvec2(1e-300));
    const double aspect = extent.x / extent.y;
    const auto cells_along = [&](double share) {
        const double cells = std::ceil(std::sqrt(double(reflex_count) * share));
        // NaN (an infinite extent: inf / inf) or under one: one cell (converting NaN to a size is undefined).
        return cells >= 1.0 ? size_t(std::min(cells, double(std::max<size_t>(reflex_count, 1)))) : size_t(1);
    };
    const size_t nx = cells_along(aspect), ny = cells_along(1.0 / aspect);
    const glm::dvec2 scale = glm::dvec2(double(nx), double(ny)) / extent;
    auto cell_of = [&](glm::dvec2 p) {
        const glm::dvec2 c = glm::floor((p - lo) * scale);  // NaN compares false: cell 0
        const int x = c.x > 0.0 ? int(std::min(c.x, double(nx - 1))) : 0, y = c.y > 0.0 ? int(std::min(c.y, double(ny - 1))) : 0;
        return glm::ivec2(x, y);
    };
    auto cell_index = [&](glm::ivec2 c) { return size_t(c.y) * nx + size_t(c.x); };
    // Each cell's reflex corners at in_cell[cell_begin, cell_end); a corner that turns convex is swapped out.
    std::vector<uint32_t> cell_begin(nx * ny + 1, 0), in_cell(reflex_count), slot_of(n, 0);
    for (size_t b = 0; b < n; ++b)
        if (reflex[b]) ++cell_begin[cell_index(cell_of(point[b])) + 1];
    for (size_t k = 0; k < nx * ny; ++k) cell_begin[k + 1] += cell_begin[k];
    std::vector<uint32_t> cell_end(cell_begin.begin(), cell_begin.end() - 1);
    for (size_t b = 0; b < n; ++b)
        if (reflex[b]) {
            const size_t k = cell_index(cell_of(point[b]));
            slot_of[b] = cell_end[k];
            in_cell[cell_end[k]++] = uint32_t(b);
        }
    std::vector<uint32_t> late_reflex;  // corners that turned reflex after the grid was made (reflex[b] == 2)
    auto now_convex = [&](size_t b) {
        if (!reflex[b] || turn(b) < 0.0) return;
        --reflex_count;
        if (reflex[b] == 2) {
            reflex[b] = 0;
            late_reflex.erase(std::find(late_reflex.begin(), late_reflex.end(), uint32_t(b)));
            return;
        }
        reflex[b] = 0;
        const size_t k = cell_index(cell_of(point[b]));
        const uint32_t last = in_cell[--cell_end[k]];
        in_cell[slot_of[b]] = last;
        slot_of[last] = slot_of[b];
    };
    auto now_reflex = [&](size_t b) {
        if (reflex[b] || !(turn(b) < 0.0)) return;
        reflex[b] = 2;
        ++reflex_count;
        late_reflex.push_back(uint32_t(b));
    };
    // A reflex corner p other than the would-be ear's own corners inside it (or on its edge).
    auto inside_ear = [&](size_t p, size_t a, size_t b, size_t c) {
        if (p == a || p == c) return false;
        if (point[p] == point[a] || point[p] == point[b] || point[p] == point[c]) return false;
        return orientation(point[a], point[b], point[p]) >= 0.0 && orientation(point[b], point[c], point[p]) >= 0.0 &&
               orientation(point[c], point[a], point[p]) >= 0.0;
    };
    // `budget`: a polygon that crosses itself may find no ear for long.
    auto is_ear = [&](size_t b) {
        const size_t a = prev[b], c = next[b];
        --budget;
        if (orientation(point[a], point[b], point[c]) <= 0.0) return false;  // reflex or flat
        budget -= std::min<uint64_t>(budget, late_reflex.size());
        for (const uint32_t p : late_reflex)
            if (inside_ear(p, a, b, c)) return false;
        const glm::ivec2 c0 = cell_of(glm::min(point[a], glm::min(point[b], point[c])));
        const glm::ivec2 c1 = cell_of(glm::max(point[a], glm::max(point[b], point[c])));
        for (int y = c0.y; y <= c1.y; ++y)
            for (int x = c0.x; x <= c1.x; ++x) {
                const size_t k = cell_index({x, y});
                budget -= std::min<uint64_t>(budget, 1 + cell_end[k] - cell_begin[k]);
                for (uint32_t slot = cell_begin[k]; slot < cell_end[k]; ++slot)
                    if (inside_ear(in_cell[slot], a, b, c)) return false;
            }
        return true;
    };
    size_t tried = 0;
    // Corners cut where a full turn found no ear, each after a turn of ear tests: a few at most, so that a polygon
    // crossing itself at every step costs a few turns more than before and is then fanned, as it was.
    constexpr int kMostForced = 16;
    int forced = 0;
    // After an ear the walk goes on forward, not back to the corner before it: going back cut a fan around
    // that corner whose ears, ever longer, spanned the reflex corners still ahead (a star of 200,000 corners
    // spent the whole budget, and was fanned).
    auto clip_at = [&](size_t b) {
        const size_t a = prev[b], c = next[b];
        clip(b);
        now_convex(a);
        now_convex(c);
        now_reflex(a);
        now_reflex(c);
        at = c;
        tried = 0;
    };
    // Without a reflex corner what is left turns left at every corner: convex, and fanned (below) as a convex
    // polygon is (unless it crosses itself, winding more than once: then no cut covers it once).
    while (left > 3 && budget > 0 && reflex_count > 0) {
        if (tried >= left) {
            // A full turn without an ear: the polygon crosses itself (or its corners, rounded to floats, make it
            // cross). The convex corner of the smallest turn is cut off as if it were an ear, and the clipping goes
            // on, where a fan of the whole rest (what was done before) overlapped itself across the polygon.
            if (++forced > kMostForced) break;
            size_t best = n;
            double least = INFINITY;
            size_t b = at;
            do {
                const double t = turn(b);
                if (t > 0.0 && t < least) least = t, best = b;
                b = next[b];
            } while (b != at);
            budget -= std::min<uint64_t>(budget, left);
            if (best == n) break;  // no corner turns left: the rest winds the other way (a lobe of a crossing); fanned
            clip_at(best);
            continue;
        }
        if (is_ear(at)) {
            clip_at(at);
        } else {
            at = next[at];
            ++tried;
        }
    }
    // The last triangle, or a fan of the rest: convex, or where the clipping spent its budget or gave up on a
    // polygon crossing itself.
    for (size_t b = next[at]; next[b] != at; b = next[b]) emit(at, b, next[b]);
    return budget == 0 && reflex_count > 0 && left > 3 ? Triangulated::budget_spent : Triangulated::clipped;
}

}  // namespace stipple
