#pragma once
// Binary PLY output (the benchmark caches its derived models as PLY; the loader reads them back).
#include <string>

#include "mesh/mesh.hpp"

namespace stipple {

// Writes positions and triangles as binary little-endian PLY (vertex x,y,z float; face list uchar
// int), through a temporary file renamed into place so that readers never see half a file.
// Throws stipple::Error("<path>: ...") on an I/O failure.
void write_ply_binary(const std::string& path, const Mesh& mesh);

}  // namespace stipple
