#pragma once
// A stipple's place in its triangle as 16-bit (u, v): position = a + u (b - a) + v (c - a). The GPU
// keeps candidates this way (shared_types.h: StippleVertex) and the stipple cache stores them this way,
// so both use these two functions: a position rebuilt from its (u, v) packs back to the same (u, v).
#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

#include "mesh/mesh.hpp"

namespace stipple {

// (u, v) with position = a + u (b - a) + v (c - a), unquantized; (0, 0) for a degenerate triangle.
inline glm::dvec2 barycentric_uv(const Mesh& mesh, uint32_t triangle, glm::vec3 position) {
    const glm::dvec3 a = mesh.positions[mesh.indices[3 * triangle]];
    const glm::dvec3 e0 = glm::dvec3(mesh.positions[mesh.indices[3 * triangle + 1]]) - a;
    const glm::dvec3 e1 = glm::dvec3(mesh.positions[mesh.indices[3 * triangle + 2]]) - a;
    const glm::dvec3 d = glm::dvec3(position) - a;
    const double d00 = glm::dot(e0, e0), d01 = glm::dot(e0, e1), d11 = glm::dot(e1, e1);
    const double denominator = d00 * d11 - d01 * d01;
    if (!(denominator > 0.0)) return {0.0, 0.0};
    return {(d11 * glm::dot(d, e0) - d01 * glm::dot(d, e1)) / denominator,
            (d00 * glm::dot(d, e1) - d01 * glm::dot(d, e0)) / denominator};
}

// u | v << 16, each a 16-bit unorm. A degenerate triangle holds its stipples at its first corner.
inline uint32_t pack_barycentric(const Mesh& mesh, uint32_t triangle, glm::vec3 position) {
    const glm::dvec2 uv = barycentric_uv(mesh, triangle, position);
    auto unorm16 = [](float value) { return uint32_t(std::lround(std::clamp(value, 0.0f, 1.0f) * 65535.0f)); };
    return unorm16(float(uv.x)) | unorm16(float(uv.y)) << 16;
}

// The position of a packed (u, v) in its triangle.
inline glm::vec3 unpack_barycentric(const Mesh& mesh, uint32_t triangle, uint32_t packed) {
    const glm::dvec3 a = mesh.positions[mesh.indices[3 * triangle]];
    const glm::dvec3 e0 = glm::dvec3(mesh.positions[mesh.indices[3 * triangle + 1]]) - a;
    const glm::dvec3 e1 = glm::dvec3(mesh.positions[mesh.indices[3 * triangle + 2]]) - a;
    const double u = double(packed & 0xFFFFu) / 65535.0, v = double(packed >> 16) / 65535.0;
    return glm::vec3(a + u * e0 + v * e1);
}

}  // namespace stipple
