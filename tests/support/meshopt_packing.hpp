#pragma once
// Writes .glb files the way gltfpack -cc does (EXT_meshopt_compression), from a one-buffer .glb: the
// compressed views' bytes in buffer 0, their uncompressed layout in a placeholder buffer 1 that holds no
// data. Tests compare what loads from both forms.
#include <cstdint>
#include <map>
#include <string>

namespace stipple::test {

struct ViewCoding {
    std::string mode = "ATTRIBUTES";  // ATTRIBUTES, TRIANGLES or INDICES
    uint32_t stride = 4;              // bytes per element as the codec sees them
    std::string filter = "NONE";      // the view's data must already be in the filter's encoded form
    bool fallback_flag = true;        // mark buffer 1 with {"fallback": true} (the extension allows either)
};

// Compresses the views listed in `codings` (by index), or, when it is empty, every view whose length is a
// multiple of 4 as ATTRIBUTES of 4-byte elements (or of the view's byteStride); the other views stay
// uncompressed in buffer 0.
std::string meshopt_pack_glb(const std::string& glb, const std::map<size_t, ViewCoding>& codings = {});

}  // namespace stipple::test
