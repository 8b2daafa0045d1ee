#pragma once
// A cheap look at a glTF file before loading it: whether it declares animations, skins or morph weights.
// Reads only the JSON (a .glb's first chunk), so a static model is loaded once by the static loader
// instead of twice.
#include <string>

namespace stipple::anim {

// True when the file's JSON has a non-empty "animations" array, or when it cannot tell (malformed JSON:
// the full loader then reports the problem in its own words). What is no model file to read (missing, a
// FIFO, a device, empty) is refused as load_mesh refuses it (check_model_file).
bool gltf_declares_animations(const std::string& path);

// True when the file declares animations, skins, or morph weights other than zero (a mesh's default
// weights or a node's): its rest pose may then differ from the static loader's placement of each
// primitive by its node, and only the animated loader draws it right (animated_model.cpp). Also true when
// it cannot tell.
bool gltf_declares_deformation(const std::string& path);

}  // namespace stipple::anim
