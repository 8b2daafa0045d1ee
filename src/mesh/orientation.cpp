#include "mesh/orientation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "mesh/mesh_ops.hpp"

namespace stipple {

namespace {

constexpr uint32_t kUnassigned = std::numeric_limits<uint32_t>::max();
// An open part whose holes, capped, add less than this share of its area is nearly closed: its volume says
// which way is out. A scan's holes add a few percent; a hemisphere's mouth a half, a valley's or a sheet's
// about its whole area; a sphere open over 60 degrees of its polar angle about a quarter.
constexpr double kNearlyClosed = 0.2;

bool indices_in_range(const Mesh& mesh, size_t t) {
    const size_t n = mesh.positions.size();
    return mesh.indices[3 * t] < n && mesh.indices[3 * t + 1] < n && mesh.indices[3 * t + 2] < n;
}

// An edge of one triangle only (a hole's rim, a sheet's edge), walked from `from` to `to` (welded corners) in
// the triangle's own winding.
struct BorderEdge {
    uint32_t triangle, from, to;
};

// Each triangle's neighbours across its manifold edges, as (neighbour << 1 | same): `same` when both
// walk the shared edge in the same direction, i.e. when exactly one of them must be turned.
struct Adjacency {
    std::vector<uint32_t> first;  // triangle t's entries are [first[t], first[t + 1])
    std::vector<uint32_t> entries;
    std::vector<uint8_t> on_border;  // the triangle has an edge that joins it to no neighbour (a border, a
                                     // non-manifold or folded edge): its part is not closed
    std::vector<BorderEdge> borders;  // the edges of one triangle (not the non-manifold or folded ones)
};

glm::dvec3 corner_position(const Mesh& mesh, size_t t, int k) {
    return glm::dvec3(mesh.positions[mesh.indices[3 * t + k]]);
}

// Two triangles on one side of their shared edge (a, b), within 10 degrees of each other: faces laid over
// each other (a duplicate, a polygon drawn twice over) rather than a surface going on across the edge.
// Which way they should be wound says nothing about the other: the edge is no constraint.
bool folded_onto_each_other(const Mesh& mesh, std::span<const uint32_t> corner, uint32_t a, uint32_t b, uint32_t s,
                            uint32_t t) {
    const glm::dvec3 pa(mesh.positions[a]), edge = glm::dvec3(mesh.positions[b]) - pa;
    const double length2 = glm::dot(edge, edge);
    if (!(length2 > 0.0)) return false;
    auto across = [&](uint32_t triangle) {
        for (int k = 0; k < 3; ++k) {
            const uint32_t c = corner[mesh.indices[3 * triangle + k]];
            if (c == a || c == b) continue;
            const glm::dvec3 d = corner_position(mesh, triangle, k) - pa;
            return d - glm::dot(d, edge) / length2 * edge;
        }
        return glm::dvec3(0.0);
    };
    const glm::dvec3 u = across(s), w = across(t);
    const double lengths = glm::length(u) * glm::length(w);
    return lengths > 0.0 && glm::dot(u, w) > 0.985 * lengths;  // cos 10 degrees
}

Adjacency manifold_adjacency(const Mesh& mesh, std::span<const uint32_t> corner) {
    const size_t triangles = mesh.triangle_count();
    // Half-edges bucketed by their smaller corner (a counting sort: a comparison sort of the 2.6M half-edges
    // of an 871k-triangle scan took most of the repair's time), then matched within each small bucket.
    struct HalfEdge {
        uint32_t larger;  // the other corner
        uint32_t walked;  // triangle << 1 | 1 when the triangle walks from the smaller corner to the larger
    };
    std::vector<uint32_t> bucket_first(mesh.positions.size() + 1, 0);
    auto for_each_half_edge = [&](auto&& visit) {
        for (size_t t = 0; t < triangles; ++t) {
            if (!indices_in_range(mesh, t)) continue;
            for (int k = 0; k < 3; ++k) {
                const uint32_t a = corner[mesh.indices[3 * t + k]], b = corner[mesh.indices[3 * t + (k + 1) % 3]];
                if (a == b) continue;  // a collapsed side joins nothing
                visit(std::min(a, b), HalfEdge{std::max(a, b), uint32_t(t << 1) | uint32_t(a < b)});
            }
        }
    };
    for_each_half_edge([&](uint32_t smaller, HalfEdge) { ++bucket_first[smaller + 1]; });
    for (size_t v = 0; v < mesh.positions.size(); ++v) bucket_first[v + 1] += bucket_first[v];
    std::vector<HalfEdge> half_edges(bucket_first.back());
    {
        std::vector<uint32_t> fill(bucket_first.begin(), bucket_first.end() - 1);
        for_each_half_edge([&](uint32_t smaller, HalfEdge h) { half_edges[fill[smaller]++] = h; });
    }

    // The manifold edges as pairs of half-edges, then counted into each triangle's range.
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    pairs.reserve(half_edges.size() / 2);
    std::vector<uint32_t> unpaired;  // triangles with an edge that joins them to no neighbour
    std::vector<BorderEdge> borders;
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const auto begin = half_edges.begin() + bucket_first[v], end = half_edges.begin() + bucket_first[v + 1];
        std::sort(begin, end, [](const HalfEdge& x, const HalfEdge& y) {
            return x.larger != y.larger ? x.larger < y.larger : x.walked < y.walked;
        });
        for (auto run = begin; run != end;) {
            auto run_end = run + 1;
            while (run_end != end && run_end->larger == run->larger) ++run_end;
            if (run_end - run == 2 && (run[0].walked >> 1) != (run[1].walked >> 1) &&
                !folded_onto_each_other(mesh, corner, uint32_t(v), run->larger, run[0].walked >> 1, run[1].walked >> 1))
                pairs.emplace_back(run[0].walked, run[1].walked);
            else
                for (auto h = run; h != run_end; ++h) unpaired.push_back(h->walked >> 1);
            if (run_end - run == 1) {
                const bool ascending = (run->walked & 1u) != 0u;  // the triangle walks from v to the larger corner
                borders.push_back({run->walked >> 1, ascending ? uint32_t(v) : run->larger, ascending ? run->larger : uint32_t(v)});
            }
            run = run_end;
        }
    }
    Adjacency adjacency;
    adjacency.borders = std::move(borders);
    adjacency.on_border.assign(triangles, 0);
    for (uint32_t t : unpaired) adjacency.on_border[t] = 1;
    adjacency.first.assign(triangles + 1, 0);
    for (auto [x, y] : pairs) ++adjacency.first[(x >> 1) + 1], ++adjacency.first[(y >> 1) + 1];
    for (size_t t = 0; t < triangles; ++t) adjacency.first[t + 1] += adjacency.first[t];
    adjacency.entries.resize(adjacency.first[triangles]);
    std::vector<uint32_t> fill(adjacency.first.begin(), adjacency.first.end() - 1);
    for (auto [x, y] : pairs) {
        const uint32_t same = (x ^ y) & 1u ? 0u : 1u;
        adjacency.entries[fill[x >> 1]++] = (y >> 1) << 1 | same;
        adjacency.entries[fill[y >> 1]++] = (x >> 1) << 1 | same;
    }
    return adjacency;
}

// Each open part's holes closed by fans: a rim (border edges of one part joined through shared corners) from
// the centroid of its edges' midpoints, each fan triangle walking its border edge against the triangle that
// has it (`flipped`: the triangle's winding is to be reversed). With its caps a part encloses a volume that
// does not depend on where it is taken from, and the caps' area says how open the part is: small holes of a
// scan, or the wide mouth of a bowl, a valley, a room.
struct PartCaps {
    std::vector<double> area;             // per part
    std::vector<double> volume;           // per part, about `centre[part]`
    std::vector<double> unsigned_volume;  // the same with every tetrahedron taken positive
};

PartCaps cap_holes(const Mesh& mesh, const std::vector<BorderEdge>& borders, const std::vector<uint32_t>& part,
                   const std::vector<uint8_t>& wanted, const std::function<bool(uint32_t)>& flipped,
                   const std::vector<glm::dvec3>& centre, size_t parts) {
    PartCaps caps{std::vector<double>(parts, 0.0), std::vector<double>(parts, 0.0), std::vector<double>(parts, 0.0)};
    auto counted = [&](uint32_t i) {
        const uint32_t p = part[borders[i].triangle];
        return p != kUnassigned && wanted[p] != 0;
    };
    // Rims: border edges joined where they share a corner within one part (union-find over the edges). The
    // edges' ends bucketed by corner with a counting sort, as manifold_adjacency buckets its half-edges: a
    // triangle soup has three border edges a triangle, and a comparison sort of them was most of the repair.
    std::vector<uint32_t> root(borders.size());
    for (uint32_t i = 0; i < root.size(); ++i) root[i] = i;
    auto find = [&](uint32_t i) {
        while (root[i] != i) i = root[i] = root[root[i]];
        return i;
    };
    std::vector<uint32_t> first(mesh.positions.size() + 1, 0);
    for (uint32_t i = 0; i < borders.size(); ++i)
        if (counted(i)) ++first[borders[i].from + 1], ++first[borders[i].to + 1];
    for (size_t v = 0; v < mesh.positions.size(); ++v) first[v + 1] += first[v];
    std::vector<uint32_t> at(first.back());
    {
        std::vector<uint32_t> fill(first.begin(), first.end() - 1);
        for (uint32_t i = 0; i < borders.size(); ++i)
            if (counted(i)) at[fill[borders[i].from]++] = i, at[fill[borders[i].to]++] = i;
    }
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const auto begin = at.begin() + first[v], end = at.begin() + first[v + 1];
        if (end - begin < 2) continue;
        std::sort(begin, end, [&](uint32_t a, uint32_t b) {
            const uint32_t pa = part[borders[a].triangle], pb = part[borders[b].triangle];
            return pa != pb ? pa < pb : a < b;
        });
        for (auto e = begin + 1; e != end; ++e)
            if (part[borders[*e].triangle] == part[borders[*(e - 1)].triangle]) {
                const uint32_t a = find(*e), b = find(*(e - 1));
                if (a != b) root[std::max(a, b)] = std::min(a, b);
            }
    }
    std::vector<uint32_t>().swap(at);
    std::vector<uint32_t>().swap(first);
    // A welded corner is a vertex index (weld_by_position: the first vertex at that position).
    std::vector<glm::dvec3> apex(borders.size(), glm::dvec3(0.0));
    std::vector<double> weight(borders.size(), 0.0);
    for (uint32_t i = 0; i < borders.size(); ++i) {
        if (!counted(i)) continue;
        const glm::dvec3 a(mesh.positions[borders[i].from]), b(mesh.positions[borders[i].to]);
        const uint32_t r = find(i);
        apex[r] += 0.5 * (a + b), weight[r] += 1.0;
    }
    for (uint32_t i = 0; i < borders.size(); ++i) {
        if (!counted(i)) continue;
        const uint32_t p = part[borders[i].triangle];
        const uint32_t r = find(i);
        const glm::dvec3 o = centre[p];
        glm::dvec3 a = glm::dvec3(mesh.positions[borders[i].from]) - o, b = glm::dvec3(mesh.positions[borders[i].to]) - o;
        if (flipped(borders[i].triangle)) std::swap(a, b);  // the triangle walks a -> b; its fan triangle b -> a
        const glm::dvec3 c = apex[r] / weight[r] - o;
        const double area = 0.5 * glm::length(glm::cross(a - c, b - c));
        const double volume = glm::dot(b, glm::cross(a, c)) / 6.0;
        if (!std::isfinite(area) || !std::isfinite(volume)) continue;
        caps.area[p] += area;
        caps.volume[p] += volume;
        caps.unsigned_volume[p] += std::abs(volume);
    }
    return caps;
}

}  // namespace

