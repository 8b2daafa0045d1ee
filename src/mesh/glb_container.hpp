#pragma once
// The binary glTF container (.glb): a 12-byte header, a JSON chunk and an optional BIN chunk, each
// padded to four bytes. Split when a file is read (gltf_validate), joined when one is written (the
// meshopt and Draco rewrites, GltfBuilder, the tests' files).
#include <string>
#include <string_view>

namespace stipple {

// The JSON and binary chunks of a .glb, after its header and chunk lengths are checked.
struct GlbChunks {
    std::string_view json;
    bool has_bin = false;
    std::string_view bin;
};

// Splits a .glb container; throws stipple::Error "<name>: ..." for a bad header or chunk, and for a
// glTF 1.0 binary file.
GlbChunks split_glb(const std::string& name, std::string_view bytes);

// The inverse: a .glb container of a JSON document and a binary chunk (none when `bin` is empty), each
// padded as GLB requires.
std::string join_glb(std::string_view json, std::string_view bin);

}  // namespace stipple
