#include "core/unit_direction.hpp"
#include "scene/scene_content.hpp"

#include <algorithm>
#include <map>
#include <vector>

#include "anim/pose.hpp"
#include "core/error.hpp"
#include "core/timing.hpp"
#include "params/param_table.hpp"
#include "render/object_gpu.hpp"

namespace stipple {

namespace {

// The generation parameters as a key (the table's Regenerate parameters): objects with equal keys on
// one mesh share their stipples.
using GenerationKey = std::pair<std::string, std::vector<double>>;

// An error about object i: a scene file names itself and the object's field; a bare model keeps the loader's
// own line.
[[noreturn]] void fail_in_scene(const Scene& scene, size_t i, const std::string& field, const Error& e) {
    if (scene.source.empty()) throw e;
    fail_file(scene.source, "objects[" + std::to_string(i) + "]." + field + ": " + e.what());
}

// What an object's mesh is: its model, reflected where its transform mirrors it (a mirrored copy and the
// model itself are two meshes, with two sets of stipples).
std::string mesh_key(const Scene& scene, size_t i) {
    return scene.objects[i].transform.mirrors() ? scene.model_path(i) + "\n(mirrored)" : scene.model_path(i);
}

}  // namespace

SceneContent load_scene_models(const Scene& scene) {
    SceneContent content;
    std::map<std::string, ObjectData> models;  // by mesh_key
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const std::string path = scene.model_path(i);
        validate_params(scene.objects[i].params);
        ObjectData object;
        try {
            auto found = models.find(path);
            if (found == models.end()) {
                found = models.emplace(path, load_model_data(path)).first;
                content.load_seconds += found->second.load_seconds;
            }
            object = found->second;
        } catch (const Error& e) {
            fail_in_scene(scene, i, "model", e);
        }
        if (scene.objects[i].transform.mirrors()) {
            try {
                auto found = models.find(mesh_key(scene, i));
                if (found == models.end()) found = models.emplace(mesh_key(scene, i), reflected_object(object)).first;
                object = found->second;
            } catch (const Error& e) {
                fail_in_scene(scene, i, "transform", e);
            }
        }
        content.objects.push_back(std::move(object));
    }
    // Models given side by side on the command line share its --animation: it is for those that move (a fox
    // beside a static model walks; it refused the pair until 2026-12-05). A scene file names each object's own.
    const bool shared_choice = scene.source.empty() && scene.objects.size() > 1 &&
                               std::any_of(content.objects.begin(), content.objects.end(), [](const ObjectData& o) { return bool(o.motion); });
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        if (shared_choice && !content.objects[i].motion) continue;
        try {
            resolve_animation(content.objects[i], scene.objects[i].animation);
        } catch (const Error& e) {
            fail_in_scene(scene, i, "animation.name", e);
        }
        // Said where the scene file names the path (the renderer's own refusal names the model).
        const DensityPath path = scene.objects[i].params.density_path;
        if (content.objects[i].motion && density_on_cpu(path))
            fail_in_scene(scene, i, "params.density_path",
                          Error(scene.objects[i].model + ": the " + density_path_name(path) +
                                " density path cannot draw an animated model (it computes densities on the CPU from the "
                                "rest pose): use vertex, indirect or splat"));
    }
    return content;
}

void drop_animations_of_static_models(Scene& scene, const SceneContent& content) {
    STIPPLE_CHECK(scene.objects.size() == content.objects.size(), "one ObjectData per scene object");
    for (size_t i = 0; i < scene.objects.size(); ++i)
        if (!content.objects[i].motion) scene.objects[i].animation = AnimationChoice{};
}

void make_scene_stipples(const Scene& scene, SceneContent& content) {
    STIPPLE_CHECK(scene.objects.size() == content.objects.size(), "one ObjectData per scene object");
    std::map<GenerationKey, std::shared_ptr<const StippleSet>> stipples;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        ObjectData& object = content.objects[i];
        const GenerationParams& generation = scene.objects[i].params.generation;
        const GenerationKey key{mesh_key(scene, i), generation_values(generation)};
        auto set = stipples.find(key);
        if (set == stipples.end()) {
            const auto start = Clock::now();
            set = stipples.emplace(key, make_model_stipples(scene.model_path(i), object, generation)).first;
            content.generation_seconds += seconds_since(start);
        }
        object.stipples = set->second;
    }
}

