#include "mesh/mesh_ops.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

#include <meshoptimizer.h>

#include "core/error.hpp"
#include "core/parallel.hpp"

namespace stipple {

namespace {

// Keeps only the vertices the triangles use, in first-use order (deterministic).
Mesh compact(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices, const std::string& source) {
    Mesh out;
    out.source = source;
    std::vector<uint32_t> remap(positions.size(), UINT32_MAX);
    out.indices.reserve(indices.size());
    for (uint32_t i : indices) {
        if (remap[i] == UINT32_MAX) {
            remap[i] = uint32_t(out.positions.size());
            out.positions.push_back(positions[i]);
        }
        out.indices.push_back(remap[i]);
    }
    compute_vertex_normals(out);
    return out;
}

}  // namespace

Mesh weld_positions(const Mesh& mesh) {
    std::vector<uint32_t> remap(mesh.positions.size());
    size_t unique = meshopt_generateVertexRemap(remap.data(), mesh.indices.data(), mesh.indices.size(),
                                                mesh.positions.data(), mesh.positions.size(), sizeof(glm::vec3));
    std::vector<glm::vec3> positions(unique);
    meshopt_remapVertexBuffer(positions.data(), mesh.positions.data(), mesh.positions.size(), sizeof(glm::vec3),
                              remap.data());
    std::vector<uint32_t> indices(mesh.indices.size());
    meshopt_remapIndexBuffer(indices.data(), mesh.indices.data(), mesh.indices.size(), remap.data());
    return compact(positions, indices, mesh.source);
}

namespace {

// Union-find's root, halving the path on the way.
uint32_t weld_root(std::vector<uint32_t>& parent, uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
}

}  // namespace

std::vector<uint32_t> weld_by_position(std::span<const glm::vec3> positions) {
    const size_t n = positions.size();
    std::vector<uint32_t> parent(n);
    for (size_t v = 0; v < n; ++v) parent[v] = uint32_t(v);
    // Positions a rounding step or so apart are one corner too (kWeldFloatSteps): an export that wrote each
    // face's corners with its own rounding left every triangle a part of its own, and its lines in dashes or
    // none. Measured in steps of each coordinate's own float, not in the model's size: a model sharing its
    // file with a large ground plane, or holding one stray vertex far away, keeps its fine detail (a tolerance
    // of a millionth of the whole file's extent collapsed and dropped most of a bunny beside a 600-unit quad).
    // Keys: each coordinate's bits as an ordered integer (adjacent floats adjacent, -0 and +0 one), in buckets
    // of twice kWeldFloatSteps, each axis at offset 0 or half a bucket (8 grids): two positions within
    // kWeldFloatSteps on every axis share a bucket of one of them (on each axis a bucket boundary falls
    // between them at most at one of the two offsets). Hashed as bytes by meshoptimizer (an unordered_map took
    // a fifth of the winding repair's time on an 871k-triangle scan). Positions that are not numbers keep
    // their own corner (their bits as they are).
    const auto ordered = [](float x) {
        uint32_t bits;
        std::memcpy(&bits, &x, sizeof bits);
        const int64_t magnitude = int64_t(bits & 0x7FFFFFFFu);
        return (bits & 0x80000000u) ? -magnitude : magnitude;  // -0 and +0 both 0
    };
    constexpr int64_t kBucket = 2 * kWeldFloatSteps;
    constexpr int kGrids = 8;
    // Two grids at a time, their keys and ids side by side on two cores, then joined in order on one: at most
    // 32 bytes a position more (the loaded mesh's budget, loader_util.cpp).
    constexpr int kGridsAtOnce = 2;
    std::vector<uint32_t> ids[kGridsAtOnce];
    std::vector<uint32_t> first;
    for (int batch = 0; batch < kGrids; batch += kGridsAtOnce) {
        parallel_for(size_t(kGridsAtOnce), 1, [&](size_t k) {
            const int grid = batch + int(k);
            std::vector<int32_t> keys(3 * n);
            for (size_t v = 0; v < n; ++v) {
                const glm::vec3& p = positions[v];
                const bool finite = std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
                for (int axis = 0; axis < 3; ++axis) {
                    const int64_t o = ordered(p[axis]) + ((grid >> axis) & 1 ? kBucket / 2 : 0);
                    // Floor division: buckets of equal width on both sides of zero.
                    keys[3 * v + axis] = finite ? int32_t(o >= 0 ? o / kBucket : -((-o + kBucket - 1) / kBucket))
                                                : int32_t(ordered(p[axis]));
                }
            }
            ids[k].resize(n);
            meshopt_generateVertexRemap(ids[k].data(), nullptr, n, keys.data(), n, 3 * sizeof(int32_t));
        });
        for (int k = 0; k < kGridsAtOnce; ++k) {
            first.assign(n, UINT32_MAX);  // ids are below n
            for (size_t v = 0; v < n; ++v) {
                const uint32_t id = ids[k][v];
                if (first[id] == UINT32_MAX) {
                    first[id] = uint32_t(v);
                    continue;
                }
                const uint32_t a = weld_root(parent, first[id]), b = weld_root(parent, uint32_t(v));
                parent[std::max(a, b)] = std::min(a, b);  // the root is the first position of the set
            }
        }
    }
    std::vector<uint32_t> representative(n);
    for (size_t v = 0; v < n; ++v) representative[v] = weld_root(parent, uint32_t(v));
    return representative;
}

size_t drop_duplicate_triangles(Mesh& mesh) { return drop_duplicate_triangles(mesh, weld_by_position(mesh.positions)); }

size_t drop_duplicate_triangles(Mesh& mesh, std::span<const uint32_t> corner, bool collapsed_by_position) {
    const size_t triangles = mesh.triangle_count(), n = mesh.positions.size();
    std::vector<uint8_t> repeat(triangles, 0);
    size_t dropped = 0;
    for (size_t t = 0; t < triangles; ++t) {
        const uint32_t* i = &mesh.indices[3 * t];
        if (i[0] >= n || i[1] >= n || i[2] >= n) continue;
        const uint32_t a = corner[i[0]], b = corner[i[1]], c = corner[i[2]];
        const bool named_twice = i[0] == i[1] || i[1] == i[2] || i[0] == i[2];
        if (named_twice || (collapsed_by_position && (a == b || b == c || a == c))) repeat[t] = 1, ++dropped;
    }
    // A repeat follows its first in their bucket. (Comparing every pair of a bucket took 8 s for one polygon of
    // 100k corners fanned around its first corner.)
    const CornerBuckets buckets = bucket_by_smallest_corner(mesh, corner, false);
    for (size_t v = 0; v < n; ++v)
        for (uint32_t i = buckets.first[v] + 1; i < buckets.first[v + 1]; ++i) {
            const CornerBuckets::Entry &e = buckets.entries[i], &previous = buckets.entries[i - 1];
            if (e.second == previous.second && e.third == previous.third && !repeat[e.triangle]) repeat[e.triangle] = 1, ++dropped;
        }
    if (dropped == 0) return 0;
    size_t kept = 0;
    for (size_t t = 0; t < triangles; ++t) {
        if (repeat[t]) continue;
        for (int k = 0; k < 3; ++k) mesh.indices[3 * kept + k] = mesh.indices[3 * t + k];
        ++kept;
    }
    mesh.indices.resize(3 * kept);
    return dropped;
}

CornerBuckets bucket_by_smallest_corner(const Mesh& mesh, std::span<const uint32_t> corner, bool skip_collapsed) {
    const size_t triangles = mesh.triangle_count(), n = mesh.positions.size();
    using Entry = CornerBuckets::Entry;
    auto rotated = [&](size_t t, uint32_t& smallest, Entry& entry) {
        const uint32_t* i = &mesh.indices[3 * t];
        if (i[0] >= n || i[1] >= n || i[2] >= n) return false;
        const uint32_t a = corner[i[0]], b = corner[i[1]], c = corner[i[2]];
        if (skip_collapsed && (a == b || b == c || a == c)) return false;
        if (a <= b && a <= c) smallest = a, entry = {b, c, uint32_t(t)};
        else if (b <= c) smallest = b, entry = {c, a, uint32_t(t)};
        else smallest = c, entry = {a, b, uint32_t(t)};
        return true;
    };
    CornerBuckets buckets;
    buckets.first.assign(n + 1, 0);
    uint32_t smallest = 0;
    Entry entry{};
    for (size_t t = 0; t < triangles; ++t)
        if (rotated(t, smallest, entry)) ++buckets.first[smallest + 1];
    for (size_t v = 0; v < n; ++v) buckets.first[v + 1] += buckets.first[v];
    buckets.entries.resize(buckets.first[n]);
    std::vector<uint32_t> fill(buckets.first.begin(), buckets.first.end() - 1);
    for (size_t t = 0; t < triangles; ++t)
        if (rotated(t, smallest, entry)) buckets.entries[fill[smallest]++] = entry;
    for (size_t v = 0; v < n; ++v)
        if (buckets.first[v + 1] - buckets.first[v] > 1)
            std::sort(buckets.entries.begin() + buckets.first[v], buckets.entries.begin() + buckets.first[v + 1], CornerBuckets::before);
    return buckets;
}

size_t split_vertices_between_opposite_sides(Mesh& mesh) {
    const size_t n = mesh.positions.size(), triangles = mesh.triangle_count();
    // Each triangle's normal times twice its area; zero where it has none or refers beyond the vertices.
    std::vector<glm::dvec3> faces(triangles, glm::dvec3(0.0));
    for (size_t t = 0; t < triangles; ++t) {
        const uint32_t* i = &mesh.indices[3 * t];
        if (i[0] >= n || i[1] >= n || i[2] >= n) continue;
        const glm::dvec3 a(mesh.positions[i[0]]);
        const glm::dvec3 f = glm::cross(glm::dvec3(mesh.positions[i[1]]) - a, glm::dvec3(mesh.positions[i[2]]) - a);
        if (std::isfinite(f.x) && std::isfinite(f.y) && std::isfinite(f.z)) faces[t] = f;
    }
    auto in_range = [&](size_t t) {
        return mesh.indices[3 * t] < n && mesh.indices[3 * t + 1] < n && mesh.indices[3 * t + 2] < n;
    };
    // Each vertex's largest face, then how much of its faces' area lies on either side of it.
    std::vector<glm::dvec3> largest(n, glm::dvec3(0.0));
    for (size_t t = 0; t < triangles; ++t) {
        if (!in_range(t)) continue;
        const glm::dvec3 f = faces[t];
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = mesh.indices[3 * t + k];
            if (glm::dot(f, f) > glm::dot(largest[v], largest[v])) largest[v] = f;
        }
    }
    std::vector<double> total(n, 0.0), along(n, 0.0), against(n, 0.0);
    for (size_t t = 0; t < triangles; ++t) {
        if (!in_range(t)) continue;
        const glm::dvec3 f = faces[t];
        const double length = glm::length(f);
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = mesh.indices[3 * t + k];
            const double length_of_largest = glm::length(largest[v]);
            if (!(length > 0.0) || !(length_of_largest > 0.0)) continue;
            const double cosine = glm::dot(f, largest[v]) / (length * length_of_largest);
            total[v] += length;
            if (cosine > 0.9) along[v] += length;
            if (cosine < -0.9) against[v] += length;
        }
    }
    // Both sides of one sheet: a fifth of the area at least on either side, within 26 degrees of the largest
    // face's normal and of its opposite. A fleck of a scan folded back stays with its neighbours, and so does
    // the corner of any solid but a needle's (a tetrahedron's faces are 125 degrees apart); a knife edge
    // gets the crease it should have anyway.
    std::vector<uint32_t> other_side(n, UINT32_MAX);
    size_t split = 0;
    for (size_t v = 0; v < n; ++v) {
        if (!(total[v] > 0.0) || along[v] < 0.2 * total[v] || against[v] < 0.2 * total[v]) continue;
        other_side[v] = uint32_t(mesh.positions.size() + split++);
    }
    if (split == 0) return 0;
    STIPPLE_CHECK(mesh.positions.size() + split <= UINT32_MAX, "too many vertices for 32-bit indices");
    const bool has_normals = mesh.normals.size() == n;
    for (size_t v = 0; v < n; ++v) {
        if (other_side[v] == UINT32_MAX) continue;
        mesh.positions.push_back(mesh.positions[v]);
        if (has_normals) mesh.normals.push_back(-mesh.normals[v]);
    }
    // The faces turned away from the vertex's largest face move to its copy.
    for (size_t t = 0; t < triangles; ++t) {
        if (!in_range(t)) continue;
        const glm::dvec3 f = faces[t];
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = mesh.indices[3 * t + k];
            if (v < n && other_side[v] != UINT32_MAX && glm::dot(f, largest[v]) < 0.0) mesh.indices[3 * t + k] = other_side[v];
        }
    }
    return split;
}

