#include "anim/procedural_rigs.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "core/error.hpp"

namespace stipple::anim::rigs {

namespace {

using nlohmann::json;

constexpr double kPi = 3.14159265358979323846;

void append(std::vector<float>& out, const glm::vec3& v) { out.insert(out.end(), {v.x, v.y, v.z}); }
void append(std::vector<float>& out, const glm::quat& q) { out.insert(out.end(), {q.x, q.y, q.z, q.w}); }
void append(std::vector<float>& out, const glm::mat4& m) { out.insert(out.end(), glm::value_ptr(m), glm::value_ptr(m) + 16); }

glm::quat about(const glm::vec3& axis, double degrees) {
    return glm::quat(glm::angleAxis(static_cast<float>(degrees * kPi / 180.0), axis));
}

// A sampler (and its accessors) from key times and the values per key, returning its index in `samplers`.
int add_sampler(GltfBuilder& b, json& samplers, const std::vector<float>& times, const std::vector<float>& values,
                const std::string& value_type, const std::string& interpolation) {
    const int input = b.add_floats(times, "SCALAR");
    const int output = b.add_floats(values, value_type);
    samplers.push_back({{"input", input}, {"output", output}, {"interpolation", interpolation}});
    return static_cast<int>(samplers.size() - 1);
}

json channel(int sampler, int node, const char* path) { return {{"sampler", sampler}, {"target", {{"node", node}, {"path", path}}}}; }

}  // namespace

float cylinder_elbow_weight(float y) { return std::clamp((y - 0.75f) / 0.5f, 0.0f, 1.0f); }

GltfBuilder bending_cylinder(const CylinderOptions& o) {
    if (o.rings < 1 || o.segments < 3) fail("bending_cylinder: needs at least 1 ring and 3 segments");
    const uint32_t ring_vertices = o.segments;
    std::vector<float> positions, weights;
    std::vector<uint16_t> joints;
    std::vector<uint32_t> indices;
    auto add_vertex = [&](const glm::vec3& p) {
        append(positions, p);
        const float w = cylinder_elbow_weight(p.y);
        weights.insert(weights.end(), {1.0f - w, w, 0.0f, 0.0f});
        joints.insert(joints.end(), {0, 1, 0, 0});
    };
    for (uint32_t r = 0; r <= o.rings; ++r)
        for (uint32_t s = 0; s < o.segments; ++s) {
            const double a = 2.0 * kPi * s / o.segments;
            add_vertex(glm::vec3(o.radius * std::cos(a), 2.0 * r / o.rings, o.radius * std::sin(a)));
        }
    // Angle grows from +x towards +z, so (ring up, around) is the outward order.
    for (uint32_t r = 0; r < o.rings; ++r)
        for (uint32_t s = 0; s < o.segments; ++s) {
            const uint32_t a = r * ring_vertices + s, b = r * ring_vertices + (s + 1) % o.segments;
            const uint32_t c = b + ring_vertices, d = a + ring_vertices;
            indices.insert(indices.end(), {a, d, c, a, c, b});
        }
    const uint32_t bottom = static_cast<uint32_t>(positions.size() / 3);
    add_vertex(glm::vec3(0.0f));
    const uint32_t top = bottom + 1;
    add_vertex(glm::vec3(0.0f, 2.0f, 0.0f));
    for (uint32_t s = 0; s < o.segments; ++s) {
        const uint32_t next = (s + 1) % o.segments;
        indices.insert(indices.end(), {bottom, s, next});
        indices.insert(indices.end(), {top, o.rings * ring_vertices + next, o.rings * ring_vertices + s});
    }

    GltfBuilder b;
    const int position = b.add_floats(positions, "VEC3");
    const int joint = b.add_uint16(joints, "VEC4");
    const int weight = b.add_floats(weights, "VEC4");
    const int index = b.add_uint32(indices, "SCALAR");
    b.add("meshes", {{"name", "tube"},
                     {"primitives", json::array({{{"attributes", {{"POSITION", position}, {"JOINTS_0", joint}, {"WEIGHTS_0", weight}}},
                                                  {"indices", index}}})}});
    const glm::vec3 t = o.mesh_node_translation;
    b.add("nodes", {{"name", "tube"}, {"mesh", 0}, {"skin", 0}, {"translation", {t.x, t.y, t.z}}});
    b.add("nodes", {{"name", "root"}, {"children", {2}}});
    b.add("nodes", {{"name", "elbow"}, {"translation", {0.0, 1.0, 0.0}}});
    std::vector<float> inverse_bind;
    append(inverse_bind, glm::mat4(1.0f));
    append(inverse_bind, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -1.0f, 0.0f)));
    b.add("skins", {{"name", "arm"}, {"joints", {1, 2}}, {"inverseBindMatrices", b.add_floats(inverse_bind, "MAT4")}});
    b.add("scenes", {{"nodes", {0, 1}}});
    b.doc["scene"] = 0;

    json samplers = json::array();
    std::vector<float> bend;
    const glm::quat keys[3] = {glm::quat(1, 0, 0, 0), about(glm::vec3(0, 0, 1), o.bend_degrees), glm::quat(1, 0, 0, 0)};
    const bool cubic = o.interpolation == "CUBICSPLINE";
    for (const glm::quat& q : keys) {
        if (cubic) append(bend, glm::quat(0, 0, 0, 0));
        append(bend, q);
        if (cubic) append(bend, glm::quat(0, 0, 0, 0));
    }
    add_sampler(b, samplers, {0.0f, 1.0f, 2.0f}, bend, "VEC4", o.interpolation);
    b.add("animations", {{"name", "Bend"}, {"samplers", samplers}, {"channels", json::array({channel(0, 2, "rotation")})}});
    json lift = json::array();
    add_sampler(b, lift, {0.0f, 1.0f}, {0, 0, 0, 0, 1, 0}, "VEC3", "LINEAR");
    b.add("animations", {{"name", "Lift"}, {"samplers", lift}, {"channels", json::array({channel(0, 1, "translation")})}});
    return b;
}

