#include "mesh/ply_writer.hpp"

#include <unistd.h>

#include <bit>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "core/error.hpp"

namespace stipple {

void write_ply_binary(const std::string& path, const Mesh& mesh) {
    static_assert(std::endian::native == std::endian::little, "the PLY writer assumes a little-endian host");
    std::filesystem::path target(path);
    if (target.has_parent_path()) {
        std::error_code ec;
        std::filesystem::create_directories(target.parent_path(), ec);
        if (ec) fail_file(path, "cannot create its folder: " + ec.message());
    }
    // A temporary name unique to this process: two processes deriving the same model do not collide.
    std::string temporary = path + ".tmp" + std::to_string(::getpid());
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) fail_file(temporary, "cannot open for writing");
        out << "ply\nformat binary_little_endian 1.0\ncomment stipple benchmark model (" << mesh.source << ")\n"
            << "element vertex " << mesh.positions.size() << "\nproperty float x\nproperty float y\nproperty float z\n"
            << "element face " << mesh.triangle_count() << "\nproperty list uchar int vertex_indices\nend_header\n";
        out.write(reinterpret_cast<const char*>(mesh.positions.data()),
                  std::streamsize(mesh.positions.size() * sizeof(glm::vec3)));
        std::vector<char> faces(mesh.triangle_count() * 13);
        for (size_t t = 0; t < mesh.triangle_count(); ++t) {
            faces[13 * t] = 3;
            std::memcpy(&faces[13 * t + 1], &mesh.indices[3 * t], 12);
        }
        out.write(faces.data(), std::streamsize(faces.size()));
        out.flush();
        if (!out) {
            out.close();
            std::filesystem::remove(temporary);
            fail_file(path, "write failed (disk full?)");
        }
    }
    std::error_code ec;
    std::filesystem::rename(temporary, target, ec);
    if (ec) {
        std::filesystem::remove(temporary);
        fail_file(path, "cannot move the new file into place: " + ec.message());
    }
}

}  // namespace stipple
