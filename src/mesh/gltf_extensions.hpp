#pragma once
// The extension lists of a glTF file (part of gltf_validate): extensionsUsed and extensionsRequired
// must be arrays of well-formed names; a name that is neither used in the file nor a known extension
// but close to one is taken for a misspelling and named with the likely intent; a required extension
// that changes how geometry is stored (compression, quantisation, instancing) or that we do not know
// is refused, since the model would load wrong without it, except those that loading decodes
// (KHR_mesh_quantization, EXT_meshopt_compression, KHR_draco_mesh_compression).
#include <set>
#include <string>

#include <nlohmann/json.hpp>

namespace stipple {

// `used` holds the keys of every "extensions" object in the file.
void check_gltf_extensions(const std::string& name, const nlohmann::json& doc, const std::set<std::string>& used);

}  // namespace stipple
