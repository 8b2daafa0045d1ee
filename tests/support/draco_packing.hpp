#pragma once
// Writes .glb files with KHR_draco_mesh_compression (as glTF-Transform or Blender write them), from a
// one-buffer .glb: each triangle primitive's attributes and indices become one Draco bitstream, and its
// accessors lose their buffer views. Tests compare what loads from both forms.
#include <string>

namespace stipple::test {

// `position_bits`: POSITION quantized to that many bits (0: stored losslessly, as every other attribute).
// A primitive without indices gets an indices accessor (Draco stores triangles).
std::string draco_pack_glb(const std::string& glb, int position_bits = 0);

}  // namespace stipple::test
