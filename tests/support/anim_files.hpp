#pragma once
// Animated glTF files for the animation tests: generated rigs written to a fresh temporary folder.
#include <string>

#include "anim/animated_model.hpp"
#include "anim/gltf_builder.hpp"
#include "support/test_paths.hpp"

namespace stipple::test {

// Writes `builder` to <temp>/<folder>/<name>.glb (the folder emptied first) and returns the path.
inline std::string write_rig(const anim::GltfBuilder& builder, const std::string& folder, const std::string& name) {
    const std::string path = (temp_dir(folder) / (name + ".glb")).string();
    builder.write(path);
    return path;
}

inline anim::AnimatedModel load_rig(const anim::GltfBuilder& builder, const std::string& folder,
                                    const std::string& name) {
    return anim::load_animated_model(write_rig(builder, folder, name));
}

}  // namespace stipple::test
