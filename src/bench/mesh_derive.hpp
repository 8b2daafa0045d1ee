#pragma once
// Mesh operations that derive the benchmark's model set from real scans: welding, midpoint
// subdivision, simplification to a triangle count (meshoptimizer), and a binary PLY writer.
#include <cstddef>
#include <string>

#include "mesh/mesh.hpp"

namespace stipple::bench {

// Merges vertices at identical positions (meshopt_generateVertexRemap) and drops unused ones; normals
// are recomputed. Triangles are kept as they are (degenerate ones included).
Mesh weld_positions(const Mesh& mesh);

// Each triangle into four by its edge midpoints; a midpoint shared by two triangles is one vertex.
// The mesh should be welded first (otherwise seams get duplicate midpoints). Normals are recomputed.
Mesh subdivide_midpoints(const Mesh& mesh);

struct SimplifyResult {
    Mesh mesh;
    std::string method;   // "simplify (error 0.01)" or "simplifySloppy"
    float error = 0.0f;   // meshoptimizer's relative error of the result
};

// Simplifies a welded mesh to `target` triangles within `tolerance` (relative): meshopt_simplify with
// a growing error bound until the count is at most target * (1 + tolerance), then, if needed,
// meshopt_simplifySloppy. Deterministic. Throws stipple::Error when the count cannot be reached.
SimplifyResult simplify_to(const Mesh& mesh, size_t target, double tolerance);

// Writes positions and triangles as binary little-endian PLY (vertex x,y,z float; face list uchar
// int), through a temporary file renamed into place so that readers never see half a file.
// Throws stipple::Error("<path>: ...") on an I/O failure.
void write_ply_binary(const std::string& path, const Mesh& mesh);

// True when `count` is within `tolerance` (relative) of `target`.
inline bool within(size_t count, size_t target, double tolerance) {
    double d = double(count) - double(target);
    return (d < 0 ? -d : d) <= tolerance * double(target);
}

}  // namespace stipple::bench
