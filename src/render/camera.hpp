#pragma once
// Orbit camera framing a bounding sphere; Vulkan depth range [0, 1].
#include <glm/glm.hpp>

#include "mesh/mesh.hpp"

namespace stipple {

struct OrbitCamera {
    glm::vec3 target{0.0f};
    float distance = 1.0f;  // eye to target, world units
    float yaw_deg = 0.0f;   // around +Y; 0 looks down -Z from +Z
    float pitch_deg = 0.0f; // up is positive
    float fov_y_deg = 30.0f;
    // How far the image moves right, in heights of the view, as a lens shifted sideways (the frustum sheared,
    // the eye and its direction unchanged): the viewer centres the target in the columns its panel leaves
    // free, so that orbiting still turns about the target and the scene stays where it is. In heights, not
    // widths: a window made narrower or wider keeps the image as many pixels from its centre, as far as the
    // panel (of fixed pixels) needs.
    float lens_shift = 0.0f;
    // Parallel lines of sight (technical and scientific illustration): the view spans 2 distance tan(fov_y / 2)
    // vertically at every depth, what the perspective view spans at the target's, so switching keeps the
    // target's scale. The eye is only placed for clipping then, beyond the scene.
    bool orthographic = false;
};

struct CameraMatrices {
    glm::mat4 view{1.0f};
    glm::mat4 proj{1.0f};
    glm::vec3 eye{0.0f};
    bool orthographic = false;  // proj is an orthographic projection (OrbitCamera::orthographic)
    float near_plane = 0.01f;
    float far_plane = 100.0f;
};

// The depth that divides pixels per unit at unit depth into a point's scale on screen: its depth in
// perspective, 1 in parallel projection (formulas::scaling_distance, for the GPU's terms).
inline float scaling_depth(const CameraMatrices& m, float depth) { return m.orthographic ? 1.0f : depth; }

// Distance at which the sphere just fits the view, vertically and horizontally (in an orthographic view, the
// distance whose span fits it).
float framing_distance(const Sphere& sphere, float aspect, float fov_y_deg, bool orthographic = false);

// A camera framing `sphere`, at `distance_multiple` times the framing distance.
OrbitCamera frame_sphere(const Sphere& sphere, float aspect, float distance_multiple, float yaw_deg, float pitch_deg,
                         float fov_y_deg = OrbitCamera{}.fov_y_deg, bool orthographic = false);

// Near and far planes hug `scene` (so depth precision is spent on the objects).
CameraMatrices camera_matrices(const OrbitCamera& camera, float aspect, const Sphere& scene);

}  // namespace stipple
