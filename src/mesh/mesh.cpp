#include "mesh/mesh.hpp"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <meshoptimizer.h>

#include "core/error.hpp"

namespace stipple {

namespace {

glm::dvec3 to_double(const glm::vec3& v) { return glm::dvec3(v); }

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

void compute_vertex_normals(Mesh& mesh) {
    // Accumulate in double: the unnormalised cross product is twice the face area, so summing it
    // weights each face by its area; float sums lose the small faces of dense scans.
    std::vector<glm::dvec3> sum(mesh.positions.size(), glm::dvec3(0.0));
    const size_t vertex_count = mesh.positions.size();
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        // Skipped rather than trusted: this runs before validate_mesh reports bad indices.
        if (a >= vertex_count || b >= vertex_count || c >= vertex_count) continue;
        const glm::dvec3 pa = to_double(mesh.positions[a]);
        const glm::dvec3 n = glm::cross(to_double(mesh.positions[b]) - pa, to_double(mesh.positions[c]) - pa);
        if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z)) continue;
        sum[a] += n;
        sum[b] += n;
        sum[c] += n;
    }
    mesh.normals.resize(vertex_count);
    for (size_t i = 0; i < vertex_count; ++i) {
        const double length = glm::length(sum[i]);
        mesh.normals[i] = length > 0.0 ? glm::vec3(sum[i] / length) : glm::vec3(0.0f, 0.0f, 1.0f);
    }
}

void validate_mesh(const Mesh& mesh) {
    const std::string& source = mesh.source;
    if (mesh.indices.size() % 3 != 0)
        fail_file(source, "index count " + std::to_string(mesh.indices.size()) + " is not a multiple of 3");
    if (mesh.indices.empty()) fail_file(source, "the model has no triangles");
    const size_t vertex_count = mesh.positions.size();
    for (size_t i = 0; i < mesh.indices.size(); ++i) {
        if (mesh.indices[i] >= vertex_count)
            fail_file(source, "face " + std::to_string(i / 3) + " refers to vertex " +
                                  std::to_string(mesh.indices[i]) + " but there are only " +
                                  std::to_string(vertex_count) + " vertices");
    }
    for (size_t i = 0; i < vertex_count; ++i) {
        const glm::vec3& p = mesh.positions[i];
        if (std::isnan(p.x) || std::isnan(p.y) || std::isnan(p.z))
            fail_file(source, "vertex " + std::to_string(i) + " has a NaN coordinate");
        if (!finite(p)) fail_file(source, "vertex " + std::to_string(i) + " has an infinite coordinate");
    }
    // Size and place are the drawn surface's: vertices no face uses are dropped before drawing
    // (optimize_draw_order), so one left at the origin must not hide a model far from it, nor one far away
    // refuse a model near it.
    std::vector<uint8_t> used(vertex_count, 0);
    for (uint32_t i : mesh.indices) used[i] = 1;
    glm::vec3 lo{std::numeric_limits<float>::max()}, hi{std::numeric_limits<float>::lowest()};
    for (size_t i = 0; i < vertex_count; ++i) {
        if (!used[i]) continue;
        const glm::vec3& p = mesh.positions[i];
        const float largest = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
        if (largest > kMaxCoordinate) {
            // Named by where it lies: a loader may number the vertices otherwise than the file does (OBJ counts from
            // 1 and splits a vertex by its normals; this counted from 0 in the loaded order).
            char text[200];
            std::snprintf(text, sizeof(text), "a vertex at (%g, %g, %g) has a coordinate of %g, beyond the %g units it can be drawn within",
                          double(p.x), double(p.y), double(p.z), double(largest), double(kMaxCoordinate));
            fail_file(source, text);
        }
        lo = glm::min(lo, p), hi = glm::max(hi, p);
    }
    const glm::vec3 size = hi - lo;
    const float extent = std::max({size.x, size.y, size.z});
    if (extent > 0.0f && extent < kMinExtent) {
        char text[160];
        std::snprintf(text, sizeof(text), "the model is %g units across, below the %g it can be drawn at: scale it up",
                      double(extent), double(kMinExtent));
        fail_file(source, text);
    }
    // Where the file has it (a model stored about its own centre keeps its shape, but the drawing puts it back
    // there in single precision: a sphere 1e7 times its size from the origin lost a tenth of its tone).
    const glm::dvec3 flo = glm::dvec3(lo) + mesh.origin, fhi = glm::dvec3(hi) + mesh.origin;
    const float offset = float(std::max({std::abs(flo.x), std::abs(flo.y), std::abs(flo.z), std::abs(fhi.x), std::abs(fhi.y), std::abs(fhi.z)}));
    if (extent > 0.0f && offset > kMaxOffsetOverExtent * extent) {
        char text[256];
        std::snprintf(text, sizeof(text),
                      "the model lies up to %g units from the origin along an axis, %g times its size (at most %g): the drawing places "
                      "it in single precision, which keeps too few digits there; move it near the origin",
                      double(offset), double(offset / extent), double(kMaxOffsetOverExtent));
        fail_file(source, text);
    }
    if (mesh.normals.size() != vertex_count)
        fail_file(source, "has " + std::to_string(mesh.normals.size()) + " normals for " +
                              std::to_string(vertex_count) + " vertices");
    for (size_t i = 0; i < mesh.normals.size(); ++i) {
        if (!finite(mesh.normals[i])) fail_file(source, "normal " + std::to_string(i) + " is not finite");
    }
}

