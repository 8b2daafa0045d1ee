#include "mesh/primitives.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>
#include <unordered_map>

#include "core/error.hpp"

namespace stipple {

namespace {

constexpr double kPi = 3.14159265358979323846;

void check_sphere_args(const char* what, float radius, glm::vec3 center) {
    if (!(radius > 0.0f) || !std::isfinite(radius))
        fail(std::string(what) + ": radius must be a positive finite number, got " + std::to_string(radius));
    if (!std::isfinite(center.x) || !std::isfinite(center.y) || !std::isfinite(center.z))
        fail(std::string(what) + ": centre must be finite");
}

// Sphere vertices are computed on the unit sphere in double and only then scaled, so that every
// vertex lies at `radius` up to float rounding; normals are the exact unit directions.
void push_sphere_vertex(Mesh& mesh, glm::dvec3 dir, float radius, glm::vec3 center) {
    dir = glm::normalize(dir);
    mesh.positions.push_back(center + radius * glm::vec3(dir));
    mesh.normals.push_back(glm::vec3(dir));
}

// Appends triangle (a, b, c), swapped if needed so that it is counter-clockwise seen from outside
// (its geometric normal points away from the centre). Cheaper to get right than to reason about
// every band's orientation, and it makes "CCW outward" hold by construction.
void push_outward_triangle(Mesh& mesh, uint32_t a, uint32_t b, uint32_t c, glm::vec3 center) {
    const glm::dvec3 pa(mesh.positions[a]), pb(mesh.positions[b]), pc(mesh.positions[c]);
    const glm::dvec3 n = glm::cross(pb - pa, pc - pa);
    const glm::dvec3 centroid = (pa + pb + pc) / 3.0 - glm::dvec3(center);
    if (glm::dot(n, centroid) < 0.0) std::swap(b, c);
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
}

}  // namespace

Mesh make_uv_sphere(size_t target_triangles, float radius, glm::vec3 center) {
    check_sphere_args("make_uv_sphere", radius, center);
    // `stacks` latitude bands and slices = 2 * stacks longitudes (square-ish quads at the equator):
    // two polar fans of `slices` triangles plus (stacks - 2) bands of 2 * slices triangles,
    // 2 * slices * (stacks - 1) = 4 s (s - 1) in all; s solves 4 s (s - 1) = target.
    const double s = (1.0 + std::sqrt(1.0 + static_cast<double>(target_triangles))) / 2.0;
    const uint32_t stacks = static_cast<uint32_t>(std::clamp(std::llround(s), 2LL, 30000LL));
    const uint32_t slices = 2 * stacks;

    Mesh mesh;
    mesh.source = "uv_sphere";
    const size_t vertex_count = 2 + static_cast<size_t>(stacks - 1) * slices;
    mesh.positions.reserve(vertex_count);
    mesh.normals.reserve(vertex_count);
    push_sphere_vertex(mesh, {0.0, 1.0, 0.0}, radius, center);  // north pole (+Y)
    for (uint32_t i = 1; i < stacks; ++i) {
        const double theta = kPi * i / stacks;
        for (uint32_t j = 0; j < slices; ++j) {
            const double phi = 2.0 * kPi * j / slices;
            push_sphere_vertex(mesh, {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)},
                               radius, center);
        }
    }
    push_sphere_vertex(mesh, {0.0, -1.0, 0.0}, radius, center);  // south pole
    const uint32_t south = static_cast<uint32_t>(mesh.positions.size() - 1);
    auto ring = [&](uint32_t i, uint32_t j) { return 1 + (i - 1) * slices + (j % slices); };

    mesh.indices.reserve(static_cast<size_t>(6) * slices * (stacks - 1));
    for (uint32_t j = 0; j < slices; ++j) push_outward_triangle(mesh, 0, ring(1, j), ring(1, j + 1), center);
    for (uint32_t i = 1; i + 1 < stacks; ++i) {
        for (uint32_t j = 0; j < slices; ++j) {
            push_outward_triangle(mesh, ring(i, j), ring(i + 1, j), ring(i + 1, j + 1), center);
            push_outward_triangle(mesh, ring(i, j), ring(i + 1, j + 1), ring(i, j + 1), center);
        }
    }
    for (uint32_t j = 0; j < slices; ++j)
        push_outward_triangle(mesh, south, ring(stacks - 1, j + 1), ring(stacks - 1, j), center);
    return mesh;
}

