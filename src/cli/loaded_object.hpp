#pragma once
// A model loaded from disk with its generated stipples and how long each step took.
#include <string>

#include "mesh/mesh.hpp"
#include "render/object_params.hpp"
#include "stipple/stipple_set.hpp"

namespace stipple::cli {

struct LoadedObject {
    Mesh mesh;
    StippleSet stipples;
    Sphere bounds_sphere;
    double load_seconds = 0.0;
};

// Loads and generates; a progress bar is shown for models over ~200k triangles on a terminal.
LoadedObject load_object(const std::string& path, const ObjectParams& params);

}  // namespace stipple::cli