Mesh subdivide_midpoints(const Mesh& mesh) {
    Mesh out;
    out.source = mesh.source;
    out.positions = mesh.positions;
    out.positions.reserve(mesh.positions.size() + mesh.indices.size() / 2 + 16);
    out.indices.reserve(mesh.indices.size() * 4);
    std::unordered_map<uint64_t, uint32_t> midpoints;
    midpoints.reserve(mesh.indices.size());
    auto midpoint = [&](uint32_t a, uint32_t b) {
        uint64_t key = a < b ? (uint64_t(a) << 32 | b) : (uint64_t(b) << 32 | a);
        auto [it, inserted] = midpoints.try_emplace(key, uint32_t(out.positions.size()));
        if (inserted) out.positions.push_back(0.5f * (mesh.positions[a] + mesh.positions[b]));
        return it->second;
    };
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
        out.indices.insert(out.indices.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
    }
    compute_vertex_normals(out);
    return out;
}

SimplifyResult simplify_to(const Mesh& mesh, size_t target, double tolerance) {
    const size_t count = mesh.triangle_count();
    if (within(count, target, tolerance)) return {mesh, "as is", 0.0f};
    if (count < target)
        fail(mesh.source + ": " + std::to_string(count) + " triangles cannot be simplified up to " +
             std::to_string(target) + " (subdivide first)");
    const size_t target_indices = 3 * target;
    const size_t limit = size_t(double(target) * (1.0 + tolerance));
    std::vector<uint32_t> indices(mesh.indices.size());
    SimplifyResult result;
    // Errors are relative to the mesh's extent; 1 allows any collapse the topology permits.
    for (float error : {0.001f, 0.004f, 0.016f, 0.064f, 0.25f, 1.0f}) {
        float reached = 0.0f;
        size_t n = meshopt_simplify(indices.data(), mesh.indices.data(), mesh.indices.size(),
                                    &mesh.positions[0].x, mesh.positions.size(), sizeof(glm::vec3), target_indices,
                                    error, 0, &reached);
        if (n / 3 <= limit) {
            indices.resize(n);
            char method[64];
            std::snprintf(method, sizeof method, "simplify (error bound %g)", double(error));
            result.method = method;
            result.error = reached;
            break;
        }
    }
    if (result.method.empty()) {
        float reached = 0.0f;
        size_t n = meshopt_simplifySloppy(indices.data(), mesh.indices.data(), mesh.indices.size(),
                                          &mesh.positions[0].x, mesh.positions.size(), sizeof(glm::vec3),
                                          target_indices, 1.0f, &reached);
        indices.resize(n);
        result.method = "simplifySloppy";
        result.error = reached;
    }
    if (!within(indices.size() / 3, target, tolerance))
        fail(mesh.source + ": simplification reached " + std::to_string(indices.size() / 3) +
             " triangles, not within " + std::to_string(int(tolerance * 100)) + "% of " + std::to_string(target));
    result.mesh = compact(mesh.positions, indices, mesh.source);
    return result;
}

}  // namespace stipple