Bounds compute_bounds(const Mesh& mesh) {
    if (mesh.positions.empty()) return Bounds{};
    Bounds b{mesh.positions[0], mesh.positions[0]};
    for (const glm::vec3& p : mesh.positions) {
        b.min = glm::min(b.min, p);
        b.max = glm::max(b.max, p);
    }
    return b;
}

glm::dvec3 far_origin(std::span<const glm::dvec3> positions) {
    if (positions.empty()) return glm::dvec3(0.0);
    glm::dvec3 lo(positions[0]), hi(positions[0]);
    for (const glm::dvec3& p : positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const glm::dvec3 size = hi - lo, centre = 0.5 * (lo + hi);
    const double extent = std::max({size.x, size.y, size.z});
    const double farthest = std::max({std::abs(lo.x), std::abs(lo.y), std::abs(lo.z), std::abs(hi.x), std::abs(hi.y), std::abs(hi.z)});
    if (!(extent > 0.0) || farthest > double(kMaxCoordinate)) return glm::dvec3(0.0);
    const double offset = std::max({std::abs(centre.x), std::abs(centre.y), std::abs(centre.z)});
    return offset > kRecentreOverExtent * extent ? centre : glm::dvec3(0.0);
}

glm::dvec3 far_origin(std::span<const glm::dvec3> positions, std::span<const uint32_t> indices) {
    std::vector<uint8_t> used(positions.size(), 0);
    for (const uint32_t v : indices)
        if (v < used.size()) used[v] = 1;
    std::vector<glm::dvec3> drawn;
    for (size_t v = 0; v < positions.size(); ++v)
        if (used[v]) drawn.push_back(positions[v]);
    return far_origin(drawn);
}

void store_about_far_origin(Mesh& mesh, std::span<const glm::dvec3> exact) {
    STIPPLE_CHECK(exact.size() == mesh.positions.size(), "one exact position per vertex");
    mesh.origin = far_origin(exact, mesh.indices);
    if (mesh.origin != glm::dvec3(0.0))
        for (size_t v = 0; v < exact.size(); ++v) mesh.positions[v] = glm::vec3(exact[v] - mesh.origin);
}

Mesh reflected_through_origin(const Mesh& mesh) {
    Mesh reflected = mesh;
    reflected.origin = -mesh.origin;
    for (glm::vec3& p : reflected.positions) p = -p;
    for (glm::vec3& n : reflected.normals) n = -n;
    for (size_t t = 0; t + 2 < reflected.indices.size(); t += 3) std::swap(reflected.indices[t + 1], reflected.indices[t + 2]);
    return reflected;
}

namespace {

// The linear part's stretch: its columns' length when it is a similarity (equal, orthogonal columns: then every
// direction is stretched by it), else a bound on its largest singular value, the root of the largest eigenvalue
// of its Gram matrix, which the Gram matrix's largest row sum bounds (the longest column alone does not: a
// shear stretches a diagonal farther).
struct Stretch {
    float most = 1.0f;
    bool similarity = true;
};
Stretch stretch_of(const glm::mat4& model) {
    const glm::mat3 linear(model);
    const float lengths[3] = {glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2])};
    const float longest = std::max({lengths[0], lengths[1], lengths[2]});
    Stretch s{longest, true};
    for (int i = 0; i < 3; ++i)
        if (std::abs(lengths[i] - longest) > 1e-5f * longest ||
            std::abs(glm::dot(linear[i], linear[(i + 1) % 3])) > 1e-5f * longest * longest)
            s.similarity = false;
    if (s.similarity) return s;
    const glm::mat3 gram = glm::transpose(linear) * linear;
    float most_row = 0.0f;
    for (int i = 0; i < 3; ++i) most_row = std::max(most_row, std::abs(gram[0][i]) + std::abs(gram[1][i]) + std::abs(gram[2][i]));
    s.most = std::sqrt(most_row);
    return s;
}

