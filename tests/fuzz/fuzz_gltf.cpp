// libFuzzer harness: the glTF reader on arbitrary bytes, as .glb when they start with the GLB magic
// and as .gltf (JSON) otherwise, so one corpus covers both containers (see fuzz_mesh_reader.hpp).
#include <cstring>

#include "fuzz_mesh_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const bool glb = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    return stipple::fuzz::load_model(glb ? "fuzz.glb" : "fuzz.gltf", data, size);
}
