#include "mesh/load_mesh.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <new>
#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <system_error>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "mesh/loader_util.hpp"
#include "mesh/mesh_ops.hpp"
#include "mesh/orientation.hpp"

namespace stipple {

namespace {

std::string lower_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

// Normals from a file are kept only when every one is usable; a partial set is worse than a
// consistent computed one, so any bad normal means recomputing them all.
// Lengths in double: in float a normal of 1e20 squares to infinity and one of 1e-20 to zero, and
// either normalises to a zero vector (found by fuzzing).
bool normals_usable(const Mesh& mesh) {
    if (mesh.normals.size() != mesh.positions.size()) return false;
    for (const glm::vec3& n : mesh.normals) {
        if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z)) return false;
        if (glm::length(glm::dvec3(n)) == 0.0) return false;
    }
    return true;
}

enum class Format { obj, ply, gltf, stl };

Format format_of(const std::string& name) {
    const std::string ext = lower_extension(name);
    if (ext == ".obj") return Format::obj;
    if (ext == ".ply") return Format::ply;
    if (ext == ".gltf" || ext == ".glb") return Format::gltf;
    if (ext == ".stl") return Format::stl;
    if (ext == ".json")  // a scene names models; `info` and a model's place take one model
        fail_file(name, "is a scene file, not a model (.obj, .ply, .gltf, .glb or .stl)");
    fail_file(name, (ext.empty() ? std::string("has no file extension") : "unknown model format '" + ext + "'") +
                        " (expected .obj, .ply, .gltf, .glb or .stl)");
}

Mesh parse(Format format, const std::string& name, std::string_view bytes, const std::filesystem::path* base_dir,
           const LoadOptions& options) {
    switch (format) {
        case Format::obj: return parse_obj(name, bytes, options);
        case Format::ply: return parse_ply(name, bytes, options);
        case Format::gltf: return parse_gltf(name, bytes, base_dir, options);
        case Format::stl: return parse_stl(name, bytes, options);
    }
    fail_file(name, "unknown model format");
}

// What every format shares once its parser is done: normals, validation, repeated faces dropped, one
// winding per part.
Mesh finish(Mesh mesh, const std::string& name, const LoadOptions& options) {
    mesh.source = name;
    if (mesh.indices.empty()) fail_file(name, "the model has no triangles");
    // Normals a reader computed are not the file's: they say nothing about which way a face looks, and
    // they are computed again once the winding is repaired (a glTF sheet whose computed normals cancelled
    // had its back faces turned to them, until 2026-12-04).
    const bool file_normals = normals_usable(mesh) && !mesh.normals_computed;
    mesh.normals_computed = !file_normals;
    if (file_normals) {
        for (glm::vec3& n : mesh.normals) n = glm::vec3(glm::normalize(glm::dvec3(n)));
    } else {
        compute_vertex_normals(mesh);  // tolerates bad indices; validate_mesh reports them
    }
    validate_mesh(mesh);
    // A model of degenerate triangles only would load, get no stipple and draw a blank image.
    bool has_area = false;
    for (size_t t = 0; t < mesh.triangle_count() && !has_area; ++t) has_area = triangle_area(mesh, t) > 0.0;
    if (!has_area)
        fail_file(name, "no triangle with non-zero area (all " + std::to_string(mesh.triangle_count()) +
                            " triangles are degenerate)");
    const std::vector<uint32_t> corners = weld_by_position(mesh.positions);  // dropping faces keeps the vertices
    const size_t loaded = mesh.triangle_count();
    mesh.duplicates_dropped = drop_duplicate_triangles(mesh, corners, options.drop_collapsed_by_position);
    // Corners a few float steps apart are one corner (weld_by_position): a model of such slivers only has
    // none left (the STL fuzzer found one, which loaded empty).
    if (mesh.indices.empty())
        fail_file(name, "no triangle with corners apart (all " + std::to_string(loaded) +
                            " triangles have two corners at one place, within a few float steps)");
    mesh.winding = orient_consistently(mesh, corners, file_normals);
    // Computed normals followed the file's winding (where it was mixed they cancelled out), counted
    // repeated faces again, and summed the two sides of a two-sided sheet to nothing.
    // Not for a model that deforms: its skin and morph data are per vertex of the file.
    const size_t split = file_normals || !options.split_two_sided_vertices ? 0 : split_vertices_between_opposite_sides(mesh);
    if (!file_normals && (mesh.winding.triangles_turned > 0 || mesh.duplicates_dropped > 0 || split > 0))
        compute_vertex_normals(mesh);
    if (file_normals) mesh.winding.normals_turned = turn_normals_to_faces(mesh);
    return mesh;
}