double signed_volume(const Mesh& mesh) {
    const glm::dvec3 origin = glm::dvec3(compute_bounds(mesh).center());
    double volume = 0.0;
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
        const glm::dvec3 a = corner_position(mesh, t, 0) - origin;
        const glm::dvec3 b = corner_position(mesh, t, 1) - origin;
        const glm::dvec3 c = corner_position(mesh, t, 2) - origin;
        volume += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return volume;
}

namespace {

// For each triangle, the earlier triangle it reverses (the same welded corners in the other cyclic order), or
// kUnassigned: a sheet made two-sided by a reversed copy. (Repeats in the same order were dropped before.)
std::vector<uint32_t> reversed_twins(const Mesh& mesh, std::span<const uint32_t> corner) {
    // A reversed copy lies in its first's bucket (bucket_by_smallest_corner; a comparison sort of every triangle
    // took 0.16 s of an 869k-triangle load).
    const CornerBuckets buckets = bucket_by_smallest_corner(mesh, corner, true);
    const size_t triangles = mesh.triangle_count();
    std::vector<uint32_t> twin(triangles, kUnassigned);
    std::vector<uint8_t> taken(triangles, 0);  // a first that has its twin
    for (size_t v = 0; v + 1 < buckets.first.size(); ++v) {
        const auto begin = buckets.entries.begin() + buckets.first[v], end = buckets.entries.begin() + buckets.first[v + 1];
        for (auto e = begin; e != end; ++e) {
            // The earliest triangle of the other order; a later triangle is its twin.
            const auto other = std::lower_bound(begin, end, CornerBuckets::Entry{e->third, e->second, 0}, CornerBuckets::before);
            if (other == end || other->second != e->third || other->third != e->second) continue;
            if (other->triangle < e->triangle && !taken[other->triangle] && twin[other->triangle] == kUnassigned)
                twin[e->triangle] = other->triangle, taken[other->triangle] = 1;
        }
    }
    return twin;
}

WindingRepair orient_parts(Mesh& mesh, std::span<const uint32_t> corners, bool normals_from_file);

}  // namespace

