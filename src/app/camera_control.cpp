#include "app/camera_control.hpp"

#include <algorithm>
#include <cmath>

namespace stipple::app {

namespace {

glm::vec3 eye_offset(const OrbitCamera& camera) {
    float yaw = glm::radians(camera.yaw_deg), pitch = glm::radians(camera.pitch_deg);
    return {std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch)};
}

}  // namespace

glm::vec3 camera_right(const OrbitCamera& camera) {
    // Same construction as camera_matrices' lookAt with +Y up: right = forward x up.
    glm::vec3 forward = -eye_offset(camera);
    glm::vec3 right = glm::cross(forward, glm::vec3(0, 1, 0));
    float length = glm::length(right);
    if (length < 1e-6f) {
        float yaw = glm::radians(camera.yaw_deg);
        return {std::cos(yaw), 0.0f, -std::sin(yaw)};
    }
    return right / length;
}

glm::vec3 camera_up(const OrbitCamera& camera) { return glm::cross(camera_right(camera), -eye_offset(camera)); }

void orbit_degrees(OrbitCamera& camera, float yaw_deg, float pitch_deg) {
    camera.yaw_deg = std::fmod(camera.yaw_deg + yaw_deg, 360.0f);
    camera.pitch_deg = std::clamp(camera.pitch_deg + pitch_deg, -kMaxPitch, kMaxPitch);
}

void orbit(OrbitCamera& camera, glm::vec2 drag_pixels) {
    orbit_degrees(camera, -drag_pixels.x * kDegreesPerPixel, drag_pixels.y * kDegreesPerPixel);
}

void pan(OrbitCamera& camera, glm::vec2 drag_pixels, float viewport_height) {
    float world_per_pixel =
        2.0f * camera.distance * std::tan(glm::radians(camera.fov_y_deg) * 0.5f) / std::max(viewport_height, 1.0f);
    // Screen y grows downward: dragging down moves the scene down, so the target moves up.
    camera.target += (-drag_pixels.x * camera_right(camera) + drag_pixels.y * camera_up(camera)) * world_per_pixel;
}

void zoom(OrbitCamera& camera, float steps, const Sphere& bounds, float aspect) {
    float framing = framing_distance(bounds, aspect, camera.fov_y_deg, camera.orthographic);
    camera.distance = std::clamp(camera.distance * std::pow(kZoomPerStep, steps), framing * 1e-3f, framing * 1e3f);
}

void frame_all(OrbitCamera& camera, const Sphere& bounds, float aspect, glm::vec2 free) {
    const float share = std::clamp(free.y - free.x, 0.05f, 1.0f);  // a sliver left free frames in a twentieth
    // Looking at the centre, the sphere's outline is a circle about the image's middle: framed for the free
    // columns' shape it spans their width or the window's height, and the lens shift moves it into them.
    camera.target = bounds.center;
    camera.distance = framing_distance(bounds, aspect * share, camera.fov_y_deg, camera.orthographic);
    camera.lens_shift = lens_shift_into(free, aspect);
}

float lens_shift_into(glm::vec2 free, float aspect) {
    return 0.5f * (free.x + free.y - 1.0f) * aspect;  // the free columns' middle (device x) in heights of the view
}

void frame_at_open(OrbitCamera& camera, const Sphere& bounds, float aspect, glm::vec2 free, std::optional<float> distance_multiple) {
    if (!distance_multiple) {  // a placed camera: as given, its target moved into the free columns
        camera.lens_shift = lens_shift_into(free, aspect);
        return;
    }
    frame_all(camera, bounds, aspect, free);
    camera.distance *= *distance_multiple;  // the centre's image stays in the free columns' middle
}

glm::vec2 columns_left_free(glm::vec4 rect, glm::vec2 window) {
    if (window.x <= 0.0f || window.y <= 0.0f) return {0.0f, 1.0f};
    const float left = std::clamp(rect.x / window.x, 0.0f, 1.0f), right = std::clamp((rect.x + rect.z) / window.x, 0.0f, 1.0f);
    if (right <= left) return {0.0f, 1.0f};
    const glm::vec2 free = left >= 1.0f - right ? glm::vec2(0.0f, left) : glm::vec2(right, 1.0f);
    return free.y - free.x < 0.25f ? glm::vec2(0.0f, 1.0f) : free;
}

}  // namespace stipple::app