GltfBuilder node_animated_box() {
    std::vector<float> positions, normals;
    std::vector<uint16_t> indices;
    // Each face: its normal n and two in-plane axes u, v with u x v = n, so corners in (u, v) order wind outward.
    const glm::vec3 faces[6][3] = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},   {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
                                   {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}},   {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
                                   {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},   {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}}};
    for (const auto& f : faces) {
        const uint16_t base = static_cast<uint16_t>(positions.size() / 3);
        const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (const auto& c : corners) {
            append(positions, 0.5f * (f[0] + c[0] * f[1] + c[1] * f[2]));
            append(normals, f[0]);
        }
        indices.insert(indices.end(), {base, uint16_t(base + 1), uint16_t(base + 2), base, uint16_t(base + 2), uint16_t(base + 3)});
    }
    GltfBuilder b;
    const int position = b.add_floats(positions, "VEC3");
    const int normal = b.add_floats(normals, "VEC3");
    const int index = b.add_uint16(indices, "SCALAR");
    const json primitive = {{"attributes", {{"POSITION", position}, {"NORMAL", normal}}}, {"indices", index}};
    b.add("meshes", {{"name", "cube"}, {"primitives", json::array({primitive})}});
    b.add("nodes", {{"name", "holder"}, {"translation", {0.0, 0.0, -3.0}}, {"children", {1}}});
    b.add("nodes", {{"name", "box"}, {"mesh", 0}});
    b.add("scenes", {{"nodes", {0}}});
    json samplers = json::array();
    add_sampler(b, samplers, {0.0f, 2.0f}, {0, 0, 0, 2, 0, 0}, "VEC3", "LINEAR");
    std::vector<float> rotations;
    for (double degrees : {0.0, 90.0, 180.0}) append(rotations, about(glm::vec3(0, 1, 0), degrees));
    add_sampler(b, samplers, {0.0f, 1.0f, 2.0f}, rotations, "VEC4", "LINEAR");
    add_sampler(b, samplers, {0.0f, 2.0f}, {1, 1, 1, 1, 3, 1}, "VEC3", "LINEAR");
    b.add("animations", {{"name", "Move"},
                         {"samplers", samplers},
                         {"channels", json::array({channel(0, 1, "translation"), channel(1, 1, "rotation"), channel(2, 1, "scale")})}});
    return b;
}

