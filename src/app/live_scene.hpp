#pragma once
// The viewer's scene while it runs: the Scene the panel edits, the objects' CPU data, and the
// renderer kept in step with both (parameters and transforms every frame; new stipples, added and
// removed objects when they are ready). Objects have ids that survive removals, so work finished in
// the background (background_work.hpp) lands on the object it was started for.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "render/stipple_renderer.hpp"
#include "scene/scene.hpp"
#include "scene/scene_content.hpp"

namespace stipple::app {

class LiveScene {
public:
    // Adds every object, its stipples made, to `renderer`, which must be empty and outlive this.
    LiveScene(Scene scene, SceneContent content, StippleRenderer& renderer);

    Scene& scene() { return scene_; }
    const Scene& scene() const { return scene_; }
    size_t size() const { return scene_.objects.size(); }
    std::vector<std::string> names() const;  // file names, for the panel
    const std::vector<ObjectData>& objects() const { return data_; }  // per scene object, what was loaded
    Sphere bounds() const;                   // world space, with the current transforms

    uint64_t id(size_t object) const { return ids_.at(object); }
    std::optional<size_t> index_of(uint64_t id) const;
    const ObjectData& model(size_t object) const { return data_.at(object); }

    // Copies the panel's edits into the renderer (cheap: a few bytes per object) and poses the animated
    // objects at `scene_seconds`. Before prepare(). An edit the renderer refuses (a CPU density path for
    // an animated object) is undone; the reasons come back, one line each.
    std::vector<std::string> sync(double scene_seconds = 0.0);
    // True when the panel's generation parameters differ from those the stipples were made with.
    bool generation_changed(size_t object) const;
    // New stipples made elsewhere for object `id` with `generation`. Ignored (false) if the object is gone
    // or its generation parameters are no longer `generation` (edited again, or set back, meanwhile).
    bool apply_stipples(uint64_t id, const GenerationParams& generation, std::shared_ptr<const StippleSet> stipples,
                        const ObjectUpload& upload);
    // A model loaded elsewhere, added beside the others and scaled like the first object. True when it
    // moves and `params` asked for a density path on the CPU, which it cannot take: it gets the default.
    bool add_loaded(const std::string& path, ObjectData data, const ObjectUpload& upload, const ObjectParams& params);
    void remove(size_t object);  // the last object stays

    // The same work done here and now (tests, scripts): new stipples if the generation parameters
    // changed (returns whether it regenerated); a model loaded and added. Throw stipple::Error.
    bool regenerate_if_changed(size_t object);
    void add_model(const std::string& path);
    // The parameters a model dropped now would get (the last object's).
    ObjectParams params_for_new_object() const;

    // A model dropped again: an object of the scene drawn from the same file (not mirrored, not animated) whose
    // stipples were made with `params`' generation parameters, of which the new object can be a copy
    // (add_copy: it shares the mesh, the stipples and their GPU buffers); none otherwise.
    std::optional<size_t> copy_source(const std::string& path, const ObjectParams& params) const;
    // A static copy of object `source`, added beside the others as a dropped model is.
    void add_copy(size_t source, const ObjectParams& params);
    // The bytes to check a new object against beside this scene's: what a scene file of these objects plans
    // for them (planned_scene_bytes) less what the device holds now (its own share counted there), so that
    // the viewer adds only what a saved scene can load again (the viewer took 748 copies that the saved file
    // then refused at objects[724]).
    uint64_t planned_beyond_held() const;
    // What a scene file of these objects plans for them (planned_scene_bytes, the stipples as generated).
    uint64_t planned_bytes() const;

    // The current state with `camera` as the scene's camera; model paths relative to the file.
    // The scene as drawn at `scene_seconds` of the timeline: each animated object's start is the pose it shows
    // (its animation time then, wrapped or held), so that render draws the saved file as the window shows it;
    // `playback_speed` (the timeline's scene seconds per wall second) multiplies each object's speed. Returns
    // how many objects' speeds that took beyond a scene file's range, saved at its end (kMaxAnimationSpeed).
    // `paused`: the timeline is paused, and the file says so where something moves (Scene::paused).
    size_t save(const std::string& path, const OrbitCamera& camera, double scene_seconds = 0.0, double playback_speed = 1.0,
                bool paused = false) const;

private:
    // A model file as it was when loaded: a drop of the same file rewritten since is loaded again, not copied.
    struct FileStamp {
        std::filesystem::file_time_type time{};
        uintmax_t size = 0;
        bool operator==(const FileStamp&) const = default;
    };
    static std::optional<FileStamp> stamp_of(const std::string& path);
    // A new object of the model at `path` (absolute) with `params`, placed beside the scene at the first
    // object's size; and it, with its data, appended to the scene's lists.
    SceneObject placed_beside(const std::string& path, const ObjectParams& params, const Sphere& model_bounds) const;
    void push_object(SceneObject object, ObjectData data);

    Scene scene_;
    std::map<const Mesh*, std::optional<FileStamp>> loaded_as_;  // by the mesh its objects share
    std::vector<ObjectData> data_;
    std::vector<ObjectParams> generated_with_;
    std::vector<uint64_t> ids_;
    uint64_t next_id_ = 1;
    StippleRenderer& renderer_;
};

}  // namespace stipple::app
