#include "cli/loaded_object.hpp"

#include <chrono>

#include "mesh/load_mesh.hpp"
#include "stipple/stipple_cache.hpp"

namespace stipple::cli {

LoadedObject load_object(const std::string& path, const ObjectParams& params) {
    validate_params(params);
    LoadedObject object;
    auto start = std::chrono::steady_clock::now();
    object.mesh = load_mesh_for_drawing(path);
    object.load_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    object.bounds_sphere = compute_bounding_sphere(object.mesh);
    GenerationParams generation = params.generation;
    generation.progress = object.mesh.triangle_count() > 200'000;
    object.stipples = generate_stipples_cached(object.mesh, generation);
    return object;
}

}  // namespace stipple::cli
