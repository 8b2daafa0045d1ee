#pragma once
// Mesh operations: welding, midpoint subdivision, simplification to a triangle count (meshoptimizer).
// The benchmark derives its model set from the scans with them (src/bench/model_set.cpp).
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace stipple {

// Merges vertices at identical positions (meshopt_generateVertexRemap) and drops unused ones; normals
// are recomputed. Triangles are kept as they are (degenerate ones included).
Mesh weld_positions(const Mesh& mesh);

// Each vertex's representative: the first vertex at the same position, each coordinate within kWeldFloatSteps
// steps of its float (up to twice that where they share a bucket). A mesh whose corners are split (a triangle
// soup, a glTF primitive without indices, per-face normals or texture seams) would otherwise make every split
// edge a border; edge tables and the winding repair (mesh/orientation.hpp) are built on the representatives,
// which lie where the split corners do. Exported corners a rounding step apart (each face written with its
// own rounding) are split corners too: welded only where exactly equal until 2026-12-07, such a bunny drew its
// outline in dashes, a cube none.
inline constexpr int64_t kWeldFloatSteps = 4;
std::vector<uint32_t> weld_by_position(std::span<const glm::vec3> positions);

// Drops every triangle that repeats an earlier one: the same corners (welded by position) in the same
// cyclic order. Broken exports double whole surfaces, and each copy would get its own stipples at the same
// depth: twice the tone. A copy wound the other way is kept (a sheet made two-sided by a reversed copy
// shows its front from either side). Also drops every triangle two of whose corners lie at one place (a a b):
// it has no area and no edge of its own, but its edges, counted as faces' edges, drew creases fanning over a
// smooth surface and split its part in the winding repair (with `collapsed_by_position` off, only a triangle
// naming one vertex twice: an animation may pull two vertices at one place apart). Keeps the first of each and
// the order of the rest; returns how many were dropped. Indices beyond the positions are left for
// validate_mesh to report.
size_t drop_duplicate_triangles(Mesh& mesh);

// Each triangle rotated to start at its smallest corner (welded by position) and bucketed by that corner (a
// counting sort: comparison sorts of every triangle took much of a large scan's load), each bucket sorted by the
// other two corners, then by triangle: a repeat follows its first in their bucket, and a reversed copy (a, c, b)
// of (a, b, c) lies in the same bucket with those two swapped. Triangles with an index beyond the positions are
// left out, and with `skip_collapsed` those with two corners at one place.
struct CornerBuckets {
    struct Entry {
        uint32_t second, third, triangle;
    };
    static bool before(const Entry& x, const Entry& y) {
        return x.second != y.second ? x.second < y.second : x.third != y.third ? x.third < y.third : x.triangle < y.triangle;
    }
    std::vector<uint32_t> first;  // bucket v (a welded corner) holds entries [first[v], first[v + 1])
    std::vector<Entry> entries;
};
CornerBuckets bucket_by_smallest_corner(const Mesh& mesh, std::span<const uint32_t> corners, bool skip_collapsed);
// The same with the corners already welded (weld_by_position of mesh.positions).
size_t drop_duplicate_triangles(Mesh& mesh, std::span<const uint32_t> corners, bool collapsed_by_position = true);

// A sheet made two-sided by a reversed copy that shares its vertices (as files write it) gets computed
// normals that cancel: +n and -n summed at every vertex, +Z left, and the toon ramp reads those. A vertex
// with a fifth of its faces' area at least on either side (within 26 degrees of its largest face's normal,
// and of the opposite) is split in two: the faces turned away from its largest face move to a copy at the
// same position (its normal, if any, negated), one copy per vertex, so that each side stays smooth.
// Recompute the normals afterwards. Returns how many vertices were split.
size_t split_vertices_between_opposite_sides(Mesh& mesh);

// Each triangle into four by its edge midpoints; a midpoint shared by two triangles is one vertex.
// The mesh should be welded first (otherwise seams get duplicate midpoints). Normals are recomputed.
Mesh subdivide_midpoints(const Mesh& mesh);

// True when `count` is within `tolerance` (relative) of `target`.
inline bool within(size_t count, size_t target, double tolerance) {
    double d = double(count) - double(target);
    return (d < 0 ? -d : d) <= tolerance * double(target);
}

struct SimplifyResult {
    Mesh mesh;
    std::string method;   // "simplify (error 0.01)" or "simplifySloppy"
    float error = 0.0f;   // meshoptimizer's relative error of the result
};

// Simplifies a welded mesh to `target` triangles within `tolerance` (relative): meshopt_simplify with
// a growing error bound until the count is at most target * (1 + tolerance), then, if needed,
// meshopt_simplifySloppy. Deterministic. Throws stipple::Error when the count cannot be reached.
SimplifyResult simplify_to(const Mesh& mesh, size_t target, double tolerance);

}  // namespace stipple
