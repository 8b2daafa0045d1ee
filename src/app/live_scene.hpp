#pragma once
// The viewer's scene while it runs: the Scene the panel edits, the objects' CPU data, and the
// renderer kept in step with both (parameters and transforms every frame; new stipples, added and
// removed objects when asked).
#include <string>
#include <vector>

#include "render/stipple_renderer.hpp"
#include "scene/scene.hpp"
#include "scene/scene_content.hpp"

namespace stipple::app {

class LiveScene {
public:
    // Adds every object to `renderer`, which must be empty and outlive this.
    LiveScene(Scene scene, SceneContent content, StippleRenderer& renderer);

    Scene& scene() { return scene_; }
    const Scene& scene() const { return scene_; }
    size_t size() const { return scene_.objects.size(); }
    std::vector<std::string> names() const;  // file names, for the panel
    const std::vector<ObjectData>& objects() const { return data_; }  // per scene object, what was loaded
    Sphere bounds() const;                   // world space, with the current transforms

    // Copies the panel's edits into the renderer (cheap: a few bytes per object) and poses the animated
    // objects at `scene_seconds`. Before prepare(). An edit the renderer refuses (a CPU density path for
    // an animated object) is undone; the reasons come back, one line each.
    std::vector<std::string> sync(double scene_seconds = 0.0);
    // New stipples for `object` when its generation parameters differ from those it was generated with.
    // Returns whether it regenerated.
    bool regenerate_if_changed(size_t object);
    // Loads a model and adds it beside the others, scaled like the first object. Throws stipple::Error.
    void add_model(const std::string& path);
    void remove(size_t object);  // the last object stays

    // The current state with `camera` as the scene's camera; model paths relative to the file.
    void save(const std::string& path, const OrbitCamera& camera) const;

private:
    // Renderer objects [first, end) are rebuilt from the CPU data (objects keep their order).
    void rebuild_from(size_t first);

    Scene scene_;
    std::vector<ObjectData> data_;
    std::vector<ObjectParams> generated_with_;
    StippleRenderer& renderer_;
};

}  // namespace stipple::app