Mesh make_icosphere(int subdivisions, float radius, glm::vec3 center) {
    check_sphere_args("make_icosphere", radius, center);
    if (subdivisions < 0 || subdivisions > 10)
        fail("make_icosphere: subdivisions must be in [0, 10], got " + std::to_string(subdivisions));

    // Directions are kept in double on the unit sphere through all levels; positions are derived
    // at the end, so repeated midpoint projection accumulates no float error.
    const double g = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<glm::dvec3> dirs = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                                    {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    for (glm::dvec3& d : dirs) d = glm::normalize(d);
    std::vector<uint32_t> tris = {0, 11, 5, 0, 5,  1,  0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                                  4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3, 9,  4, 3, 4,  2, 3, 2, 6, 3,
                                  6, 8,  3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2,  10, 8, 6, 7, 9, 8, 1};

    for (int level = 0; level < subdivisions; ++level) {
        std::unordered_map<uint64_t, uint32_t> midpoint;
        midpoint.reserve(tris.size());
        auto mid = [&](uint32_t a, uint32_t b) {
            const uint64_t key = a < b ? (uint64_t(a) << 32 | b) : (uint64_t(b) << 32 | a);
            auto [it, inserted] = midpoint.try_emplace(key, static_cast<uint32_t>(dirs.size()));
            if (inserted) dirs.push_back(glm::normalize(dirs[a] + dirs[b]));
            return it->second;
        };
        std::vector<uint32_t> next;
        next.reserve(tris.size() * 4);
        for (size_t t = 0; t < tris.size(); t += 3) {
            const uint32_t a = tris[t], b = tris[t + 1], c = tris[t + 2];
            const uint32_t ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
            next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
        }
        tris.swap(next);
    }

    Mesh mesh;
    mesh.source = "icosphere";
    mesh.positions.reserve(dirs.size());
    mesh.normals.reserve(dirs.size());
    for (const glm::dvec3& d : dirs) push_sphere_vertex(mesh, d, radius, center);
    mesh.indices.reserve(tris.size());
    for (size_t t = 0; t < tris.size(); t += 3) push_outward_triangle(mesh, tris[t], tris[t + 1], tris[t + 2], center);
    return mesh;
}

namespace {

// Joins two latitude rings of `a_count` and `b_count` vertices (starting at longitude 0, evenly spaced)
// by walking both in order of longitude: one triangle per step of either ring.
void zip_rings(Mesh& mesh, uint32_t a_first, uint32_t a_count, uint32_t b_first, uint32_t b_count, glm::vec3 center) {
    uint32_t i = 0, j = 0;
    while (i < a_count || j < b_count) {
        const bool step_a = j >= b_count || (i < a_count && double(i + 1) / a_count <= double(j + 1) / b_count);
        if (step_a) {
            push_outward_triangle(mesh, a_first + i, a_first + (i + 1) % a_count, b_first + j % b_count, center);
            ++i;
        } else {
            push_outward_triangle(mesh, a_first + i % a_count, b_first + (j + 1) % b_count, b_first + j, center);
            ++j;
        }
    }
}

}  // namespace

Mesh make_mixed_sphere(int coarse_stacks, int fine_stacks, float radius, glm::vec3 center) {
    check_sphere_args("make_mixed_sphere", radius, center);
    if (coarse_stacks < 1 || coarse_stacks > 2000 || fine_stacks < 1 || fine_stacks > 2000)
        fail("make_mixed_sphere: stacks must be in [1, 2000], got " + std::to_string(coarse_stacks) + " and " +
             std::to_string(fine_stacks));
    // Rings from the north pole to the south pole: (polar angle, vertex count); the equator is coarse.
    std::vector<std::pair<double, uint32_t>> rings;
    for (int k = 1; k <= coarse_stacks; ++k) rings.push_back({0.5 * kPi * k / coarse_stacks, 4u * uint32_t(coarse_stacks)});
    for (int k = 1; k < fine_stacks; ++k) rings.push_back({0.5 * kPi * (1.0 + double(k) / fine_stacks), 4u * uint32_t(fine_stacks)});

    Mesh mesh;
    mesh.source = "mixed_sphere";
    push_sphere_vertex(mesh, {0.0, 1.0, 0.0}, radius, center);
    std::vector<uint32_t> first;
    for (const auto& [theta, count] : rings) {
        first.push_back(uint32_t(mesh.positions.size()));
        for (uint32_t j = 0; j < count; ++j) {
            const double phi = 2.0 * kPi * j / count;
            push_sphere_vertex(mesh, {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)},
                               radius, center);
        }
    }
    push_sphere_vertex(mesh, {0.0, -1.0, 0.0}, radius, center);
    const uint32_t south = uint32_t(mesh.positions.size() - 1);
    const uint32_t top = rings.front().second, bottom = rings.back().second;
    for (uint32_t j = 0; j < top; ++j) push_outward_triangle(mesh, 0, first[0] + j, first[0] + (j + 1) % top, center);
    for (size_t r = 0; r + 1 < rings.size(); ++r)
        zip_rings(mesh, first[r], rings[r].second, first[r + 1], rings[r + 1].second, center);
    for (uint32_t j = 0; j < bottom; ++j)
        push_outward_triangle(mesh, south, first.back() + (j + 1) % bottom, first.back() + j, center);
    return mesh;
}

