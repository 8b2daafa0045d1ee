#pragma once
// Small meshes whose lines are known exactly, for the line tests: an open bowl, a flat disc, a box.
// Each is wound counter-clockwise seen from its outside (a disc: from +z), with vertex normals. And a cloud
// of small tetrahedra for the selection values.
#include <string>

#include <glm/glm.hpp>

#include "mesh/mesh.hpp"

namespace stipple::test {

// The lower half of the unit sphere, open at the top (its rim is the circle y = 0, radius 1):
// `segments` around, `rings` from the bottom pole up to the rim.
Mesh make_open_hemisphere(int segments, int rings);

// A flat disc of radius 1 in the z = 0 plane, facing +z: `rings` rings of `segments` each.
Mesh make_disc(int segments, int rings);

// A box centred on the origin with these side lengths: 8 shared corners, 12 triangles, so each of its
// 12 edges joins two faces at 90 degrees and each face's diagonal joins two triangles of one plane.
Mesh make_box(glm::vec3 size);

// Clouds of small parts for the selection values, in the draw order a model is loaded in
// (optimize_draw_order: each copy's faces in the same order); far away such particles lie below a dot and
// are drawn by the probabilistic selection. `copies` regular tetrahedra inscribed in cubes of half-edge
// `size`, wound outward, at hashed places in the unit cube, each turned about z by a hashed angle (a face
// of a given number has the same elevation in every copy); and `copies` boxes of edge `size`, not turned
// (each face of a given number faces the same way in every copy, along an axis).
Mesh make_tetrahedron_cloud(size_t copies, float size);
Mesh make_box_cloud(size_t copies, float size);

// Triangle t's normal scaled by twice its area (counter-clockwise corners give the side they face), and
// its centroid, in double.
glm::dvec3 face_normal(const Mesh& mesh, size_t t);
glm::dvec3 face_centroid(const Mesh& mesh, size_t t);

// The mesh as a Wavefront OBJ file's text (positions and faces).
std::string obj_text(const Mesh& mesh);

}  // namespace stipple::test
