#pragma once
// A scene: several objects, each with its own transform and its own paper parameters (§2.3, Fig. 3
// draws objects at different scales in one image), a camera, a light and the two colours.
// The same description drives `stipple view` and `stipple render`; scene_json.cpp reads and writes it.
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "mesh/mesh.hpp"
#include "render/camera.hpp"
#include "params/object_params.hpp"

namespace stipple {

// Placement of an object in the world: translate * rotate * scale, or an explicit matrix.
struct Transform {
    glm::vec3 translate{0.0f};
    glm::vec3 rotate_deg{0.0f};  // about X, then Y, then Z (degrees)
    float scale = 1.0f;          // uniform (what the viewer's panel edits)
    glm::vec3 axis_scale{1.0f};  // one an axis on top of it ("scale": [x, y, z] in a scene file)
    std::optional<glm::mat4> matrix;  // when set it replaces the three above (column-major, like glTF)

    glm::mat4 to_matrix() const;  // as written (what a saved scene keeps)
    // A transform whose linear part has a negative determinant mirrors the object. The drawing needs every
    // object's winding to face out (the depth pass keeps the faces facing the eye, the toon ramp and the
    // contours read the normals), so a mirrored object's mesh is stored reflected through its origin and
    // re-wound (reflected_object), and drawn with this matrix: to_matrix() times that reflection, a
    // proper transform that puts every point where to_matrix() puts the stored model's.
    bool mirrors() const;
    glm::mat4 drawing_matrix() const;
};

// What an animated model plays (glTF animations, issue 16): scene files' "animation" field, and
// `--animation` / `--time` for models given on the command line. Ignored for a static model, which
// rejects a name.
// The most seconds an animation's start (a scene file's, or --time) may lie from 0, either way.
inline constexpr double kMaxAnimationSeconds = 1e6;
// The fastest an animation may play, animation seconds per scene second, either way (a scene file's "speed").
inline constexpr double kMaxAnimationSpeed = 1000.0;

struct AnimationChoice {
    std::string name;     // the animation's name, or its index ("0", "1", ...); "" for the model's first
    double start = 0.0;   // seconds into the animation at scene time 0
    double speed = 1.0;   // animation seconds per scene second (negative plays backwards)
    bool loop = true;     // past its end the animation starts again; else it holds its last pose

    double time_at(double scene_seconds) const { return start + speed * scene_seconds; }
    bool is_default() const { return name.empty() && start == 0.0 && speed == 1.0 && loop; }
};

struct SceneObject {
    std::string model;  // as written in the scene file (relative to Scene::base_dir) or absolute
    Transform transform;
    ObjectParams params;
    AnimationChoice animation;
};

// Where the camera looks from. By default it orbits the centre of the scene's bounds at a multiple
// of the distance that frames them, so a scene reads the same at any image size and aspect.
struct SceneCamera {
    float yaw_deg = 0.0f;
    float pitch_deg = 0.0f;
    float distance = 1.0f;                    // multiple of the framing distance
    std::optional<float> world_distance;      // explicit eye-to-target distance (replaces `distance`); in
                                              // parallel projection the one whose span the view keeps
    std::optional<glm::vec3> target;          // default: the centre of the scene's bounds
    float fov_y_deg = 30.0f;
    bool orthographic = false;                // "projection": "orthographic" (OrbitCamera::orthographic)
};

struct Scene {
    std::vector<SceneObject> objects;
    SceneCamera camera;
    std::vector<SceneCamera> camera_path;  // keyframes for frame sequences (optional)
    glm::vec3 light{-0.45f, 0.55f, 0.70f};  // toward the light, view space (as FrameView::light_view)
    glm::vec3 paper{1.0f};
    glm::vec3 ink{0.0f};
    // The viewer opens it with its animations paused (a scene saved while paused reopened playing, a tester);
    // render draws the saved pose either way.
    bool paused = false;
    std::filesystem::path base_dir;  // relative model paths are resolved against it
    std::string source;              // the file it came from ("" when built from models)

    std::string model_path(size_t object) const;  // resolved against base_dir
};

// True for paths that name a scene file rather than a model (.json).
bool is_scene_file(const std::string& path);

// Sets the transforms of objects 1.. so that each sits beside the ones before it, scaled to object 0's
// bounding radius (`spheres`: the objects' object-space bounding spheres). For several models given
// on the command line, which come in any units and would otherwise overlap.
void arrange_side_by_side(Scene& scene, const std::vector<Sphere>& spheres);

// Where to put one more model of bounding sphere `sphere` next to what is already in `scene_bounds`:
// same radius as `reference_radius`, to the right. Used by drag-and-drop too.
Transform placement_beside(const Sphere& scene_bounds, const Sphere& sphere, float reference_radius);

// A sphere in world space holding `sphere` (object space) under `model`.
Sphere transform_sphere(const Sphere& sphere, const glm::mat4& model);
// The smallest sphere holding both (exact for two spheres).
Sphere merge_spheres(const Sphere& a, const Sphere& b);
// A sphere enclosing all of them, independent of their order and near the smallest one (the merge above
// is exact for two, loose for many).
Sphere enclosing_sphere(std::span<const Sphere> spheres);

// The orbit camera a SceneCamera describes for a scene with these bounds and this aspect ratio.
OrbitCamera resolve_camera(const SceneCamera& camera, const Sphere& scene_bounds, float aspect);
// The inverse, for saving: an explicit target and world distance.
SceneCamera scene_camera_from(const OrbitCamera& camera);

}  // namespace stipple
