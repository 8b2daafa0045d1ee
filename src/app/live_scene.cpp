#include "app/live_scene.hpp"

#include <algorithm>
#include <filesystem>

#include "anim/pose.hpp"
#include "core/error.hpp"
#include "gpu/context.hpp"
#include "params/param_table.hpp"
#include "scene/scene_content.hpp"
#include "scene/scene_json.hpp"

namespace stipple::app {

LiveScene::LiveScene(Scene scene, SceneContent content, StippleRenderer& renderer)
    : scene_(std::move(scene)), renderer_(renderer) {
    STIPPLE_CHECK(renderer.object_count() == 0, "LiveScene needs an empty renderer");
    // `stipple view` checks the device and makes the stipples before its window opens (cmd_view.cpp).
    STIPPLE_CHECK(std::all_of(content.objects.begin(), content.objects.end(),
                              [](const ObjectData& o) { return o.stipples != nullptr; }),
                  "LiveScene needs every object's stipples (make_scene_stipples)");
    data_ = std::move(content.objects);
    for (size_t i = 0; i < scene_.objects.size(); ++i) {
        generated_with_.push_back(scene_.objects[i].params);
        ids_.push_back(next_id_++);
        loaded_as_.emplace(data_[i].mesh.get(), stamp_of(scene_.model_path(i)));
    }
    add_scene_objects(renderer_, scene_, data_);
}

std::vector<std::string> LiveScene::names() const {
    std::vector<std::string> names;
    for (const SceneObject& o : scene_.objects) names.push_back(std::filesystem::path(o.model).filename().string());
    return names;
}

Sphere LiveScene::bounds() const { return scene_bounds(scene_, data_); }

std::optional<size_t> LiveScene::index_of(uint64_t id) const {
    for (size_t i = 0; i < ids_.size(); ++i)
        if (ids_[i] == id) return i;
    return std::nullopt;
}

std::vector<std::string> LiveScene::sync(double scene_seconds) {
    std::vector<std::string> refused;
    for (size_t i = 0; i < scene_.objects.size(); ++i) {
        ObjectParams& wanted = scene_.objects[i].params;
        ObjectParams params = wanted;
        // Generation parameters only change with new stipples; until then the object keeps the old ones.
        params.generation = generated_with_[i].generation;
        const DensityPath previous = renderer_.params(i).density_path;
        renderer_.params(i) = params;
        try {
            check_animated_path(renderer_.object(i));  // the renderer's own rule and wording
        } catch (const Error& e) {
            refused.push_back(e.what());
            wanted.density_path = renderer_.params(i).density_path = previous;
        }
        renderer_.model(i) = scene_.objects[i].transform.drawing_matrix();
    }
    set_scene_time(renderer_, scene_, data_, scene_seconds);
    return refused;
}

bool LiveScene::generation_changed(size_t object) const {
    return needs_regeneration(generated_with_.at(object), scene_.objects.at(object).params);
}

bool LiveScene::apply_stipples(uint64_t id, const GenerationParams& generation,
                               std::shared_ptr<const StippleSet> stipples, const ObjectUpload& upload) {
    const std::optional<size_t> object = index_of(id);
    if (!object) return false;  // removed while its stipples were being made
    // Made for parameters the panel no longer asks for (changed again, or set back, while they were made):
    // stale. Set back to what the drawn stipples have, nothing else would ever replace them.
    ObjectParams made = scene_.objects[*object].params;
    made.generation = generation;
    if (needs_regeneration(made, scene_.objects[*object].params)) return false;
    renderer_.replace_object(*object, upload);
    data_[*object].stipples = std::move(stipples);
    generated_with_[*object].generation = generation;
    return true;
}

bool LiveScene::add_loaded(const std::string& path, ObjectData data, const ObjectUpload& upload,
                           const ObjectParams& params) {
    // Checked again here, beside the scene as it is now: loads dropped together (or one dropped while another
    // loaded) were each checked when dropped, beside the same plan. A model that another load of the same file
    // has brought in meanwhile becomes a copy of it.
    if (!data.motion) {
        if (const std::optional<size_t> source = copy_source(path, params)) {
            add_copy(*source, params);
            return false;
        }
    }
    check_object_fits(renderer_.context(), *data.mesh, data.stipples->size(), planned_beyond_held());
    SceneObject object = placed_beside(path, params, data.bounds);
    // A new object takes the last one's parameters, but a model that moves cannot take a density path
    // computed on the CPU from the rest pose: it takes the splat's, the default.
    const bool moved_to_gpu = data.motion && density_on_cpu(object.params.density_path);
    if (moved_to_gpu) object.params.density_path = ObjectParams{}.density_path;
    // The renderer first: if it refuses the object, the scene's lists must not hold it (the next frame
    // would ask the renderer for an object it does not have).
    renderer_.add_object(upload, object.transform.drawing_matrix(), object.params);
    loaded_as_[data.mesh.get()] = stamp_of(path);  // read moments ago, by the background load
    push_object(std::move(object), std::move(data));
    return moved_to_gpu;
}

SceneObject LiveScene::placed_beside(const std::string& path, const ObjectParams& params, const Sphere& model_bounds) const {
    SceneObject object;
    // Absolute: the scene may have come from a file in another folder (base_dir); the drop did not.
    object.model = std::filesystem::absolute(path).lexically_normal().string();
    object.params = params;
    if (!data_.empty()) {
        float reference = transform_sphere(data_[0].bounds, scene_.objects[0].transform.drawing_matrix()).radius;
        object.transform = placement_beside(bounds(), model_bounds, reference);
    }
    return object;
}

void LiveScene::push_object(SceneObject object, ObjectData data) {
    generated_with_.push_back(object.params);
    scene_.objects.push_back(std::move(object));
    data_.push_back(std::move(data));
    ids_.push_back(next_id_++);
}

ObjectParams LiveScene::params_for_new_object() const {
    return scene_.objects.empty() ? ObjectParams{} : scene_.objects.back().params;
}

bool LiveScene::regenerate_if_changed(size_t object) {
    if (!generation_changed(object)) return false;
    const GenerationParams wanted = scene_.objects.at(object).params.generation;
    check_model_fits(renderer_.context(), data_[object], wanted);
    auto stipples = make_model_stipples(data_[object].mesh->source, data_[object], wanted);
    apply_stipples(ids_[object], wanted, stipples,
                   prepare_object_upload(renderer_.context(), *data_[object].mesh, *stipples, wanted.seed,
                                         data_[object].motion));
    return true;
}

std::optional<LiveScene::FileStamp> LiveScene::stamp_of(const std::string& path) {
    std::error_code time_error, size_error;
    FileStamp stamp{std::filesystem::last_write_time(path, time_error), std::filesystem::file_size(path, size_error)};
    if (time_error || size_error) return std::nullopt;
    return stamp;
}

std::optional<size_t> LiveScene::copy_source(const std::string& path, const ObjectParams& params) const {
    const std::vector<double> wanted = generation_values(params.generation);
    const std::optional<FileStamp> now = stamp_of(path);
    if (!now) return std::nullopt;  // not there (the load says so)
    for (size_t i = 0; i < data_.size(); ++i) {
        if (data_[i].motion || scene_.objects[i].transform.mirrors() || !data_[i].stipples) continue;
        if (generation_values(generated_with_[i].generation) != wanted) continue;
        // The file as it was loaded: one rewritten since (a model edited and exported again) is loaded anew.
        const auto loaded = loaded_as_.find(data_[i].mesh.get());
        if (loaded == loaded_as_.end() || loaded->second != now) continue;
        std::error_code ec;
        if (std::filesystem::equivalent(path, scene_.model_path(i), ec) && !ec) return i;
    }
    return std::nullopt;
}

uint64_t LiveScene::planned_bytes() const {
    Scene planned = scene_;
    for (size_t i = 0; i < planned.objects.size(); ++i) planned.objects[i].params.generation = generated_with_[i].generation;
    return planned_scene_bytes(planned, SceneContent{data_});
}

uint64_t LiveScene::planned_beyond_held() const {
    const uint64_t plan = planned_bytes();
    const uint64_t held = renderer_.context().bytes_allocated();
    return plan > held ? plan - held : 0;
}

void LiveScene::add_copy(size_t source, const ObjectParams& params) {
    ObjectData data = data_.at(source);  // the mesh and stipples shared
    check_object_fits(renderer_.context(), *data.mesh, data.stipples->size(), planned_beyond_held(), true);
    SceneObject object = placed_beside(scene_.model_path(source), params, data.bounds);
    // The renderer finds the source's shape by its key and makes a copy of it (no upload).
    renderer_.add_object(*data.mesh, *data.stipples, object.transform.drawing_matrix(), object.params, data.motion);
    push_object(std::move(object), std::move(data));
}

void LiveScene::add_model(const std::string& path) {
    if (is_scene_file(path)) fail_file(path, "is a scene file: open it with `stipple view " + path + "`");
    const ObjectParams params = params_for_new_object();
    if (const std::optional<size_t> source = copy_source(path, params)) return add_copy(*source, params);
    ObjectData data = load_model_data(path);
    check_model_fits(renderer_.context(), data, params.generation, planned_beyond_held());
    data.stipples = make_model_stipples(path, data, params.generation);
    const ObjectUpload upload =
        prepare_object_upload(renderer_.context(), *data.mesh, *data.stipples, params.generation.seed, data.motion);
    add_loaded(path, std::move(data), upload, params);
}

void LiveScene::remove(size_t object) {
    if (scene_.objects.size() <= 1 || object >= scene_.objects.size()) return;
    renderer_.remove_object(object);
    scene_.objects.erase(scene_.objects.begin() + std::ptrdiff_t(object));
    data_.erase(data_.begin() + std::ptrdiff_t(object));
    generated_with_.erase(generated_with_.begin() + std::ptrdiff_t(object));
    ids_.erase(ids_.begin() + std::ptrdiff_t(object));
}

size_t LiveScene::save(const std::string& path, const OrbitCamera& camera, double scene_seconds, double playback_speed,
                       bool paused) const {
    size_t clamped = 0;
    Scene saved = scene_;
    // Said only where something moves: a still scene has no timeline to pause.
    saved.paused = paused && std::any_of(data_.begin(), data_.end(), [](const ObjectData& d) { return bool(d.motion); });
    saved.camera = scene_camera_from(camera);
    // Parameters as generated: a slider not yet released has not changed the picture.
    for (size_t i = 0; i < saved.objects.size(); ++i) saved.objects[i].params.generation = generated_with_[i].generation;
    // The pose shown: until 2026-12-05 the file kept each animation's start, and render drew the pose at 0 s. A
    // looping animation's time is wrapped into it; one that holds its ends keeps the time as it runs (a start
    // before 0 holds the first pose a while: clamped, the saved scene would start moving at once), within the
    // range a scene file takes.
    for (size_t i = 0; i < saved.objects.size(); ++i) {
        if (!data_[i].motion) continue;
        AnimationChoice& choice = saved.objects[i].animation;
        const anim::Animation& animation =
            data_[i].motion.model->animations.at(size_t(resolve_animation(data_[i], choice)));
        choice.start = choice.loop ? anim::animation_time(animation, choice.time_at(scene_seconds), true)
                                   : std::clamp(choice.time_at(scene_seconds), -kMaxAnimationSeconds, kMaxAnimationSeconds);
        // And as fast as it plays: the timeline's speed (scene seconds per wall second) is folded into the
        // object's own, so that the saved scene plays, and render --frames draws, what the viewer showed.
        const double speed = choice.speed * playback_speed;
        choice.speed = std::clamp(speed, -kMaxAnimationSpeed, kMaxAnimationSpeed);
        clamped += choice.speed != speed;
    }
    save_scene(path, saved);
    return clamped;
}

}  // namespace stipple::app