// The farthest image of the box's corners from `centre`.
float farthest_corner(const Bounds& box, const glm::mat4& model, const glm::vec3& centre) {
    float farthest = 0.0f;
    for (int corner = 0; corner < 8; ++corner)
        farthest = std::max(farthest, glm::length(glm::vec3(model * glm::vec4(box.corner(corner), 1.0f)) - centre));
    return farthest;
}

}  // namespace

float transformed_radius(const Sphere& sphere, const Bounds& box, const glm::mat4& model) {
    const Stretch s = stretch_of(model);
    if (s.similarity) return sphere.radius * s.most;
    return std::min(sphere.radius * s.most, farthest_corner(box, model, glm::vec3(model * glm::vec4(sphere.center, 1.0f))));
}

Sphere transformed_bounds(const Sphere& sphere, const Bounds& box, const glm::mat4& model) {
    const Stretch s = stretch_of(model);
    const glm::vec3 centre(model * glm::vec4(sphere.center, 1.0f));
    if (s.similarity) return {centre, sphere.radius * s.most};  // the sphere's image, as it always was
    const Sphere stretched{centre, sphere.radius * s.most};
    const glm::vec3 box_centre(model * glm::vec4(box.center(), 1.0f));
    const Sphere around_box{box_centre, farthest_corner(box, model, box_centre)};
    return around_box.radius < stretched.radius ? around_box : stretched;
}

Sphere compute_bounding_sphere(const Mesh& mesh) {
    const std::vector<glm::vec3>& points = mesh.positions;
    if (points.empty()) return Sphere{};
    // Ritter: two sweeps for a far-apart pair give the initial diameter.
    auto farthest_from = [&](const glm::dvec3& from) {
        size_t best = 0;
        double best_d2 = -1.0;
        for (size_t i = 0; i < points.size(); ++i) {
            const glm::dvec3 d = to_double(points[i]) - from;
            const double d2 = glm::dot(d, d);
            if (d2 > best_d2) best_d2 = d2, best = i;
        }
        return to_double(points[best]);
    };
    const glm::dvec3 y = farthest_from(to_double(points[0]));
    const glm::dvec3 z = farthest_from(y);
    glm::dvec3 center = 0.5 * (y + z);
    double radius = 0.5 * glm::length(z - y);
    // Grow towards every point left outside, moving the centre only as far as needed.
    for (const glm::vec3& p : points) {
        const glm::dvec3 q = to_double(p);
        const double d = glm::length(q - center);
        if (d > radius) {
            const double grown = 0.5 * (radius + d);
            center += (grown - radius) / d * (q - center);
            radius = grown;
        }
    }
    // Rounding in the growing pass can leave a point a hair outside, and so can converting the
    // centre to float: the radius is the true maximum distance from the float centre, padded so
    // that converting it to float cannot lose the guarantee either.
    const glm::vec3 c(center);
    double max_d = 0.0;
    for (const glm::vec3& p : points) max_d = std::max(max_d, glm::length(to_double(p) - to_double(c)));
    return Sphere{c, static_cast<float>(max_d * (1.0 + 1e-6))};
}

