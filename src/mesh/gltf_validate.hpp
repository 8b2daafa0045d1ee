#pragma once
// glTF 2.0 files checked against the fields stipple reads, before tinygltf parses them. tinygltf is
// silent about a field of the wrong JSON type (a string where a number belongs reads as if absent), so
// a broken file would load as some other model, or fail later with a message that names nothing.
// Here every problem is one line naming the field, in the form of the scene files' messages:
//   "<file>: accessors[3].count: expected a non-negative integer, got -1"
//
// Checked: the container (GLB header and chunks; glTF 1.0 is named as such), the JSON itself (syntax,
// nesting depth), and for JSON type and index range every field that the static loader reads
// (scene, scenes, nodes, meshes, primitives, accessors, buffer views, buffers) and that animation
// reads (skins, animations with their samplers and channels, morph targets, weights), the
// extension lists, EXT_meshopt_compression's fields (gltf_meshopt.hpp: placeholder buffers, and each
// compressed view's source range, mode, filter, stride and count, which must fill its view), Draco
// primitives' and EXT_mesh_gpu_instancing's (a node with a mesh, attributes naming accessors). Sizes are
// checked against the bytes that are really there (the GLB's BIN chunk, a data: URI, an external file),
// so no count in the JSON can make a reader allocate beyond the file.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace stipple {

// Validates a whole .gltf (binary == false: the bytes are JSON) or .glb file. `base_dir` is the folder
// external buffers are resolved against; nullptr when the bytes did not come from a file, and then an
// external buffer is an error. Throws stipple::Error "<name>: <field>: <problem>". Returns the document.
nlohmann::json validate_gltf(const std::string& name, std::string_view bytes, bool binary, const std::filesystem::path* base_dir);

// The file an external buffer's uri names: percent-escapes decoded (RFC 3986: '+' stands for itself), relative
// to `base_dir` (an absolute path stays as it is). The validator checks that file and the document reader reads
// it, so both mean the same one.
std::filesystem::path external_buffer_path(const std::filesystem::path& base_dir, const std::string& uri);

}  // namespace stipple
