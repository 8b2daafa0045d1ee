#pragma once
// Which way a model's triangles face. Everything that tells front from back reads the winding: the
// computed vertex normals (and so the shading, §2.2), the facing test of the density pass, the back faces
// of the Raskar–Cohen silhouettes (§3.1), the contours between front and back faces. Real models are
// often wound inconsistently (exports that lost the orientation, meshes stitched from parts, scans
// repaired by hand): there the computed normals cancel, and a third of the faces count as back faces.
// Loading repairs it (load_mesh): the triangles of each part are wound alike, and a part that is then
// clearly inside out is turned outward.
#include <cstddef>
#include <cstdint>
#include <span>

#include "mesh/mesh.hpp"

namespace stipple {

// Signed volume enclosed by the triangles (positive when they are wound counter-clockwise seen from
// outside); about zero for an open sheet.
double signed_volume(const Mesh& mesh);

// Winds the triangles of each part alike and each part outward:
// 1. Corners are welded by position (weld_by_position), so split seams do not cut a part in two. An edge
//    shared by exactly two triangles (manifold) should be walked in opposite directions by them; an edge
//    of one triangle (a border) or of three or more (non-manifold: fins, duplicated faces) says nothing.
// 2. A breadth-first walk over the manifold edges gives each part one winding; of its two, the part keeps
//    the one that turns less of its area (the file's winding, where the file was consistent).
// 3. Outward, where the volume says so clearly: scans are sometimes wound
//    inside out (the Cyberware horse is), and mirrored parts of an assembly are. A closed part (no border
//    edge) is turned whole when its own signed volume is negative (below a thousandth of the sum of its
//    tetrahedra's volumes taken positive, so that a thin rod across its box counts too). An open part nearly
//    closed (a scan with holes: its holes, capped by fans from each rim's centre, add under a fifth of its
//    area) is turned by the same rule with its caps. A part open wider (a bowl, a valley, a room, a sheet)
//    encloses nothing: it keeps its majority's winding, the side the file shows.
//    A closed part inside another (the wall of a cavity) is turned outward too; it is hidden in any view.
//    With normals_from_file, an open part whose faces the file's normals clearly contradict is turned to
//    them first, where the normals clearly agree with more of the open parts' area than they contradict
//    (a loose panel of an export wound against the rest: no volume tells which way it faces); otherwise
//    the normals are what is wrong, and the volume decides, as for the parts they agree with.
// Only the corner order changes (corners 1 and 2 swap): positions, normals and vertex order stay, so the
// caller decides what to do with the normals (load_mesh recomputes computed ones and turns file ones to
// agree with their faces). Deterministic; indices beyond the positions are skipped (validate_mesh reports
// them).
WindingRepair orient_consistently(Mesh& mesh);
// The same with the corners already welded (weld_by_position of mesh.positions).
WindingRepair orient_consistently(Mesh& mesh, std::span<const uint32_t> corners, bool normals_from_file = false);

// The edges of one triangle only, corners welded by position (holes' rims, a sheet's edges): what loading's
// repair counted (WindingRepair::border_edges, where it ran: parts > 0), else counted now.
size_t border_edge_count(const Mesh& mesh);

// Vertex normals from a file, each turned around where it disagrees with its faces (the area-weighted sum
// of dot(face normal, vertex normal) over the triangles around it is negative): after a winding repair,
// normals that followed the old winding. Returns how many were turned.
size_t turn_normals_to_faces(Mesh& mesh);

}  // namespace stipple