GltfBuilder morphed_quad() {
    GltfBuilder b;
    const int position = b.add_floats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, "VEC3");
    const int normal = b.add_floats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3");
    const int index = b.add_uint16({0, 1, 2, 0, 2, 3}, "SCALAR");
    const int lift_position = b.add_floats({0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0}, "VEC3");
    const int lift_normal = b.add_floats({0.5f, 0, 0, 0.5f, 0, 0, 0.5f, 0, 0, 0.5f, 0, 0}, "VEC3");
    const int raise_position = b.add_floats({0, 0, 0.5f, 0, 0, 0.5f, 0, 0, 0.5f, 0, 0, 0.5f}, "VEC3");
    json primitive = {{"attributes", {{"POSITION", position}, {"NORMAL", normal}}},
                      {"indices", index},
                      {"targets", json::array({{{"POSITION", lift_position}, {"NORMAL", lift_normal}}, {{"POSITION", raise_position}}})}};
    b.add("meshes", {{"name", "sheet"}, {"primitives", json::array({primitive})}, {"weights", {0.5, 0.5}},
                     {"extras", {{"targetNames", {"lift", "raise"}}}}});
    b.add("nodes", {{"name", "sheet"}, {"mesh", 0}, {"translation", {1.0, 2.0, 3.0}}, {"weights", {0.25, 0.0}}});
    b.add("scenes", {{"nodes", {0}}});
    json samplers = json::array();
    add_sampler(b, samplers, {0.0f, 1.0f, 2.0f}, {0, 0, 1, 0.5f, 0, 1}, "SCALAR", "LINEAR");
    b.add("animations", {{"name", "Morph"}, {"samplers", samplers}, {"channels", json::array({channel(0, 0, "weights")})}});
    return b;
}

glm::quat key_rotation(int key) {
    const double degrees[3] = {0.0, 90.0, 170.0};
    const glm::quat q = about(glm::vec3(0, 1, 0), degrees[key]);
    return key == 2 ? -q : q;
}

GltfBuilder interpolation_sample(const std::string& interpolation) {
    GltfBuilder b;
    const int position = b.add_floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
    b.add("meshes", {{"name", "tri"}, {"primitives", json::array({{{"attributes", {{"POSITION", position}}}}})}});
    b.add("nodes", {{"name", "mover"}, {"mesh", 0}});
    b.add("scenes", {{"nodes", {0}}});
    const bool cubic = interpolation == "CUBICSPLINE";
    std::vector<float> translations, rotations;
    for (int k = 0; k < 3; ++k) {
        if (cubic) append(translations, glm::make_vec3(kKeyInTangents[k]));
        append(translations, glm::make_vec3(kKeyTranslations[k]));
        if (cubic) append(translations, glm::make_vec3(kKeyOutTangents[k]));
        if (cubic) append(rotations, glm::quat(0, 0, 0, 0));
        append(rotations, key_rotation(k));
        if (cubic) append(rotations, glm::quat(0, 0, 0, 0));
    }
    const std::vector<float> times(std::begin(kKeyTimes), std::end(kKeyTimes));
    json samplers = json::array();
    add_sampler(b, samplers, times, translations, "VEC3", interpolation);
    add_sampler(b, samplers, times, rotations, "VEC4", interpolation);
    const json channels = json::array({channel(0, 0, "translation"), channel(1, 0, "rotation")});
    b.add("animations", {{"name", "Keys"}, {"samplers", samplers}, {"channels", channels}});
    return b;
}

GltfBuilder stretching_plane(uint32_t cells) {
    if (cells < 1) fail("stretching_plane: needs at least one cell");
    std::vector<float> positions, normals, weights;
    std::vector<uint16_t> joints;
    std::vector<uint32_t> indices;
    for (uint32_t j = 0; j <= cells; ++j)
        for (uint32_t i = 0; i <= cells; ++i) {
            const float x = float(i) / cells, y = float(j) / cells;
            append(positions, glm::vec3(x, y, 0.0f));
            append(normals, glm::vec3(0.0f, 0.0f, 1.0f));
            weights.insert(weights.end(), {1.0f - x, x, 0.0f, 0.0f});
            joints.insert(joints.end(), {0, 1, 0, 0});
        }
    for (uint32_t j = 0; j < cells; ++j)
        for (uint32_t i = 0; i < cells; ++i) {
            const uint32_t a = j * (cells + 1) + i, b = a + 1, c = b + cells + 1, d = a + cells + 1;
            indices.insert(indices.end(), {a, b, c, a, c, d});
        }
    GltfBuilder b;
    const int position = b.add_floats(positions, "VEC3");
    const int normal = b.add_floats(normals, "VEC3");
    const int joint = b.add_uint16(joints, "VEC4");
    const int weight = b.add_floats(weights, "VEC4");
    const int index = b.add_uint32(indices, "SCALAR");
    const json attributes = {{"POSITION", position}, {"NORMAL", normal}, {"JOINTS_0", joint}, {"WEIGHTS_0", weight}};
    b.add("meshes", {{"name", "sheet"}, {"primitives", json::array({{{"attributes", attributes}, {"indices", index}}})}});
    b.add("nodes", {{"name", "sheet"}, {"mesh", 0}, {"skin", 0}});
    b.add("nodes", {{"name", "left"}});
    b.add("nodes", {{"name", "right"}, {"translation", {1.0, 0.0, 0.0}}});
    std::vector<float> inverse_bind;
    append(inverse_bind, glm::mat4(1.0f));
    append(inverse_bind, glm::translate(glm::mat4(1.0f), glm::vec3(-1.0f, 0.0f, 0.0f)));
    b.add("skins", {{"joints", {1, 2}}, {"inverseBindMatrices", b.add_floats(inverse_bind, "MAT4")}});
    b.add("scenes", {{"nodes", {0, 1, 2}}});
    json samplers = json::array();
    add_sampler(b, samplers, {0.0f, 1.0f}, {1, 0, 0, 2, 0, 0}, "VEC3", "LINEAR");
    b.add("animations", {{"name", "Stretch"}, {"samplers", samplers}, {"channels", json::array({channel(0, 2, "translation")})}});
    return b;
}

