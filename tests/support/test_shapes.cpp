#include "support/test_shapes.hpp"

#include <cmath>
#include <string>

#include "core/hash.hpp"

namespace stipple::test {

namespace {

constexpr float kPi = 3.14159265358979f;

// Flips the triangles that face toward `inside` (every shape here is convex about its inside point,
// or flat with a known front), so that all of them face outward.
void face_outward(Mesh& mesh, glm::vec3 inside, glm::vec3 flat_front = glm::vec3(0.0f)) {
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
        uint32_t* i = &mesh.indices[3 * t];
        glm::vec3 a = mesh.positions[i[0]], b = mesh.positions[i[1]], c = mesh.positions[i[2]];
        glm::vec3 normal = glm::cross(b - a, c - a);
        glm::vec3 outward = flat_front != glm::vec3(0.0f) ? flat_front : (a + b + c) / 3.0f - inside;
        if (glm::dot(normal, outward) < 0.0f) std::swap(i[1], i[2]);
    }
    compute_vertex_normals(mesh);
}

// Rings of `segments` vertices around a pole vertex (index 0): ring k's vertices follow, and each
// band of quads is split into two triangles; `point(k, s)` places ring k's vertex s (k from 1).
template <class Point>
Mesh polar_grid(int segments, int rings, glm::vec3 pole, Point point) {
    Mesh mesh;
    mesh.positions.push_back(pole);
    for (int k = 1; k <= rings; ++k)
        for (int s = 0; s < segments; ++s) mesh.positions.push_back(point(k, s));
    auto at = [&](int k, int s) { return uint32_t(1 + (k - 1) * segments + (s % segments)); };
    for (int s = 0; s < segments; ++s) mesh.indices.insert(mesh.indices.end(), {0u, at(1, s), at(1, s + 1)});
    for (int k = 1; k < rings; ++k)
        for (int s = 0; s < segments; ++s)
            mesh.indices.insert(mesh.indices.end(),
                                {at(k, s), at(k + 1, s), at(k + 1, s + 1), at(k, s), at(k + 1, s + 1), at(k, s + 1)});
    return mesh;
}

}  // namespace

Mesh make_open_hemisphere(int segments, int rings) {
    Mesh mesh = polar_grid(segments, rings, glm::vec3(0.0f, -1.0f, 0.0f), [&](int k, int s) {
        float polar = 0.5f * kPi * float(k) / float(rings);  // from the bottom pole to the rim
        float around = 2.0f * kPi * float(s) / float(segments);
        return glm::vec3(std::sin(polar) * std::cos(around), -std::cos(polar), std::sin(polar) * std::sin(around));
    });
    mesh.source = "open hemisphere";
    face_outward(mesh, glm::vec3(0.0f));
    return mesh;
}

Mesh make_disc(int segments, int rings) {
    Mesh mesh = polar_grid(segments, rings, glm::vec3(0.0f), [&](int k, int s) {
        float radius = float(k) / float(rings);
        float around = 2.0f * kPi * float(s) / float(segments);
        return glm::vec3(radius * std::cos(around), radius * std::sin(around), 0.0f);
    });
    mesh.source = "disc";
    face_outward(mesh, glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, 1.0f));
    return mesh;
}

namespace {

// `copies` of `part` at hashed places in the unit cube, each turned about z by a hashed angle if `turn`, in
// the draw order a model is loaded in.
Mesh cloud_of(const Mesh& part, size_t copies, bool turn, const char* source) {
    Mesh mesh;
    for (size_t copy = 0; copy < copies; ++copy) {
        const uint64_t bits = mix64(copy + 1);
        const glm::vec3 centre =
            glm::vec3(float(bits & 0xFFFF), float((bits >> 16) & 0xFFFF), float((bits >> 32) & 0xFFFF)) / 65536.0f;
        const float angle = turn ? float((bits >> 48) & 0xFFFF) / 65536.0f * 6.2831853f : 0.0f;
        const float c = std::cos(angle), s = std::sin(angle);
        const uint32_t base = uint32_t(mesh.positions.size());
        for (const glm::vec3& v : part.positions)
            mesh.positions.push_back(centre + glm::vec3(c * v.x - s * v.y, s * v.x + c * v.y, v.z));
        for (uint32_t i : part.indices) mesh.indices.push_back(base + i);
    }
    mesh.source = source;
    optimize_draw_order(mesh);
    return mesh;
}

}  // namespace

Mesh make_tetrahedron_cloud(size_t copies, float size) {
    Mesh tetrahedron;
    tetrahedron.positions = {{size, size, size}, {size, -size, -size}, {-size, size, -size}, {-size, -size, size}};
    tetrahedron.indices = {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2};  // outward
    return cloud_of(tetrahedron, copies, true, "tetrahedron cloud");
}

Mesh make_box_cloud(size_t copies, float size) {
    return cloud_of(make_box(glm::vec3(size)), copies, false, "box cloud");
}

Mesh make_box(glm::vec3 size) {
    Mesh mesh;
    mesh.source = "box";
    for (int corner = 0; corner < 8; ++corner)
        mesh.positions.push_back(0.5f * size * glm::vec3(corner & 1 ? 1.0f : -1.0f, corner & 2 ? 1.0f : -1.0f,
                                                         corner & 4 ? 1.0f : -1.0f));
    // Each face as a quad of corner numbers in cyclic order, split along one diagonal.
    const uint32_t faces[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
    for (const auto& q : faces) mesh.indices.insert(mesh.indices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
    face_outward(mesh, glm::vec3(0.0f));
    return mesh;
}

glm::dvec3 face_normal(const Mesh& mesh, size_t t) {
    const glm::dvec3 a(mesh.positions[mesh.indices[3 * t]]), b(mesh.positions[mesh.indices[3 * t + 1]]),
        c(mesh.positions[mesh.indices[3 * t + 2]]);
    return glm::cross(b - a, c - a);
}

glm::dvec3 face_centroid(const Mesh& mesh, size_t t) {
    return (glm::dvec3(mesh.positions[mesh.indices[3 * t]]) + glm::dvec3(mesh.positions[mesh.indices[3 * t + 1]]) +
            glm::dvec3(mesh.positions[mesh.indices[3 * t + 2]])) /
           3.0;
}

std::string obj_text(const Mesh& mesh) {
    std::string text;
    for (const glm::vec3& p : mesh.positions)
        text += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
    for (size_t t = 0; t < mesh.triangle_count(); ++t)
        text += "f " + std::to_string(mesh.indices[3 * t] + 1) + " " + std::to_string(mesh.indices[3 * t + 1] + 1) +
                " " + std::to_string(mesh.indices[3 * t + 2] + 1) + "\n";
    return text;
}

}  // namespace stipple::test
