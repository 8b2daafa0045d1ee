#pragma once
// The body of the three model-file harnesses: load_mesh_from_bytes under a name whose extension picks
// the reader, with a lower element limit than the default so that the allocation limit catches
// allocations the file does not justify rather than the designed 200M-element ceiling.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_check.hpp"
#include "mesh/load_mesh.hpp"

namespace stipple::fuzz {

inline int load_model(const std::string& name, const uint8_t* data, size_t size) {
    LoadOptions options;
    options.max_elements = 4'000'000;
    try {
        check_mesh(load_mesh_from_bytes(name, std::string_view(reinterpret_cast<const char*>(data), size), options));
    } catch (const Error& e) {
        check_message(e, name);
    }
    return 0;
}

}  // namespace stipple::fuzz
