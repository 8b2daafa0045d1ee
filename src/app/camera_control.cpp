#include "app/camera_control.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace stipple::app {

namespace {

glm::vec3 eye_offset(const OrbitCamera& camera) {
    float yaw = glm::radians(camera.yaw_deg), pitch = glm::radians(camera.pitch_deg);
    return {std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch)};
}

// The sphere's outline on screen as `camera` sees it: its normalised device x and y extents (left, right,
// bottom, top), from the cone of lines of sight that touch it. Seen off the axis a sphere's outline is an
// ellipse, wider than on the axis (by 1/cos^2 of the angle, across).
glm::vec4 outline_extent(const OrbitCamera& camera, const Sphere& sphere, float aspect) {
    const glm::vec3 forward = -eye_offset(camera), right = camera_right(camera), up = camera_up(camera);
    const glm::vec3 eye = camera.target - forward * camera.distance;
    const glm::vec3 to_centre = sphere.center - eye;
    const float distance = glm::length(to_centre);
    const float tan_half_y = std::tan(glm::radians(camera.fov_y_deg) * 0.5f), tan_half_x = tan_half_y * aspect;
    if (distance <= sphere.radius * 1.0001f) return {-1e9f, 1e9f, -1e9f, 1e9f};  // the eye inside: no outline
    const glm::vec3 u = to_centre / distance;
    const glm::vec3 a = glm::normalize(glm::abs(glm::dot(u, up)) < 0.9f ? glm::cross(u, up) : glm::cross(u, right));
    const glm::vec3 b = glm::cross(u, a);
    const float sin_angle = sphere.radius / distance, cos_angle = std::sqrt(1.0f - sin_angle * sin_angle);
    glm::vec4 e(1e9f, -1e9f, 1e9f, -1e9f);
    constexpr int kSteps = 256;
    for (int k = 0; k < kSteps; ++k) {
        const float phi = 2.0f * std::numbers::pi_v<float> * float(k) / float(kSteps);
        const glm::vec3 d = cos_angle * u + sin_angle * (std::cos(phi) * a + std::sin(phi) * b);
        const float depth = glm::dot(d, forward);
        if (depth <= 1e-6f) return {-1e9f, 1e9f, -1e9f, 1e9f};  // the outline reaches behind the eye
        const float x = glm::dot(d, right) / depth / tan_half_x, y = glm::dot(d, up) / depth / tan_half_y;
        e = {std::min(e.x, x), std::max(e.y, x), std::min(e.z, y), std::max(e.w, y)};
    }
    return e;
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
    float framing = framing_distance(bounds, aspect, camera.fov_y_deg);
    camera.distance = std::clamp(camera.distance * std::pow(kZoomPerStep, steps), framing * 1e-3f, framing * 1e3f);
}

void frame_all(OrbitCamera& camera, const Sphere& bounds, float aspect, glm::vec2 free) {
    const float share = std::clamp(free.y - free.x, 0.05f, 1.0f);  // a sliver left free frames in a twentieth
    camera.distance = framing_distance(bounds, aspect * share, camera.fov_y_deg);
    // The free columns' middle, in normalised device x; the target moves the other way by as much at its depth
    // (half the view's width there: the distance times tan_half_x).
    const float middle = free.x + free.y - 1.0f;
    const float tan_half_x = std::tan(glm::radians(camera.fov_y_deg) * 0.5f) * aspect;
    camera.target = bounds.center - camera_right(camera) * (middle * camera.distance * tan_half_x);
    // Off the axis the outline is wider than framing_distance assumes, and its middle off the centre's image:
    // a few corrections of the distance and the place (each extent scales nearly as 1/distance).
    for (int step = 0; step < 6; ++step) {
        const glm::vec4 e = outline_extent(camera, bounds, aspect);
        const float fill = std::max((e.y - e.x) / (2.0f * share), (e.w - e.z) / 2.0f);
        if (!(fill > 0.0f && fill < 1e3f)) break;
        camera.distance *= fill;
        camera.target -= camera_right(camera) * ((middle - 0.5f * (e.x + e.y)) * camera.distance * tan_half_x);
    }
}

void frame_at_open(OrbitCamera& camera, const Sphere& bounds, float aspect, glm::vec2 free, float distance_multiple) {
    frame_all(camera, bounds, aspect, free);
    // Farther or nearer along the line through the centre's image: the offset of the target scales with the distance.
    camera.target = bounds.center + (camera.target - bounds.center) * distance_multiple;
    camera.distance *= distance_multiple;
}

glm::vec2 columns_left_free(glm::vec4 rect, glm::vec2 window) {
    if (window.x <= 0.0f || window.y <= 0.0f) return {0.0f, 1.0f};
    const float left = std::clamp(rect.x / window.x, 0.0f, 1.0f), right = std::clamp((rect.x + rect.z) / window.x, 0.0f, 1.0f);
    if (right <= left) return {0.0f, 1.0f};
    const glm::vec2 free = left >= 1.0f - right ? glm::vec2(0.0f, left) : glm::vec2(right, 1.0f);
    return free.y - free.x < 0.25f ? glm::vec2(0.0f, 1.0f) : free;
}

}  // namespace stipple::app
