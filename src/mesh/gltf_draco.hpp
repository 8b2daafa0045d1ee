#pragma once
// KHR_draco_mesh_compression: a glTF primitive whose attributes and indices are stored as one Draco
// bitstream (Google's mesh codec, as three.js, Blender and glTF-Transform write it). After tinygltf has
// loaded the file, each such primitive's bitstream is decoded (Debian's libdraco) and its accessors are
// given the decoded values in a buffer of their own, so the readers (AccessorReader) see plain accessors.
// Each Draco attribute must have the component type and size its accessor declares; morph targets are
// not compressed by the extension and stay as they are.
#include <string>

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

namespace stipple {

// tinygltf refuses an indices accessor without a buffer view, which is how Draco primitives declare theirs:
// each is pointed at a four-byte stand-in (a buffer and view appended to the validated document), which
// decode_draco replaces. Returns whether the document changed.
bool prepare_draco(nlohmann::json& doc);

// Returns how many primitives were decoded. Throws stipple::Error
// "<file>: meshes[m].primitives[p].extensions.KHR_draco_mesh_compression: ..." for a bitstream that does not
// decode or does not match its accessors.
size_t decode_draco(const std::string& file, tinygltf::Model& model);

}  // namespace stipple
