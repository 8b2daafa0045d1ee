#include "mesh/loader_util.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "core/error.hpp"
#include "core/memory.hpp"

namespace stipple {

std::string read_file(const std::string& path) {
    std::error_code ec;
    const uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) fail_file(path, "cannot read: " + ec.message());
    std::string data(size, '\0');  // before the file is opened: memory that runs out leaves no handle open
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) fail_file(path, std::string("cannot open: ") + std::strerror(errno));
    const size_t got = std::fread(data.data(), 1, data.size(), f);
    std::fclose(f);
    if (got != size) fail_file(path, "read error after " + std::to_string(got) + " of " + std::to_string(size) + " bytes");
    return data;
}

// What a load takes at its peak, about: 270 bytes a triangle of three vertices of its own (a million such
// loaded in 266 MiB), the mesh, its welded corners, edges and winding repair included, and 24 bytes a vertex
// for the placed positions in double that a far origin is measured on.
constexpr uint64_t kLoadBytesPerVertex = 88, kLoadBytesPerTriangle = 64;

void check_load_fits_memory(const std::string& path, const std::string& what, uint64_t vertices, uint64_t triangles,
                            uint64_t extra_bytes) {
    const uint64_t memory = physical_memory_bytes();
    // Counts below 2^40 each (the loaders' limits are far lower): no overflow.
    const uint64_t needs = vertices * kLoadBytesPerVertex + triangles * kLoadBytesPerTriangle + extra_bytes;
    if (memory > 0 && needs > memory / 2)
        fail_file(path, what + ": " + std::to_string(vertices) + " vertices" +
                            (triangles > 0 ? " and " + std::to_string(triangles) + " triangles" : std::string()) +
                            " need about " + byte_size(needs) + " to load, more than a model may take on this machine: " +
                            byte_size(memory / 2) + ", half its " + byte_size(memory) + " of memory");
}

}  // namespace stipple
