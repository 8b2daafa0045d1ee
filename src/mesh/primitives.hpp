#pragma once
// Procedural meshes for tests, benchmarks and the default assets.
#include <cstddef>

#include "mesh/mesh.hpp"

namespace stipple {

// Unit-radius UV sphere (centre at origin) with about `target_triangles` triangles.
Mesh make_uv_sphere(size_t target_triangles, float radius = 1.0f, glm::vec3 center = glm::vec3(0.0f));
// Icosphere: 20 * 4^subdivisions triangles, very even triangles.
Mesh make_icosphere(int subdivisions, float radius = 1.0f, glm::vec3 center = glm::vec3(0.0f));
// A sphere of very uneven tessellation, for tone tests: the northern (+Y) hemisphere in `coarse_stacks`
// latitude bands of 4 * coarse_stacks slices, the southern one in `fine_stacks` bands of 4 * fine_stacks,
// joined at the equator by a strip of slivers; closed, CCW seen from outside. With 3 and 100 the
// largest triangles are about 700 times the area of the smallest (a CAD part's mix of flat faces and
// fillets, or a scan simplified in places).
Mesh make_mixed_sphere(int coarse_stacks, int fine_stacks, float radius = 1.0f, glm::vec3 center = glm::vec3(0.0f));
// A closed cylinder along +Y as a CAD program tessellates it for export: each side facet of `segments`
// one long sliver pair from cap to cap, each cap a fan from its centre. With 64 segments and a length of
// twice the diameter, the side triangles are 40 times longer than wide (at 1/16 of the frame height about
// a pixel and a half across). The rims' corners are split (radial normals on the side, axial on the caps).
Mesh make_cad_cylinder(int segments, float radius = 1.0f, float length = 4.0f);
// A flat grid of 2*n*n triangles covering [-size/2, size/2]^2 in the z = 0 plane, normal +Z.
Mesh make_grid(int n, float size = 2.0f);

}  // namespace stipple