WindingRepair orient_consistently(Mesh& mesh) { return orient_consistently(mesh, weld_by_position(mesh.positions)); }

size_t border_edge_count(const Mesh& mesh) {
    if (mesh.winding.parts > 0) return mesh.winding.border_edges;
    return manifold_adjacency(mesh, weld_by_position(mesh.positions)).borders.size();
}

// A sheet made two-sided by a reversed copy (an export's "double-sided"): every edge of it has four triangles,
// so no edge joined two and each triangle was a part of its own, turned or not by the rounding of a volume of
// nothing (8,594 of a curved sheet's 24,964 turned: both copies then faced one way in places, drawn twice, with
// lines along every cell). The twins are set aside, the rest oriented, and each twin wound against its first.
WindingRepair orient_consistently(Mesh& mesh, std::span<const uint32_t> corners, bool normals_from_file) {
    const std::vector<uint32_t> twin = reversed_twins(mesh, corners);
    if (std::all_of(twin.begin(), twin.end(), [](uint32_t t) { return t == kUnassigned; }))
        return orient_parts(mesh, corners, normals_from_file);
    const size_t triangles = mesh.triangle_count();
    Mesh kept;
    kept.positions = std::move(mesh.positions);
    kept.normals = std::move(mesh.normals);
    std::vector<uint32_t> kept_at(triangles, kUnassigned);
    for (size_t t = 0; t < triangles; ++t) {
        if (twin[t] != kUnassigned) continue;
        kept_at[t] = uint32_t(kept.triangle_count());
        kept.indices.insert(kept.indices.end(), mesh.indices.begin() + 3 * t, mesh.indices.begin() + 3 * t + 3);
    }
    WindingRepair repair = orient_parts(kept, corners, normals_from_file);
    mesh.positions = std::move(kept.positions);
    mesh.normals = std::move(kept.normals);
    // Turned where its first was turned (only corners 1 and 2 swap).
    std::vector<uint8_t> turned(triangles, 0);
    for (size_t t = 0; t < triangles; ++t) {
        if (kept_at[t] == kUnassigned) continue;
        turned[t] = kept.indices[3 * kept_at[t] + 1] != mesh.indices[3 * t + 1];
        std::copy_n(kept.indices.begin() + 3 * kept_at[t], 3, mesh.indices.begin() + 3 * t);
    }
    for (size_t t = 0; t < triangles; ++t)
        if (twin[t] != kUnassigned && turned[twin[t]]) std::swap(mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]), ++repair.triangles_turned;
    return repair;
}

