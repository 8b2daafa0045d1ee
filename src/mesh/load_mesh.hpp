#pragma once
#include <filesystem>
#include <string>
#include <string_view>

#include "mesh/mesh.hpp"

namespace tinygltf {
class Model;
}

namespace stipple {

struct LoadOptions {
    // Largest element count a header may claim before we refuse it (guards against absurd counts
    // and huge allocations). The file size also bounds every count: a count is refused when the
    // file cannot possibly hold that many elements.
    uint64_t max_elements = 200'000'000;
    // Split the vertices a two-sided sheet's sides share (split_vertices_between_opposite_sides). Off for
    // the rest mesh of an animated model, whose skin and morph data are per vertex of the file.
    bool split_two_sided_vertices = true;
    // Drop triangles two of whose vertices lie at one place (drop_duplicate_triangles). Off for the rest mesh of
    // an animated model, whose skin or morph targets may pull those vertices apart (a triangle opened by the
    // animation); a triangle naming one vertex twice is dropped either way.
    bool drop_collapsed_by_position = true;
};

// Refuses, in one line naming `path`, what is not a model file to read whole: missing, a directory, not a
// regular file (a FIFO would wait for a writer forever, /dev/zero fill memory), empty, a glTF file of 4 GiB
// or more, or any file larger than half the machine's physical memory (it is read whole, and its mesh takes
// as much again). load_mesh, load_gltf_mesh and the glTF probe call it before opening a file, so that every
// format reports these the same way (the per-format readers below do not). A glTF's external buffers are not
// counted in its size (their byteLength is read as declared).
void check_model_file(const std::string& path);

// A std::bad_alloc while loading the model at `path`, in one line: "<path>: out of memory reading it
// (3.0 GiB)", the file's size (main's "stipple: out of memory" named neither the file nor the cause).
[[noreturn]] void fail_out_of_memory(const std::string& path);

// Loads .obj, .ply, .gltf, .glb or .stl (chosen by extension, case-insensitive), validates the result
// (validate_mesh), drops repeated triangles (drop_duplicate_triangles), winds the triangles of each part
// alike and inside-out parts outward (orient_consistently; Mesh::winding says what changed), computes
// normals where the file has none and turns the file's normals to agree with their faces. The file's
// triangle and vertex order is kept; renderers reorder (optimize_draw_order).
// Every problem throws stipple::Error with one line "<path>: <problem>".
Mesh load_mesh(const std::string& path, const LoadOptions& options = {});

// load_mesh of a .gltf or .glb that also hands back the document it read, decoded (mesh/gltf_document.hpp):
// the animation loader reads skins and animations from it, so an animated file is read and decoded once.
Mesh load_gltf_mesh(const std::string& path, const LoadOptions& options, tinygltf::Model& document);
// The same from bytes in memory (`base_dir` as for parse_gltf; the format from `name`'s extension).
Mesh load_gltf_mesh_from_bytes(const std::string& name, std::string_view bytes, const std::filesystem::path* base_dir,
                               const LoadOptions& options, tinygltf::Model& document);

// load_mesh, then optimize_draw_order: what every renderer draws (render, view, info, bench).
Mesh load_mesh_for_drawing(const std::string& path, const LoadOptions& options = {});

// The same from bytes already in memory (fuzzers, data that never was a file): `name` chooses the
// format by its extension and names the model in every message. A .gltf read this way cannot refer
// to external buffer files (data: URIs and .glb chunks work).
Mesh load_mesh_from_bytes(const std::string& name, std::string_view bytes, const LoadOptions& options = {});

Mesh load_obj(const std::string& path, const LoadOptions& options);
Mesh load_ply(const std::string& path, const LoadOptions& options);
Mesh load_gltf(const std::string& path, const LoadOptions& options);  // .gltf and .glb
Mesh load_stl(const std::string& path, const LoadOptions& options);   // binary or ASCII

// The parsers proper, on the file's bytes; `name` is for messages. `base_dir` is the folder that
// external glTF buffers are resolved against, or nullptr when there is none (bytes from memory).
Mesh parse_obj(const std::string& name, std::string_view text, const LoadOptions& options);
Mesh parse_ply(const std::string& name, std::string_view bytes, const LoadOptions& options);
Mesh parse_stl(const std::string& name, std::string_view bytes, const LoadOptions& options);
// `document`, when given, receives the glTF document the mesh was read from.
Mesh parse_gltf(const std::string& name, std::string_view bytes, const std::filesystem::path* base_dir,
                const LoadOptions& options, tinygltf::Model* document = nullptr);

}  // namespace stipple