// A model file is read whole, and the mesh made from it takes as much again or more (a binary PLY's about
// ten times its size): a file over half the machine's memory cannot load, and is refused by its size before
// it is read (a 50 GB OBJ ran out of memory, saying neither which file nor why). A glTF file cannot be
// 4 GiB or more (its lengths are 32-bit), and is refused before it is read too.
void check_model_size(const std::string& path, uint64_t size) {
    const std::string ext = lower_extension(path);
    if ((ext == ".gltf" || ext == ".glb") && size > UINT32_MAX)
        fail_file(path, "is " + byte_size(size) + ": a glTF file of 4 GiB or more is not supported");
    const uint64_t memory = physical_memory_bytes();
    if (memory > 0 && size > memory / 2)
        fail_file(path, "is " + byte_size(size) + ", more than a model file may be on this machine: " + byte_size(memory / 2) +
                            ", half its " + byte_size(memory) + " of memory (the file is read whole, and its mesh takes as much again)");
}

}  // namespace

void check_model_file(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (ec && ec != std::errc::no_such_file_or_directory) fail_file(path, "cannot access: " + ec.message());
    if (!fs::exists(status)) fail_file(path, "no such file");
    if (fs::is_directory(status)) fail_file(path, "is a directory, not a model file");
    if (!fs::is_regular_file(status)) fail_file(path, "is not a regular file");
    const uintmax_t size = fs::file_size(path, ec);
    if (ec) fail_file(path, "cannot read the file size: " + ec.message());
    if (size == 0) fail_file(path, "file is empty");
    check_model_size(path, size);
}

void fail_out_of_memory(const std::string& path) {
    std::error_code ec;
    const uintmax_t size = std::filesystem::file_size(path, ec);
    fail_file(path, "out of memory reading it" + (ec ? std::string() : " (" + byte_size(size) + ")"));
}

Mesh load_mesh(const std::string& path, const LoadOptions& options) {
    check_model_file(path);
    const Format format = format_of(path);
    try {
        const std::string bytes = read_file(path);
        const std::filesystem::path base_dir = std::filesystem::path(path).parent_path();
        return finish(parse(format, path, bytes, &base_dir, options), path, options);
    } catch (const std::bad_alloc&) {
        fail_out_of_memory(path);
    }
}

Mesh load_gltf_mesh(const std::string& path, const LoadOptions& options, tinygltf::Model& document) {
    check_model_file(path);
    try {
        const std::filesystem::path base_dir = std::filesystem::path(path).parent_path();
        return load_gltf_mesh_from_bytes(path, read_file(path), &base_dir, options, document);
    } catch (const std::bad_alloc&) {
        fail_out_of_memory(path);
    }
}

Mesh load_gltf_mesh_from_bytes(const std::string& name, std::string_view bytes, const std::filesystem::path* base_dir,
                               const LoadOptions& options, tinygltf::Model& document) {
    if (format_of(name) != Format::gltf) fail_file(name, "expected a glTF file (.gltf or .glb)");
    if (bytes.empty()) fail_file(name, "file is empty");
    return finish(parse_gltf(name, bytes, base_dir, options, &document), name, options);
}

Mesh load_mesh_from_bytes(const std::string& name, std::string_view bytes, const LoadOptions& options) {
    if (bytes.empty()) fail_file(name, "file is empty");
    return finish(parse(format_of(name), name, bytes, nullptr, options), name, options);
}

Mesh load_obj(const std::string& path, const LoadOptions& options) { return parse_obj(path, read_file(path), options); }

Mesh load_ply(const std::string& path, const LoadOptions& options) { return parse_ply(path, read_file(path), options); }

Mesh load_stl(const std::string& path, const LoadOptions& options) { return parse_stl(path, read_file(path), options); }

Mesh load_gltf(const std::string& path, const LoadOptions& options) {
    const std::filesystem::path base_dir = std::filesystem::path(path).parent_path();
    return parse_gltf(path, read_file(path), &base_dir, options);
}

Mesh load_mesh_for_drawing(const std::string& path, const LoadOptions& options) {
    Mesh mesh = load_mesh(path, options);
    optimize_draw_order(mesh);
#if defined(__GLIBC__)
    // Parsing, the repairs and the reordering free tens of MB in blocks under the huge-page threshold
    // (core/huge_pages.hpp), which glibc keeps in its heap; what generation allocates next does not fit
    // all of them, so they would add to its peak (3.4 MB on an 871k-triangle scan). Handed back here.
    malloc_trim(0);
#endif
    return mesh;
}

}  // namespace stipple