namespace {

WindingRepair orient_parts(Mesh& mesh, std::span<const uint32_t> corners, bool normals_from_file) {
    const size_t triangles = mesh.triangle_count();
    const Adjacency adjacency = manifold_adjacency(mesh, corners);
    WindingRepair repair;
    repair.border_edges = adjacency.borders.size();

    // 1. Parts and a winding for each, breadth first from the lowest triangle of each part.
    std::vector<uint32_t> part(triangles, kUnassigned);
    std::vector<uint8_t> turn(triangles, 0);
    std::vector<uint32_t> queue;
    for (size_t seed = 0; seed < triangles; ++seed) {
        if (part[seed] != kUnassigned || !indices_in_range(mesh, seed)) continue;
        const uint32_t p = uint32_t(repair.parts++);
        part[seed] = p;
        queue.assign(1, uint32_t(seed));
        for (size_t head = 0; head < queue.size(); ++head) {
            const uint32_t t = queue[head];
            for (uint32_t e = adjacency.first[t]; e < adjacency.first[t + 1]; ++e) {
                const uint32_t other = adjacency.entries[e] >> 1;
                const uint8_t wanted = turn[t] ^ uint8_t(adjacency.entries[e] & 1u);
                if (part[other] == kUnassigned) {
                    part[other] = p;
                    turn[other] = wanted;
                    queue.push_back(other);
                } else if (turn[other] != wanted && t < other) {
                    ++repair.conflicting_edges;
                }
            }
        }
    }

    // 2. Of a part's two windings, the one that turns less of its area.
    struct PartFigures {
        double area = 0.0, turned_area = 0.0;
        glm::dvec3 lo{std::numeric_limits<double>::max()}, hi{std::numeric_limits<double>::lowest()};
        bool closed = true;  // every edge joins two of its triangles: its signed volume does not depend on the origin
        double volume = 0.0;
        double unsigned_volume = 0.0;  // the sum of its triangles' tetrahedra's volumes, each taken positive
    };
    std::vector<PartFigures> figures(repair.parts);
    for (size_t t = 0; t < triangles; ++t) {
        if (part[t] == kUnassigned) continue;
        PartFigures& f = figures[part[t]];
        if (adjacency.on_border[t]) f.closed = false;
        const double area = triangle_area(mesh, t);
        if (!std::isfinite(area)) continue;
        f.area += area;
        if (turn[t]) f.turned_area += area;
        for (int k = 0; k < 3; ++k) {
            f.lo = glm::min(f.lo, corner_position(mesh, t, k));
            f.hi = glm::max(f.hi, corner_position(mesh, t, k));
        }
    }
    std::vector<uint8_t> invert(repair.parts, 0);
    for (size_t p = 0; p < repair.parts; ++p) invert[p] = figures[p].turned_area > 0.5 * figures[p].area;
    for (size_t t = 0; t < triangles; ++t) repair.wound_against += part[t] != kUnassigned && turn[t] != invert[part[t]];

    // 3. Outward. A closed part by its own signed volume; an open part nearly closed by its volume with its
    // holes capped (cap_holes); an open part open wider keeps its winding.
    auto signed_volume_about = [&](size_t t, glm::dvec3 centre) {
        const glm::dvec3 a = corner_position(mesh, t, 0) - centre;
        glm::dvec3 b = corner_position(mesh, t, 1) - centre, c = corner_position(mesh, t, 2) - centre;
        if (turn[t] != invert[part[t]]) std::swap(b, c);
        const double volume = glm::dot(a, glm::cross(b, c)) / 6.0;
        return std::isfinite(volume) ? volume : 0.0;
    };
    // A closed part's volume does not depend on where it is taken from: it is negative only when the part is
    // inside out, whatever its shape. Against the unsigned sum, not the box: a thin rod or a coil lying
    // across its box encloses far less than 1% of it (a diagonal prism inside out, 0.5%, was left so until
    // 2026-12-04). A thousandth of the unsigned sum is far above rounding and far below any real solid.
    auto closed_part_inside_out = [](const PartFigures& f) { return f.volume < -1e-3 * f.unsigned_volume; };
    for (size_t t = 0; t < triangles; ++t) {
        if (part[t] == kUnassigned || !figures[part[t]].closed) continue;
        PartFigures& f = figures[part[t]];
        const double volume = signed_volume_about(t, 0.5 * (f.lo + f.hi));
        f.volume += volume;
        f.unsigned_volume += std::abs(volume);
    }
    // An open part whose faces the file's normals clearly contradict (area-weighted mean cosine below -1/2)
    // follows them, where the file's normals clearly agree with more of the open parts' area than they
    // contradict: a loose panel of an export wound against the rest, which no volume can tell. Where the
    // normals contradict most of it, they are what is wrong (an open scan wound outward with its normals
    // inward was turned inside out by them, until the review of 2026-12-04), and a lone part says nothing;
    // the volume decides those. Where they agree, the volume still decides too: a scan's normals may be as
    // inside out as its winding (the horse's are).
    std::vector<uint8_t> decided_by_normals(repair.parts, 0);
    if (normals_from_file && mesh.normals.size() == mesh.positions.size()) {
        std::vector<double> agreement(repair.parts, 0.0);
        for (size_t t = 0; t < triangles; ++t) {
            if (part[t] == kUnassigned || figures[part[t]].closed) continue;
            const glm::dvec3 a = corner_position(mesh, t, 0);
            glm::dvec3 face = glm::cross(corner_position(mesh, t, 1) - a, corner_position(mesh, t, 2) - a);
            if (turn[t] != invert[part[t]]) face = -face;
            const double length = glm::length(face);
            if (!(length > 0.0) || !std::isfinite(length)) continue;
            glm::dvec3 normal(0.0);
            for (int k = 0; k < 3; ++k) normal += glm::dvec3(mesh.normals[mesh.indices[3 * t + k]]);
            const double normal_length = glm::length(normal);
            if (normal_length > 0.0) agreement[part[t]] += 0.5 * glm::dot(face, normal) / normal_length;
        }
        double agreeing = 0.0, contradicted = 0.0;  // open area whose normals clearly agree, or contradict
        for (size_t p = 0; p < repair.parts; ++p) {
            if (figures[p].closed || !(figures[p].area > 0.0)) continue;
            if (agreement[p] > 0.5 * figures[p].area) agreeing += figures[p].area;
            if (agreement[p] < -0.5 * figures[p].area) contradicted += figures[p].area;
        }
        for (size_t p = 0; p < repair.parts && agreeing > contradicted; ++p) {
            if (figures[p].closed || !(figures[p].area > 0.0)) continue;
            if (agreement[p] < -0.5 * figures[p].area) {
                invert[p] ^= 1, ++repair.parts_turned_outward, ++repair.parts_turned_to_normals;
                decided_by_normals[p] = 1;
            }
        }
    }
    for (size_t p = 0; p < repair.parts; ++p)
        if (figures[p].closed && closed_part_inside_out(figures[p])) {
            invert[p] ^= 1;
            ++repair.parts_turned_outward;
        }
    // An open part nearly closed (its holes' caps under kNearlyClosed of its area: a scan with holes) is turned
    // when, its holes capped, it is inside out as a closed part is. A part open wider (a bowl, a valley, a room
    // open at the front, a sheet) encloses nothing: which side it shows is the file's, its majority's winding.
    // Until 2026-12-05 the open parts were turned together by the whole model's volume about its box's centre,
    // which turned a valley or a room wound to face its hollow (the side it is seen from) away, and it drew no
    // stipples from there.
    std::vector<glm::dvec3> centre(repair.parts);
    for (size_t p = 0; p < repair.parts; ++p) centre[p] = 0.5 * (figures[p].lo + figures[p].hi);
    for (size_t t = 0; t < triangles; ++t) {
        if (part[t] == kUnassigned || figures[part[t]].closed || decided_by_normals[part[t]]) continue;
        PartFigures& f = figures[part[t]];
        const double volume = signed_volume_about(t, centre[part[t]]);
        f.volume += volume;
        f.unsigned_volume += std::abs(volume);
    }
    std::vector<uint8_t> open_undecided(repair.parts, 0);
    for (size_t p = 0; p < repair.parts; ++p) open_undecided[p] = !figures[p].closed && !decided_by_normals[p];
    const PartCaps caps = cap_holes(mesh, adjacency.borders, part, open_undecided,
                                    [&](uint32_t t) { return turn[t] != invert[part[t]]; }, centre, repair.parts);
    for (size_t p = 0; p < repair.parts; ++p) {
        PartFigures& f = figures[p];
        if (f.closed || decided_by_normals[p] || !(caps.area[p] < kNearlyClosed * f.area)) continue;
        f.volume += caps.volume[p];
        f.unsigned_volume += caps.unsigned_volume[p];
        if (closed_part_inside_out(f)) invert[p] ^= 1, ++repair.parts_turned_outward;
    }

    for (size_t t = 0; t < triangles; ++t) {
        if (part[t] == kUnassigned || turn[t] == invert[part[t]]) continue;
        std::swap(mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]);
        ++repair.triangles_turned;
    }
    return repair;
}

}  // namespace

size_t turn_normals_to_faces(Mesh& mesh) {
    if (mesh.normals.size() != mesh.positions.size()) return 0;
    std::vector<double> agreement(mesh.positions.size(), 0.0);
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
        if (!indices_in_range(mesh, t)) continue;
        const glm::dvec3 a = corner_position(mesh, t, 0);
        const glm::dvec3 face = glm::cross(corner_position(mesh, t, 1) - a, corner_position(mesh, t, 2) - a);
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = mesh.indices[3 * t + k];
            agreement[v] += glm::dot(face, glm::dvec3(mesh.normals[v]));
        }
    }
    size_t turned = 0;
    for (size_t v = 0; v < agreement.size(); ++v)
        if (agreement[v] < 0.0) mesh.normals[v] = -mesh.normals[v], ++turned;
    return turned;
}

}  // namespace stipple
