#pragma once
// A cheap look at a glTF file before loading it: whether it declares any animation. Reads only the JSON
// (a .glb's first chunk), so a static model is loaded once by the static loader instead of twice.
#include <string>

namespace stipple::anim {

// True when the file's JSON has a non-empty "animations" array, or when it cannot tell (unreadable,
// malformed: the full loader then reports the problem in its own words).
bool gltf_declares_animations(const std::string& path);

}  // namespace stipple::anim
