#pragma once
// Small animated glTF models generated from code, each simple enough that its poses can be worked out
// by hand: the tests compare the evaluation with those hand-computed poses, and a large cylinder gives
// the benchmark a skinned model of any size. Every constant a pose depends on is stated here.
#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "anim/gltf_builder.hpp"

namespace stipple::anim::rigs {

// A capped tube of radius `radius` from y = 0 to y = 2 (`rings` bands of `segments` quads; no normals
// in the file), skinned to two joints: "root" (node 1) at the origin and "elbow" (node 2) at (0, 1, 0),
// the elbow a child of the root. A vertex's elbow weight is cylinder_elbow_weight(y), the rest is the
// root's (JOINTS_0 as unsigned short, WEIGHTS_0 as float). The mesh node (node 0) is translated by
// `mesh_node_translation`, which skinning ignores. Animations:
//   0 "Bend": the elbow turns about +z: 0, bend_degrees, 0 degrees at t = 0, 1, 2 (`interpolation`;
//     CUBICSPLINE with zero tangents);
//   1 "Lift": the root moves from (0, 0, 0) to (0, 1, 0) over t = 0..1, LINEAR.
struct CylinderOptions {
    uint32_t rings = 8;
    uint32_t segments = 12;
    float radius = 0.25f;
    float bend_degrees = 90.0f;
    std::string interpolation = "LINEAR";
    glm::vec3 mesh_node_translation{0.0f};
};
GltfBuilder bending_cylinder(const CylinderOptions& options = {});
// 0 below y = 0.75, 1 above y = 1.25, linear in between.
float cylinder_elbow_weight(float y);

// A unit cube centred on the origin (24 vertices with normals, 36 unsigned short indices) in node 1
// "box", child of node 0 which is translated by (0, 0, -3). Animation 0 "Move" (LINEAR) drives node 1:
// translation (0,0,0) -> (2,0,0) over t = 0..2; rotation about +y 0, 90, 180 degrees at t = 0, 1, 2;
// scale (1,1,1) -> (1,3,1) over t = 0..2.
GltfBuilder node_animated_box();

// The quad (0,0,0), (1,0,0), (1,1,0), (0,1,0) (normals +z; triangles 0 1 2, 0 2 3) in node 0, which is
// translated by (1, 2, 3). Two morph targets, named "lift" and "raise": target 0 moves vertex 2 by
// (0, 0, 1) and adds (0.5, 0, 0) to every normal; target 1 moves every vertex by (0, 0, 0.5). Mesh
// weights (0.5, 0.5), node weights (0.25, 0) (the node's win). Animation 0 "Morph" (LINEAR) sets the
// weights to (0, 0), (1, 0.5), (0, 1) at t = 0, 1, 2.
GltfBuilder morphed_quad();

// One triangle (0,0,0), (1,0,0), (0,1,0) in node 0, whose translation and rotation are driven by
// animation 0 "Keys" with `interpolation` ("STEP", "LINEAR" or "CUBICSPLINE") at the key times below.
// CUBICSPLINE stores (in-tangent, value, out-tangent) per key: translation tangents as listed, rotation
// tangents zero.
inline constexpr float kKeyTimes[3] = {1.0f, 2.0f, 4.0f};
inline constexpr float kKeyTranslations[3][3] = {{0, 0, 0}, {1, 2, 0}, {3, 0, -1}};
inline constexpr float kKeyInTangents[3][3] = {{0, 0, 0}, {0, 1, 0}, {1, 1, 1}};
inline constexpr float kKeyOutTangents[3][3] = {{1, 0, 0}, {0, 0, 2}, {0, 0, 0}};
// Rotations about +y by 0, 90 and 170 degrees, the last stored negated (-q is the same rotation; a
// LINEAR slerp must still take the short arc, 90 -> 170 degrees).
glm::quat key_rotation(int key);  // as stored in the file
GltfBuilder interpolation_sample(const std::string& interpolation);

// A square sheet (0,0,0)-(1,1,0) of cells x cells quads (normals +z) skinned to node 1 "left" at the
// origin and node 2 "right" at (1, 0, 0), a vertex's "right" weight being its x. Animation 0 "Stretch"
// (LINEAR) moves "right" from (1, 0, 0) to (2, 0, 0) over t = 0..1: every point's x doubles, so every
// polygon reaches twice its rest area at t = 1.
GltfBuilder stretching_plane(uint32_t cells = 4);

// A strip (0,0,0)-(1,0.2,0) of `cells` x 1 quads (normals +z) skinned to 8 joints, nodes 1..8, joint k
// at (k/7, 0, 0), each vertex weighted by all eight: eight_joint_weight(x, k) (JOINTS_0 as unsigned
// short for joints 0-3, JOINTS_1 as unsigned byte for 4-7, both weight sets float). Animation 0 "Wave"
// (LINEAR) moves joint k from (k/7, 0, 0) to (k/7, 0.1 k, 0) over t = 0..1, so a point rises by
// sum_k eight_joint_weight(x, k) * 0.1 k * t.
GltfBuilder eight_joint_sheet(uint32_t cells = 14);
float eight_joint_weight(float x, int joint);

}  // namespace stipple::anim::rigs
