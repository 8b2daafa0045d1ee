#include "scene/scene.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "core/error.hpp"

namespace stipple {

glm::mat4 Transform::to_matrix() const {
    if (matrix) return *matrix;
    glm::mat4 m = glm::translate(glm::mat4(1.0f), translate);
    m = glm::rotate(m, glm::radians(rotate_deg.z), glm::vec3(0, 0, 1));
    m = glm::rotate(m, glm::radians(rotate_deg.y), glm::vec3(0, 1, 0));
    m = glm::rotate(m, glm::radians(rotate_deg.x), glm::vec3(1, 0, 0));
    return glm::scale(m, scale * axis_scale);
}

bool Transform::mirrors() const { return glm::determinant(glm::dmat3(to_matrix())) < 0.0; }

glm::mat4 Transform::drawing_matrix() const {
    const glm::mat4 m = to_matrix();
    return mirrors() ? m * glm::mat4(glm::vec4(-1, 0, 0, 0), glm::vec4(0, -1, 0, 0), glm::vec4(0, 0, -1, 0), glm::vec4(0, 0, 0, 1))
                     : m;
}

std::string Scene::model_path(size_t object) const {
    std::filesystem::path path = objects.at(object).model;
    if (path.is_absolute() || base_dir.empty()) return path.string();
    return (base_dir / path).lexically_normal().string();
}

bool is_scene_file(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".json";
}

Sphere transform_sphere(const Sphere& sphere, const glm::mat4& model) {
    // The longest image of a unit axis bounds how much the linear part can stretch the radius.
    glm::mat3 linear(model);
    float stretch = std::max({glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2])});
    return {glm::vec3(model * glm::vec4(sphere.center, 1.0f)), sphere.radius * stretch};
}

Sphere merge_spheres(const Sphere& a, const Sphere& b) {
    glm::vec3 d = b.center - a.center;
    float dist = glm::length(d);
    if (dist + b.radius <= a.radius) return a;
    if (dist + a.radius <= b.radius) return b;
    float radius = 0.5f * (dist + a.radius + b.radius);
    glm::vec3 center = a.center + d * ((radius - a.radius) / std::max(dist, 1e-30f));
    return {center, radius};
}

Sphere enclosing_sphere(std::span<const Sphere> spheres) {
    if (spheres.empty()) return {};
    // Merged one after another, a sphere depends on the order and grows loose with many (a grid of 200
    // objects was framed 22% too large, its centre far off the grid's). Instead: from the centre of the
    // spheres' box, steps toward the farthest sphere's far side by shrinking fractions (Badoiu-Clarkson),
    // kept only where they enclose them more tightly than the sequential merge.
    const auto radius_about = [&](glm::vec3 c) {
        float r = 0.0f;
        for (const Sphere& s : spheres) r = std::max(r, glm::length(s.center - c) + s.radius);
        return r;
    };
    Sphere merged = spheres[0];
    glm::vec3 low(INFINITY), high(-INFINITY);
    for (const Sphere& s : spheres) {
        merged = merge_spheres(merged, s);
        low = glm::min(low, s.center - s.radius), high = glm::max(high, s.center + s.radius);
    }
    glm::vec3 c = 0.5f * (low + high);
    Sphere best{c, radius_about(c)};
    for (int step = 1; step <= 64 && spheres.size() > 1; ++step) {
        const Sphere* far = &spheres[0];
        float far_reach = -1.0f;
        for (const Sphere& s : spheres)
            if (const float reach = glm::length(s.center - c) + s.radius; reach > far_reach) far_reach = reach, far = &s;
        const glm::vec3 away = far->center - c;
        const float d = glm::length(away);
        const glm::vec3 far_point = d > 0.0f ? far->center + away * (far->radius / d) : far->center;
        c += (far_point - c) / float(step + 1);
        if (const float r = radius_about(c); r < best.radius) best = {c, r};
    }
    return best.radius < merged.radius ? best : merged;
}

Transform placement_beside(const Sphere& scene_bounds, const Sphere& sphere, float reference_radius) {
    Transform t;
    // Models come in any unit (the bunny is 0.1 wide, scanned statues 100s); a common radius keeps
    // a dropped model visible next to the others. A scene file can set any scale it likes.
    t.scale = sphere.radius > 0.0f ? reference_radius / sphere.radius : 1.0f;
    float gap = 0.25f * reference_radius;
    glm::vec3 where = scene_bounds.center + glm::vec3(scene_bounds.radius + gap + reference_radius, 0.0f, 0.0f);
    t.translate = where - sphere.center * t.scale;
    return t;
}

void arrange_side_by_side(Scene& scene, const std::vector<Sphere>& spheres) {
    STIPPLE_CHECK(scene.objects.size() == spheres.size(), "one bounding sphere per object");
    Sphere bounds{};
    for (size_t i = 0; i < spheres.size(); ++i) {
        if (i > 0) scene.objects[i].transform = placement_beside(bounds, spheres[i], spheres[0].radius);
        Sphere placed = transform_sphere(spheres[i], scene.objects[i].transform.to_matrix());
        bounds = i == 0 ? placed : merge_spheres(bounds, placed);
    }
}

OrbitCamera resolve_camera(const SceneCamera& camera, const Sphere& scene_bounds, float aspect) {
    OrbitCamera orbit;
    orbit.fov_y_deg = camera.fov_y_deg;
    orbit.orthographic = camera.orthographic;
    orbit.target = camera.target.value_or(scene_bounds.center);
    orbit.distance = camera.world_distance.value_or(
        framing_distance(scene_bounds, aspect, camera.fov_y_deg, camera.orthographic) * camera.distance);
    orbit.yaw_deg = camera.yaw_deg;
    orbit.pitch_deg = camera.pitch_deg;
    return orbit;
}

SceneCamera scene_camera_from(const OrbitCamera& camera) {
    SceneCamera c;
    c.yaw_deg = camera.yaw_deg;
    c.pitch_deg = camera.pitch_deg;
    c.world_distance = camera.distance;
    c.target = camera.target;
    c.fov_y_deg = camera.fov_y_deg;
    c.orthographic = camera.orthographic;
    return c;
}

}  // namespace stipple
