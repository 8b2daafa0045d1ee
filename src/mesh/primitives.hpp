#pragma once
// Procedural meshes for tests, benchmarks and the default assets.
#include <cstddef>

#include "mesh/mesh.hpp"

namespace stipple {

// Unit-radius UV sphere (centre at origin) with about `target_triangles` triangles.
Mesh make_uv_sphere(size_t target_triangles, float radius = 1.0f, glm::vec3 center = glm::vec3(0.0f));
// Icosphere: 20 * 4^subdivisions triangles, very even triangles.
Mesh make_icosphere(int subdivisions, float radius = 1.0f, glm::vec3 center = glm::vec3(0.0f));
// A flat grid of 2*n*n triangles covering [-size/2, size/2]^2 in the z = 0 plane, normal +Z.
Mesh make_grid(int n, float size = 2.0f);

}  // namespace stipple