Mesh make_cad_cylinder(int segments, float radius, float length) {
    if (segments < 3 || segments > 100000)
        fail("make_cad_cylinder: segments must be in [3, 100000], got " + std::to_string(segments));
    if (!(radius > 0.0f) || !(length > 0.0f) || !std::isfinite(radius) || !std::isfinite(length))
        fail("make_cad_cylinder: radius and length must be positive finite numbers");
    Mesh mesh;
    mesh.source = "cad_cylinder";
    const uint32_t n = uint32_t(segments);
    const float y[2] = {-0.5f * length, 0.5f * length};
    auto rim = [&](uint32_t j) {
        const double phi = 2.0 * kPi * (j % n) / n;
        return glm::vec3(float(std::cos(phi)), 0.0f, float(std::sin(phi)));
    };
    // Side: the rims' corners with radial normals, 2 per segment (bottom, top).
    for (uint32_t j = 0; j < n; ++j)
        for (int end = 0; end < 2; ++end) {
            mesh.positions.push_back(radius * rim(j) + glm::vec3(0.0f, y[end], 0.0f));
            mesh.normals.push_back(rim(j));
        }
    for (uint32_t j = 0; j < n; ++j) {
        const uint32_t a = 2 * j, b = 2 * j + 1, c = 2 * ((j + 1) % n), d = c + 1;
        // Counter-clockwise seen from outside: around +Y the angle grows from +X towards +Z.
        mesh.indices.insert(mesh.indices.end(), {a, b, c, c, b, d});
    }
    // Caps: a centre and the rim again, with axial normals.
    for (int end = 0; end < 2; ++end) {
        const glm::vec3 normal(0.0f, end ? 1.0f : -1.0f, 0.0f);
        const uint32_t centre = uint32_t(mesh.positions.size());
        mesh.positions.push_back(glm::vec3(0.0f, y[end], 0.0f));
        mesh.normals.push_back(normal);
        for (uint32_t j = 0; j < n; ++j) {
            mesh.positions.push_back(radius * rim(j) + glm::vec3(0.0f, y[end], 0.0f));
            mesh.normals.push_back(normal);
        }
        for (uint32_t j = 0; j < n; ++j) {
            const uint32_t p = centre + 1 + j, q = centre + 1 + (j + 1) % n;
            if (end) mesh.indices.insert(mesh.indices.end(), {centre, q, p});
            else mesh.indices.insert(mesh.indices.end(), {centre, p, q});
        }
    }
    return mesh;
}

Mesh make_grid(int n, float size) {
    if (n < 1 || n > 8192) fail("make_grid: n must be in [1, 8192], got " + std::to_string(n));
    if (!(size > 0.0f) || !std::isfinite(size)) fail("make_grid: size must be a positive finite number");
    Mesh mesh;
    mesh.source = "grid";
    const uint32_t row = static_cast<uint32_t>(n) + 1;
    mesh.positions.reserve(static_cast<size_t>(row) * row);
    for (uint32_t j = 0; j < row; ++j) {
        for (uint32_t i = 0; i < row; ++i) {
            mesh.positions.emplace_back(-0.5f * size + size * static_cast<float>(i) / static_cast<float>(n),
                                        -0.5f * size + size * static_cast<float>(j) / static_cast<float>(n), 0.0f);
        }
    }
    mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0f, 0.0f, 1.0f));
    mesh.indices.reserve(static_cast<size_t>(6) * n * n);
    for (uint32_t j = 0; j < static_cast<uint32_t>(n); ++j) {
        for (uint32_t i = 0; i < static_cast<uint32_t>(n); ++i) {
            const uint32_t a = j * row + i, b = a + 1, c = a + row + 1, d = a + row;
            // Counter-clockwise seen from +Z, the grid's front.
            mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
        }
    }
    return mesh;
}

}  // namespace stipple