float eight_joint_weight(float x, int joint) {
    auto raw = [x](int k) { return 1.0f / ((1.0f + 7.0f * std::abs(x - k / 7.0f)) * (1.0f + 7.0f * std::abs(x - k / 7.0f))); };
    float sum = 0.0f;
    for (int k = 0; k < 8; ++k) sum += raw(k);
    return raw(joint) / sum;
}

GltfBuilder eight_joint_sheet(uint32_t cells) {
    if (cells < 1) fail("eight_joint_sheet: needs at least one cell");
    std::vector<float> positions, normals, weights0, weights1;
    std::vector<uint16_t> joints0;
    std::vector<uint8_t> joints1;
    std::vector<uint32_t> indices;
    for (uint32_t j = 0; j <= 1; ++j)
        for (uint32_t i = 0; i <= cells; ++i) {
            const float x = float(i) / cells;
            append(positions, glm::vec3(x, 0.2f * j, 0.0f));
            append(normals, glm::vec3(0.0f, 0.0f, 1.0f));
            for (int k = 0; k < 4; ++k) weights0.push_back(eight_joint_weight(x, k)), joints0.push_back(uint16_t(k));
            for (int k = 4; k < 8; ++k) weights1.push_back(eight_joint_weight(x, k)), joints1.push_back(uint8_t(k));
        }
    for (uint32_t i = 0; i < cells; ++i) {
        const uint32_t a = i, b = i + 1, c = b + cells + 1, d = a + cells + 1;
        indices.insert(indices.end(), {a, b, c, a, c, d});
    }
    GltfBuilder b;
    const json attributes = {{"POSITION", b.add_floats(positions, "VEC3")}, {"NORMAL", b.add_floats(normals, "VEC3")},
                             {"JOINTS_0", b.add_uint16(joints0, "VEC4")},  {"WEIGHTS_0", b.add_floats(weights0, "VEC4")},
                             {"JOINTS_1", b.add_uint8(joints1, "VEC4")},   {"WEIGHTS_1", b.add_floats(weights1, "VEC4")}};
    const int index = b.add_uint32(indices, "SCALAR");
    b.add("meshes", {{"name", "strip"}, {"primitives", json::array({{{"attributes", attributes}, {"indices", index}}})}});
    b.add("nodes", {{"name", "strip"}, {"mesh", 0}, {"skin", 0}});
    std::vector<float> inverse_bind;
    json joint_nodes = json::array(), scene_nodes = json::array({0}), samplers = json::array(), channels = json::array();
    for (int k = 0; k < 8; ++k) {
        const float x = k / 7.0f;
        const int node = b.add("nodes", {{"name", "joint" + std::to_string(k)}, {"translation", {x, 0.0f, 0.0f}}});
        joint_nodes.push_back(node);
        scene_nodes.push_back(node);
        append(inverse_bind, glm::translate(glm::mat4(1.0f), glm::vec3(-x, 0.0f, 0.0f)));
        const int sampler = add_sampler(b, samplers, {0.0f, 1.0f}, {x, 0.0f, 0.0f, x, 0.1f * k, 0.0f}, "VEC3", "LINEAR");
        channels.push_back(channel(sampler, node, "translation"));
    }
    b.add("skins", {{"joints", joint_nodes}, {"inverseBindMatrices", b.add_floats(inverse_bind, "MAT4")}});
    b.add("scenes", {{"nodes", scene_nodes}});
    b.add("animations", {{"name", "Wave"}, {"samplers", samplers}, {"channels", channels}});
    return b;
}

}  // namespace stipple::anim::rigs
