#pragma once
// A scene's models loaded and their stipples generated, ready for a StippleRenderer; the camera and
// FrameView of a scene. Used by `render` (offscreen) and `view` (window) alike, so both draw the
// same image of the same scene.
#include <memory>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "render/stipple_renderer.hpp"
#include "scene/scene.hpp"
#include "stipple/stipple_set.hpp"

namespace stipple {

// One object's CPU data. Meshes and stipple sets are shared between objects that use the same
// model (and, for stipples, the same generation parameters): a scene may show one model many times.
struct ObjectData {
    std::shared_ptr<const Mesh> mesh;
    Sphere bounds;  // object space
    std::shared_ptr<const StippleSet> stipples;
};

struct SceneContent {
    std::vector<ObjectData> objects;  // one per Scene::objects entry
    double load_seconds = 0.0;
    double generation_seconds = 0.0;
};

// Loads every model once and generates stipples (a progress bar for big models on a terminal).
// A scene from a file prefixes loader errors with "<scene>: objects[i].model: ".
SceneContent load_scene_content(const Scene& scene);

// Loads one model and generates its stipples (the viewer's drag-and-drop).
ObjectData load_object_data(const std::string& model_path, const ObjectParams& params);

// New stipples for an object whose generation parameters (D_max, budget, seed, relaxation) changed.
void regenerate_stipples(ObjectData& object, const ObjectParams& params);

// True when going from `a` to `b` needs new stipples (the rest of the parameters act per frame).
bool needs_regeneration(const ObjectParams& a, const ObjectParams& b);

// World-space bounds of all objects: the union of their transformed bounding spheres.
Sphere scene_bounds(const Scene& scene, const std::vector<ObjectData>& objects);

// Adds every object, with its transform and parameters, to `renderer` (in scene order).
void add_scene_objects(StippleRenderer& renderer, const Scene& scene, const std::vector<ObjectData>& objects);

// The frame a scene's camera sees: matrices with near/far hugging the scene's bounds, its light and colours.
FrameView scene_frame_view(const Scene& scene, const OrbitCamera& camera, const Sphere& bounds, VkExtent2D extent);

}  // namespace stipple
