#pragma once
// Debian's libdraco behind a C interface of our own. The library carries its own, older tinygltf and
// stb_image_write and exports them: linked as it is, it took calls meant for libtinygltf (a tinygltf::Model
// of the other layout, freed as garbage) or clashed with our stb. So its codec is linked into one object
// with every symbol but these made local (third_party_config/Draco.cmake), and the rest of stipple sees
// only these functions and plain data.
#include <cstddef>
#include <cstdint>

extern "C" {

// One attribute of a decoded mesh: its value for every point, in point order, tightly packed.
struct StippleDracoAttribute {
    uint32_t unique_id;
    int data_type;    // draco::DataType: 1 INT8, 2 UINT8, 3 INT16, 4 UINT16, 5 INT32, 6 UINT32, 9 FLOAT32, ...
    int components;
    int component_size;  // bytes
    const unsigned char* values;  // points * components * component_size bytes
};

struct StippleDracoMesh {
    uint32_t points = 0, faces = 0;
    const uint32_t* corners = nullptr;  // 3 * faces point indices, each below points
    uint32_t attribute_count = 0;
    const StippleDracoAttribute* attributes = nullptr;
    char error[256] = {};  // why decoding failed
    void* owner = nullptr;
};

// Decodes a Draco mesh bitstream; 0 on success, else `error` says why. Free what it filled with
// stipple_draco_free either way.
int stipple_draco_decode(const unsigned char* data, size_t size, StippleDracoMesh* out);
void stipple_draco_free(StippleDracoMesh* mesh);

// For tests, which write Draco files: an indexed mesh with attributes given per point (values as above,
// data_type and components set; unique_id is filled in), POSITION quantized to `position_bits` (0: none).
// Kinds: 0 POSITION, 1 NORMAL, 2 COLOR, 3 TEX_COORD, 4 GENERIC. Returns 0 on success; free the bytes with
// stipple_draco_free_bytes.
struct StippleDracoInput {
    StippleDracoAttribute attribute;
    int kind;
    bool normalized;
};
int stipple_draco_encode(uint32_t points, const uint32_t* corners, uint32_t faces, StippleDracoInput* attributes,
                         uint32_t attribute_count, int position_bits, unsigned char** bytes, size_t* size);
void stipple_draco_free_bytes(unsigned char* bytes);
}