double triangle_area(const Mesh& mesh, size_t triangle) {
    const glm::dvec3 a = to_double(mesh.positions[mesh.indices[3 * triangle]]);
    const glm::dvec3 b = to_double(mesh.positions[mesh.indices[3 * triangle + 1]]);
    const glm::dvec3 c = to_double(mesh.positions[mesh.indices[3 * triangle + 2]]);
    return 0.5 * glm::length(glm::cross(b - a, c - a));
}

double total_area(const Mesh& mesh) {
    double sum = 0.0;
    for (size_t t = 0; t < mesh.triangle_count(); ++t) sum += triangle_area(mesh, t);
    return sum;
}

void append_mesh(Mesh& a, const Mesh& b) {
    if (a.source.empty()) a.source = b.source;
    const bool a_has_normals = a.positions.empty() || a.normals.size() == a.positions.size();
    const bool b_has_normals = b.normals.size() == b.positions.size();
    const auto offset = static_cast<uint32_t>(a.positions.size());
    STIPPLE_CHECK(a.positions.size() + b.positions.size() <= UINT32_MAX, "appended mesh exceeds 32-bit indices");
    a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
    // Normals only stay when both sides have a full set; otherwise they are dropped so that the
    // mismatch is visible (validate_mesh) and the caller recomputes them for the whole mesh.
    if (a_has_normals && b_has_normals)
        a.normals.insert(a.normals.end(), b.normals.begin(), b.normals.end());
    else
        a.normals.clear();
    // No exact reserve: a caller appending many small meshes (instances of one) would copy the whole list
    // at every call (250k instances of a triangle took 2 minutes); push_back grows it geometrically.
    for (uint32_t i : b.indices) a.indices.push_back(i + offset);
}

namespace {
// Above this many triangles on one vertex the draw order is optimised in linear time (optimize_draw_order).
constexpr uint32_t kMaxValenceForCacheOptimizer = 1024;
}  // namespace

void optimize_draw_order(Mesh& mesh) {
    if (mesh.indices.empty()) return;
    std::vector<uint32_t> reordered(mesh.indices.size());
    // meshopt_optimizeVertexCache rescores every triangle of a vertex in its cache at each step, so a vertex
    // shared by very many triangles costs their square (one polygon of 100k corners fanned around its
    // first: 7 s). Such meshes take the FIFO optimiser, linear in the triangles.
    std::vector<uint32_t> valence(mesh.positions.size(), 0);
    uint32_t most = 0;
    for (uint32_t i : mesh.indices)
        if (i < valence.size()) most = std::max(most, ++valence[i]);
    if (most <= kMaxValenceForCacheOptimizer)
        meshopt_optimizeVertexCache(reordered.data(), mesh.indices.data(), mesh.indices.size(), mesh.positions.size());
    else
        meshopt_optimizeVertexCacheFifo(reordered.data(), mesh.indices.data(), mesh.indices.size(), mesh.positions.size(), 16);
    std::vector<uint32_t> remap(mesh.positions.size());
    const size_t used = meshopt_optimizeVertexFetchRemap(remap.data(), reordered.data(), reordered.size(),
                                                         mesh.positions.size());
    meshopt_remapIndexBuffer(mesh.indices.data(), reordered.data(), reordered.size(), remap.data());
    std::vector<glm::vec3> positions(used), normals(mesh.normals.empty() ? 0 : used);
    meshopt_remapVertexBuffer(positions.data(), mesh.positions.data(), mesh.positions.size(), sizeof(glm::vec3),
                              remap.data());
    if (!normals.empty())
        meshopt_remapVertexBuffer(normals.data(), mesh.normals.data(), mesh.normals.size(), sizeof(glm::vec3),
                                  remap.data());
    mesh.positions.swap(positions);
    mesh.normals.swap(normals);
}

}  // namespace stipple
