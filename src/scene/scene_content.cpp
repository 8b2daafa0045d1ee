#include "scene/scene_content.hpp"

#include <chrono>
#include <map>
#include <tuple>

#include "core/error.hpp"
#include "mesh/load_mesh.hpp"
#include "stipple/stipple_cache.hpp"

namespace stipple {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::shared_ptr<const StippleSet> generate(const Mesh& mesh, const ObjectParams& params) {
    GenerationParams generation = params.generation;
    generation.progress = mesh.triangle_count() > 200'000;  // big models take seconds: show it
    return std::make_shared<const StippleSet>(generate_stipples_cached(mesh, generation));
}

// The generation parameters as a key: objects with equal keys on one mesh share their stipples.
using GenerationKey = std::tuple<std::string, float, uint64_t, uint64_t, int>;

GenerationKey generation_key(const std::string& path, const ObjectParams& p) {
    return {path, p.generation.dmax, p.generation.max_stipples, p.generation.seed, p.generation.relax_iterations};
}

}  // namespace

bool needs_regeneration(const ObjectParams& a, const ObjectParams& b) {
    return a.generation.dmax != b.generation.dmax || a.generation.max_stipples != b.generation.max_stipples ||
           a.generation.seed != b.generation.seed || a.generation.relax_iterations != b.generation.relax_iterations;
}

SceneContent load_scene_content(const Scene& scene) {
    SceneContent content;
    std::map<std::string, std::pair<std::shared_ptr<const Mesh>, Sphere>> meshes;
    std::map<GenerationKey, std::shared_ptr<const StippleSet>> stipples;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const std::string path = scene.model_path(i);
        const ObjectParams& params = scene.objects[i].params;
        validate_params(params);
        ObjectData object;
        try {
            auto found = meshes.find(path);
            if (found == meshes.end()) {
                auto start = std::chrono::steady_clock::now();
                auto mesh = std::make_shared<const Mesh>(load_mesh_for_drawing(path));
                content.load_seconds += seconds_since(start);
                found = meshes.emplace(path, std::make_pair(mesh, compute_bounding_sphere(*mesh))).first;
            }
            object.mesh = found->second.first;
            object.bounds = found->second.second;
        } catch (const Error& e) {
            // A scene file names itself and the object; a bare model keeps the loader's own line.
            if (scene.source.empty()) throw;
            fail_file(scene.source, "objects[" + std::to_string(i) + "].model: " + e.what());
        }
        GenerationKey key = generation_key(path, params);
        auto set = stipples.find(key);
        if (set == stipples.end()) {
            auto start = std::chrono::steady_clock::now();
            set = stipples.emplace(key, generate(*object.mesh, params)).first;
            content.generation_seconds += seconds_since(start);
        }
        object.stipples = set->second;
        content.objects.push_back(std::move(object));
    }
    return content;
}

ObjectData load_object_data(const std::string& model_path, const ObjectParams& params) {
    validate_params(params);
    ObjectData object;
    auto mesh = std::make_shared<const Mesh>(load_mesh_for_drawing(model_path));
    object.bounds = compute_bounding_sphere(*mesh);
    object.stipples = generate(*mesh, params);
    object.mesh = std::move(mesh);
    return object;
}

void regenerate_stipples(ObjectData& object, const ObjectParams& params) {
    validate_params(params);
    object.stipples = generate(*object.mesh, params);
}

Sphere scene_bounds(const Scene& scene, const std::vector<ObjectData>& objects) {
    STIPPLE_CHECK(scene.objects.size() == objects.size(), "one ObjectData per scene object");
    Sphere bounds{};
    for (size_t i = 0; i < objects.size(); ++i) {
        Sphere s = transform_sphere(objects[i].bounds, scene.objects[i].transform.to_matrix());
        bounds = i == 0 ? s : merge_spheres(bounds, s);
    }
    return bounds;
}

void add_scene_objects(StippleRenderer& renderer, const Scene& scene, const std::vector<ObjectData>& objects) {
    STIPPLE_CHECK(scene.objects.size() == objects.size(), "one ObjectData per scene object");
    for (size_t i = 0; i < objects.size(); ++i)
        renderer.add_object(*objects[i].mesh, *objects[i].stipples, scene.objects[i].transform.to_matrix(),
                            scene.objects[i].params);
}

FrameView scene_frame_view(const Scene& scene, const OrbitCamera& camera, const Sphere& bounds, VkExtent2D extent) {
    FrameView view;
    view.extent = extent;
    float aspect = float(extent.width) / float(extent.height);
    view.camera = camera_matrices(camera, aspect, bounds);
    view.light_view = glm::normalize(scene.light);
    view.ink_color = scene.ink;
    view.paper_color = scene.paper;
    return view;
}

}  // namespace stipple