std::vector<uint64_t> planned_scene_stipples(const Scene& scene, const SceneContent& content) {
    STIPPLE_CHECK(scene.objects.size() == content.objects.size(), "one ObjectData per scene object");
    std::map<GenerationKey, uint64_t> counted;
    std::vector<uint64_t> planned;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const GenerationParams& generation = scene.objects[i].params.generation;
        const GenerationKey key{mesh_key(scene, i), generation_values(generation)};
        auto found = counted.find(key);
        if (found == counted.end()) found = counted.emplace(key, planned_stipple_count(content.objects[i], generation)).first;
        planned.push_back(found->second);
    }
    return planned;
}

bool is_static_copy(const Scene& scene, const SceneContent& content, size_t i) {
    if (content.objects[i].motion) return false;
    // One model's objects hold one mesh (a mirrored copy another: load_scene_models), so the mesh is compared
    // first, cheaply, and the generation parameters only where it is the same.
    const Mesh* mesh = content.objects[i].mesh.get();
    const std::vector<double> generation = generation_values(scene.objects[i].params.generation);
    for (size_t j = 0; j < i; ++j)
        if (content.objects[j].mesh.get() == mesh && !content.objects[j].motion &&
            generation_values(scene.objects[j].params.generation) == generation)
            return true;
    return false;
}

uint64_t check_scene_object_fits(const gpu::Context& context, const Scene& scene, const SceneContent& content, size_t i,
                                 uint64_t planned_stipples, uint64_t planned_before, const std::string& twice,
                                 uint64_t list_bytes) {
    const Mesh& mesh = *content.objects[i].mesh;
    const bool copy = is_static_copy(scene, content, i);
    try {
        return check_object_fits(context, mesh, planned_stipples, planned_before + list_bytes, copy);
    } catch (const Error&) {
        if (planned_before == 0 && list_bytes == 0) throw;
        // Too large by itself, this throws its own refusal, which says what to lower.
        const uint64_t alone = check_object_fits(context, mesh, planned_stipples, 0, copy);
        // 200 copies of a model at the default D_max: each fits, all together do not.
        const bool file = !scene.source.empty();
        const std::string object = file                      ? "objects[" + std::to_string(i) + "] (" + mesh.source + ")"
                                   : scene.objects.size() > 1 ? mesh.source + " (model " + std::to_string(i + 1) + ")"
                                                              : mesh.source;
        // Vector output's list is most of a copy's need: said, or 2.8 MiB a spot was named where 13 were needed.
        const std::string list = list_bytes ? " (" + mebibytes(list_bytes) + " of it vector output's list of its visible "
                                                 "stipples, 20 bytes a candidate)" : "";
        const std::string before = planned_before ? " beside the " + mebibytes(planned_before) + " the objects before it take" : "";
        const std::string line = object + " needs about " + mebibytes(alone + list_bytes) + " of GPU memory" + list + before +
                                 twice + ", and the device has no more room: " +
                                 (file ? "fewer objects, or lighter ones (a lower \"dmax\" or \"max_stipples\" in their params)"
                                       : "fewer models, or a lower --dmax or --max-stipples") +
                                 (list_bytes ? ", or write a PNG" : "");
        if (scene.source.empty()) fail(line);
        fail_file(scene.source, line);
    }
}

uint64_t check_scene_visible_list_fits(const gpu::Context& context, const Scene& scene, size_t i, uint64_t planned_stipples) {
    if (scene.source.empty()) return check_visible_list_fits(context, planned_stipples);
    try {
        return check_visible_list_fits(context, planned_stipples, "a lower \"dmax\" or \"max_stipples\" in its params");
    } catch (const Error& e) {
        fail_file(scene.source, "objects[" + std::to_string(i) + "] (" + scene.model_path(i) + "): " + e.what());
    }
}

uint64_t check_scene_fits(const gpu::Context& context, const Scene& scene, const SceneContent& content,
                          uint64_t planned_before) {
    const std::vector<uint64_t> planned = planned_scene_stipples(scene, content);
    uint64_t bytes = 0;
    for (size_t i = 0; i < planned.size(); ++i)
        bytes += check_scene_object_fits(context, scene, content, i, planned[i], planned_before + bytes);
    return bytes;
}

