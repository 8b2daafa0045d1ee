// libFuzzer harness: the STL reader, binary and ASCII, on arbitrary bytes (see fuzz_mesh_reader.hpp).
#include "fuzz_mesh_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return stipple::fuzz::load_model("fuzz.stl", data, size);
}
