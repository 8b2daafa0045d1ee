#include "render/camera.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace stipple {

float framing_distance(const Sphere& sphere, float aspect, float fov_y_deg, bool orthographic) {
    float half_y = glm::radians(fov_y_deg) * 0.5f;
    float half_x = std::atan(std::tan(half_y) * aspect);
    float half = std::min(half_x, half_y);
    // Seen in perspective the outline is the cone of lines of sight touching the sphere (sin); in parallel
    // projection, its radius against the view's half span (tan).
    return std::max(sphere.radius, 1e-30f) / (orthographic ? std::tan(half) : std::sin(half));
}

OrbitCamera frame_sphere(const Sphere& sphere, float aspect, float distance_multiple, float yaw_deg, float pitch_deg,
                         float fov_y_deg, bool orthographic) {
    OrbitCamera camera;
    camera.fov_y_deg = fov_y_deg;
    camera.orthographic = orthographic;
    camera.target = sphere.center;
    camera.distance = framing_distance(sphere, aspect, camera.fov_y_deg, camera.orthographic) * distance_multiple;
    camera.yaw_deg = yaw_deg;
    camera.pitch_deg = pitch_deg;
    return camera;
}

CameraMatrices camera_matrices(const OrbitCamera& camera, float aspect, const Sphere& scene) {
    float yaw = glm::radians(camera.yaw_deg);
    float pitch = glm::radians(camera.pitch_deg);
    glm::vec3 offset(std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch));
    CameraMatrices m;
    m.orthographic = camera.orthographic;
    float radius = std::max(scene.radius, 1e-30f) * 1.02f;
    // An orthographic eye stands just outside the scene whatever the zoom (its distance sets the span, not the
    // place): nothing of the scene lies before the near plane, and depth keeps its precision at any zoom.
    const float eye_distance =
        camera.orthographic ? glm::length(scene.center - camera.target) + 2.0f * radius : camera.distance;
    m.eye = camera.target + offset * eye_distance;
    glm::vec3 up = std::abs(std::cos(pitch)) < 1e-4f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
    m.view = glm::lookAt(m.eye, camera.target, up);

    // The planes bound the scene's sphere in depth along the view axis. The straight-line distance to its
    // centre is more than that depth when the centre lies off the axis (a scene camera aimed beside the
    // objects): as the near plane's distance it cut away the front of an object off to the side.
    const float center_depth = glm::dot(scene.center - m.eye, glm::normalize(camera.target - m.eye));
    m.far_plane = std::max(center_depth + radius, radius);  // a scene behind the eye: nothing to draw, planes valid
    m.near_plane = std::max(center_depth - radius, m.far_plane * 1e-4f);
    if (camera.orthographic) {
        const float half_y = camera.distance * std::tan(glm::radians(camera.fov_y_deg) * 0.5f);
        m.proj = glm::ortho(-half_y * aspect, half_y * aspect, -half_y, half_y, m.near_plane, m.far_plane);
    } else {
        m.proj = glm::perspective(glm::radians(camera.fov_y_deg), aspect, m.near_plane, m.far_plane);
    }
    if (camera.lens_shift != 0.0f)  // clip x + shift * w: device x + shift (device units: 2 / aspect a height)
        m.proj = glm::translate(glm::mat4(1.0f), glm::vec3(camera.lens_shift * 2.0f / aspect, 0.0f, 0.0f)) * m.proj;
    return m;
}

}  // namespace stipple
