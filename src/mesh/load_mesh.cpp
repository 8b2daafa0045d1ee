#include "mesh/load_mesh.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <system_error>

#include "core/error.hpp"

namespace stipple {

namespace {

std::string lower_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

// Normals from a file are kept only when every one is usable; a partial set is worse than a
// consistent computed one, so any bad normal means recomputing them all.
bool normals_usable(const Mesh& mesh) {
    if (mesh.normals.size() != mesh.positions.size()) return false;
    for (const glm::vec3& n : mesh.normals) {
        if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z)) return false;
        if (glm::dot(n, n) == 0.0f) return false;
    }
    return true;
}

}  // namespace

Mesh load_mesh(const std::string& path, const LoadOptions& options) {
    namespace fs = std::filesystem;
    // Checked here so that every format reports these the same way, before any parser sees them.
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (ec && ec != std::errc::no_such_file_or_directory) fail_file(path, "cannot access: " + ec.message());
    if (!fs::exists(status)) fail_file(path, "no such file");
    if (fs::is_directory(status)) fail_file(path, "is a directory, not a model file");
    if (!fs::is_regular_file(status)) fail_file(path, "is not a regular file");
    const uintmax_t size = fs::file_size(path, ec);
    if (ec) fail_file(path, "cannot read the file size: " + ec.message());
    if (size == 0) fail_file(path, "file is empty");

    const std::string ext = lower_extension(path);
    Mesh mesh;
    if (ext == ".obj")
        mesh = load_obj(path, options);
    else if (ext == ".ply")
        mesh = load_ply(path, options);
    else if (ext == ".gltf" || ext == ".glb")
        mesh = load_gltf(path, options);
    else
        fail_file(path, (ext.empty() ? std::string("has no file extension") : "unknown model format '" + ext + "'") +
                            " (expected .obj, .ply, .gltf or .glb)");

    mesh.source = path;
    if (mesh.indices.empty()) fail_file(path, "the model has no triangles");
    if (normals_usable(mesh)) {
        for (glm::vec3& n : mesh.normals) n = glm::normalize(n);
    } else {
        compute_vertex_normals(mesh);  // tolerates bad indices; validate_mesh reports them
    }
    validate_mesh(mesh);
    orient_outward(mesh);
    return mesh;
}

Mesh load_mesh_for_drawing(const std::string& path, const LoadOptions& options) {
    Mesh mesh = load_mesh(path, options);
    optimize_draw_order(mesh);
    return mesh;
}

}  // namespace stipple
