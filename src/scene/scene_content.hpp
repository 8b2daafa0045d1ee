#pragma once
// A scene's models loaded and their stipples generated, ready for a StippleRenderer; the camera and
// FrameView of a scene. Used by `render` (offscreen) and `view` (window) alike, so both draw the
// same image of the same scene.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "render/stipple_renderer.hpp"
#include "scene/scene.hpp"
#include "stipple/object_data.hpp"
#include "stipple/stipple_set.hpp"

namespace stipple {

struct SceneContent {
    std::vector<ObjectData> objects;  // one per Scene::objects entry
    double load_seconds = 0.0;
    double generation_seconds = 0.0;
};

// Loads every model once and generates stipples (a progress bar for big models on a terminal): the two
// steps below. A scene from a file prefixes loader errors with "<scene>: objects[i].model: " and an
// unknown animation with "<scene>: objects[i].animation.name: ".
SceneContent load_scene_content(const Scene& scene);

// The first step: every model loaded, no stipples yet. What needs only the models (the options that
// depend on them, whether a device can hold the stipples: planned_scene_stipples) is checked before the
// second, which may take minutes.
SceneContent load_scene_models(const Scene& scene);
// Models given side by side on the command line share its --animation, which a static one among them ignores:
// its choice cleared (as a saved scene then writes it).
void drop_animations_of_static_models(Scene& scene, const SceneContent& content);
// The second: every object's stipples generated or read from the cache (objects of one model and equal
// generation parameters share them).
void make_scene_stipples(const Scene& scene, SceneContent& content);
// The count of stipples make_scene_stipples makes for each object, counted without making them.
std::vector<uint64_t> planned_scene_stipples(const Scene& scene, const SceneContent& content);
// Whether `context`'s device holds every object's planned stipples together, beside `planned_before` bytes
// (check_object_fits, object by object); throws its one-line refusal otherwise. Returns the bytes planned.
uint64_t check_scene_fits(const gpu::Context& context, const Scene& scene, const SceneContent& content,
                          uint64_t planned_before = 0);
// The bytes check_scene_fits plans for the scene's objects, without checking them: the viewer checks a new
// object beside them, so that what it accepts a saved scene file's plan also holds.
uint64_t planned_scene_bytes(const Scene& scene, const SceneContent& content);
// check_visible_list_fits for object i's planned stipples: from a scene file, the line names the file and the
// object and says what to lower in its params (the command's --dmax and --max-stipples do not take a scene).
uint64_t check_scene_visible_list_fits(const gpu::Context& context, const Scene& scene, size_t i, uint64_t planned_stipples);
// Whether object i is a static copy of an object before it (the same model and generation parameters, neither
// animated): the renderer gives it that object's shape (ObjectShape), so it needs its own buffers only.
bool is_static_copy(const Scene& scene, const SceneContent& content, size_t i);
// Object i's part of that check. An object that fits alone but not beside the ones before it is refused in a
// line about the scene (naming the object and what the others take; `twice`, when not empty, says why the
// scene is held twice), not with the single model's advice of --dmax, which a scene file does not take.
// `list_bytes`: vector output's list of the object's visible stipples, checked with it and named in the line
// (returned apart: the bytes returned are the object's own).
uint64_t check_scene_object_fits(const gpu::Context& context, const Scene& scene, const SceneContent& content, size_t i,
                                 uint64_t planned_stipples, uint64_t planned_before, const std::string& twice = "",
                                 uint64_t list_bytes = 0);


// World-space bounds of all objects: the union of their transformed bounding spheres.
Sphere scene_bounds(const Scene& scene, const std::vector<ObjectData>& objects);

// Adds every object, with its transform, parameters and motion, to `renderer` (in scene order).
void add_scene_objects(StippleRenderer& renderer, const Scene& scene, const std::vector<ObjectData>& objects);

// The animation `choice` names in `model`: its index ("" is the first). Throws a one-line error naming
// the model and its animations when there is no such animation or the model has none to play.
int resolve_animation(const ObjectData& model, const AnimationChoice& choice);

// Poses every animated object at `scene_seconds` of the scene's clock (each object's choice sets its
// animation, start, speed and loop). Renderer objects are the scene's, in order.
void set_scene_time(StippleRenderer& renderer, const Scene& scene, const std::vector<ObjectData>& objects,
                    double scene_seconds);

// The frame a scene's camera sees: matrices with near/far hugging the scene's bounds, its light and colours.
FrameView scene_frame_view(const Scene& scene, const OrbitCamera& camera, const Sphere& bounds, VkExtent2D extent);

}  // namespace stipple
