#include "stipple/object_data.hpp"

#include "core/timing.hpp"
#include "mesh/load_mesh.hpp"
#include "stipple/stipple_cache.hpp"

namespace stipple {

std::shared_ptr<const Mesh> load_drawing_mesh(const std::string& path, double* seconds) {
    const auto start = Clock::now();
    auto mesh = std::make_shared<const Mesh>(load_mesh_for_drawing(path));
    if (seconds) *seconds = seconds_since(start);
    return mesh;
}

std::shared_ptr<const StippleSet> make_stipples(const Mesh& mesh, const GenerationParams& generation,
                                                StippleSource source) {
    GenerationParams params = generation;
    params.progress = mesh.triangle_count() > kProgressBarTriangles;  // big models take seconds: show it
    if (source == StippleSource::Cache) return std::make_shared<const StippleSet>(generate_stipples_cached(mesh, params));
    const auto start = Clock::now();
    StippleSet set = generate_stipples(mesh, params);
    finish_generated_stipples(mesh, params.seed, set);  // the selection values of §2.3, as the cache keeps them
    set.generation_seconds = seconds_since(start);               // the ranking counts as preprocessing
    return std::make_shared<const StippleSet>(std::move(set));
}

ObjectData load_object_data(const std::string& path, const GenerationParams& generation, StippleSource source) {
    ObjectData object;
    object.mesh = load_drawing_mesh(path, &object.load_seconds);
    object.bounds = compute_bounding_sphere(*object.mesh);
    object.stipples = make_stipples(*object.mesh, generation, source);
    return object;
}

}  // namespace stipple