uint64_t planned_scene_bytes(const Scene& scene, const SceneContent& content) {
    const std::vector<uint64_t> planned = planned_scene_stipples(scene, content);
    uint64_t bytes = 0;
    for (size_t i = 0; i < planned.size(); ++i)
        bytes += planned_object_bytes(*content.objects[i].mesh, planned[i], is_static_copy(scene, content, i));
    return bytes;
}

SceneContent load_scene_content(const Scene& scene) {
    SceneContent content = load_scene_models(scene);
    make_scene_stipples(scene, content);
    return content;
}

Sphere scene_bounds(const Scene& scene, const std::vector<ObjectData>& objects) {
    STIPPLE_CHECK(scene.objects.size() == objects.size(), "one ObjectData per scene object");
    std::vector<Sphere> spheres;
    for (size_t i = 0; i < objects.size(); ++i) {
        // The box turned up as the drawing turns it (a quarter turn about the sphere's centre keeps it a box).
        const glm::mat4 up = up_axis_rotation(scene.objects[i].params.up, objects[i].bounds.center);
        Bounds box{glm::vec3(INFINITY), glm::vec3(-INFINITY)};
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 p(up * glm::vec4(objects[i].box.corner(corner), 1.0f));
            box.min = glm::min(box.min, p), box.max = glm::max(box.max, p);
        }
        spheres.push_back(transformed_bounds(objects[i].bounds, box, scene.objects[i].transform.drawing_matrix()));
    }
    return enclosing_sphere(spheres);
}

void add_scene_objects(StippleRenderer& renderer, const Scene& scene, const std::vector<ObjectData>& objects) {
    STIPPLE_CHECK(scene.objects.size() == objects.size(), "one ObjectData per scene object");
    for (size_t i = 0; i < objects.size(); ++i) {
        try {
            renderer.add_object(*objects[i].mesh, *objects[i].stipples, scene.objects[i].transform.drawing_matrix(),
                                scene.objects[i].params, objects[i].motion);
        } catch (const Error& e) {
            // What the plan could not foresee (the device's allocations all taken): which object met it.
            if (scene.source.empty() || scene.objects.size() < 2) throw;
            fail_file(scene.source, "objects[" + std::to_string(i) + "] (" + scene.model_path(i) + "): " + e.what());
        }
    }
}

int resolve_animation(const ObjectData& model, const AnimationChoice& choice) {
    if (!model.motion) {
        if (choice.name.empty()) return anim::kRestPose;
        const size_t still = model.still.animations.size();  // a glTF file's animations that move nothing it draws
        fail_file(model.mesh ? model.mesh->source : std::string("model"),
                  "has no animation to play (animation '" + choice.name + "' was asked for" +
                      (still == 0 ? std::string(")")
                                  : std::string("; its ") + (still == 1 ? "animation moves" : std::to_string(still) + " animations move") +
                                        " nothing it draws)"));
    }
    return choice.name.empty() ? 0 : anim::find_animation(*model.motion.model, choice.name);
}

void set_scene_time(StippleRenderer& renderer, const Scene& scene, const std::vector<ObjectData>& objects,
                    double scene_seconds) {
    STIPPLE_CHECK(scene.objects.size() == objects.size() && renderer.object_count() == objects.size(),
                  "one ObjectData and one renderer object per scene object");
    for (size_t i = 0; i < objects.size(); ++i) {
        if (!objects[i].motion) continue;
        const AnimationChoice& choice = scene.objects[i].animation;
        renderer.set_animation(i, resolve_animation(objects[i], choice), choice.time_at(scene_seconds), choice.loop);
    }
}

FrameView scene_frame_view(const Scene& scene, const OrbitCamera& camera, const Sphere& bounds, VkExtent2D extent) {
    FrameView view;
    view.extent = extent;
    float aspect = float(extent.width) / float(extent.height);
    view.camera = camera_matrices(camera, aspect, bounds);
    view.light_view = unit_direction(scene.light).value_or(glm::vec3(0.0f, 0.0f, 1.0f));
    view.ink_color = scene.ink;
    view.paper_color = scene.paper;
    return view;
}

}  // namespace stipple
