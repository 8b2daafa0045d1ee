#pragma once
// Small pieces the model loaders share.
#include <cstdint>
#include <string>

#include "core/error.hpp"

namespace stipple {

// The whole file in one read (the parsers then work on plain memory); errors name the file.
std::string read_file(const std::string& path);

// A glTF scene can multiply a few bytes of file into a huge mesh (instancing, accessors of zeros): it may
// take at most half the machine's memory to load (as a model file may be at most half: check_model_size),
// estimated from its vertices and triangles, with `extra_bytes` of the loader's own (an instance's transform).
// Refused in one line naming `what` otherwise.
void check_load_fits_memory(const std::string& path, const std::string& what, uint64_t vertices, uint64_t triangles,
                            uint64_t extra_bytes = 0);

// one_line (core/error.hpp): library messages may span lines and quote file bytes; ours are one line.

}  // namespace stipple
