#pragma once
// A glTF 2.0 file (.gltf or .glb, chosen by the path's extension) as tinygltf's model, ready to read:
// checked field by field first (gltf_validate: tinygltf reads a field of the wrong type as absent and
// trusts sizes), loaded by tinygltf without decoding images, and with EXT_meshopt_compression's views
// (gltf_meshopt) and KHR_draco_mesh_compression's primitives (gltf_draco) decoded. The static loader
// (gltf_loader.cpp) and the animation loader read the same model.
#include <filesystem>
#include <string>
#include <string_view>

#include <tiny_gltf.h>

namespace stipple {

// `base_dir`: the folder external buffers are resolved against; nullptr when the bytes did not come from
// a file (an external buffer is then an error). tinygltf's warnings are printed to stderr (the file is
// read once, even for an animated model: load_gltf_mesh). `decoded`, when given, says which storage
// extensions were decoded, e.g. "EXT_meshopt_compression (3 buffer views), KHR_mesh_quantization", or ""
// for none.
// Throws stipple::Error "<path>: <problem>".
tinygltf::Model read_gltf_model(const std::string& path, std::string_view bytes, const std::filesystem::path* base_dir,
                                std::string* decoded = nullptr);

}  // namespace stipple
