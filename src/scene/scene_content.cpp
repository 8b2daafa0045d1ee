#include "scene/scene_content.hpp"

#include <map>
#include <vector>

#include "core/error.hpp"
#include "core/timing.hpp"
#include "params/param_table.hpp"

namespace stipple {

namespace {

// The generation parameters as a key (the table's Regenerate parameters): objects with equal keys on
// one mesh share their stipples.
using GenerationKey = std::pair<std::string, std::vector<double>>;

}  // namespace

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
                double seconds = 0.0;
                auto mesh = load_drawing_mesh(path, &seconds);
                content.load_seconds += seconds;
                found = meshes.emplace(path, std::make_pair(mesh, compute_bounding_sphere(*mesh))).first;
            }
            object.mesh = found->second.first;
            object.bounds = found->second.second;
        } catch (const Error& e) {
            // A scene file names itself and the object; a bare model keeps the loader's own line.
            if (scene.source.empty()) throw;
            fail_file(scene.source, "objects[" + std::to_string(i) + "].model: " + e.what());
        }
        const GenerationKey key{path, generation_values(params.generation)};
        auto set = stipples.find(key);
        if (set == stipples.end()) {
            const auto start = Clock::now();
            set = stipples.emplace(key, make_stipples(*object.mesh, params.generation)).first;
            content.generation_seconds += seconds_since(start);
        }
        object.stipples = set->second;
        content.objects.push_back(std::move(object));
    }
    return content;
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
