#include "core/unit_direction.hpp"
#include "scene/scene_json.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "core/utf8.hpp"
#include "core/printf_string.hpp"
#include "mesh/loader_util.hpp"
#include "mesh/mesh.hpp"
#include "params/param_table.hpp"

namespace stipple {

// ordered_json keeps the file's field order (the first unknown field is the one reported) and writes
// fields in a readable order.
using json = nlohmann::ordered_json;

namespace {

// Floats are written in their shortest form that reads back to the same float ("0.15", not
// "0.15000000596046448"), so saved scenes stay readable and round trips stay exact.
json number(float value) {
    char text[32];
    auto result = std::to_chars(text, text + sizeof(text), value);
    return json(std::strtod(std::string(text, result.ptr).c_str(), nullptr));
}

json vec3_json(const glm::vec3& v) { return json::array({number(v.x), number(v.y), number(v.z)}); }

// Reads with a JSON-pointer-like location ("objects[1].params.dmax") for every message.
class Reader {
public:
    explicit Reader(std::string source) : source_(std::move(source)) {}

    [[noreturn]] void error(const std::string& where, const std::string& problem) const {
        // Field names come from the file: a control character in one ("o\bj") must not break the line.
        fail_file(source_, one_line((where.empty() ? std::string() : where + ": ") + problem));
    }

    static std::string field(const std::string& where, const std::string& key) {
        return where.empty() ? key : where + "." + key;
    }

    void expect_object(const json& j, const std::string& where, const std::vector<std::string>& allowed) const {
        if (!j.is_object()) error(where, std::string("expected an object, got ") + j.type_name());
        for (const auto& [key, value] : j.items()) {
            if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
            std::string list;
            for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
            // Cut short: a key of a megabyte made a message of a megabyte.
            const std::string shown = key.size() > 64 ? key.substr(0, 60) + "..." : key;
            error(field(where, shown), "unknown field (expected one of: " + list + ")");
        }
    }

    float number(const json& j, const std::string& where) const { return float(real(j, where)); }

    // The number as the file gives it, within single precision's range, not yet rounded to it: a parameter's
    // range check tells a value that rounds to 0 from 0 (1e-46 was taken for D_max 0, which --dmax refuses). A
    // literal beyond a double (1e-400) still reads as 0: the parser keeps no text of its numbers.
    double real(const json& j, const std::string& where) const {
        if (!j.is_number()) error(where, std::string("expected a number, got ") + j.type_name());
        double v = j.get<double>();
        // JSON has no infinity or NaN: what fails here is finite but beyond a float (as the command line says it).
        if (!std::isfinite(v) || std::abs(v) > double(std::numeric_limits<float>::max())) {
            char text[64];
            std::snprintf(text, sizeof text, "%g", v);
            error(where, std::string(text) + " is beyond single precision (3.4e+38)");
        }
        return v;
    }

    uint64_t unsigned_integer(const json& j, const std::string& where) const {
        if (j.is_number_unsigned()) return j.get<uint64_t>();
        if (j.is_number_integer()) error(where, std::to_string(j.get<int64_t>()) + " is out of range: it must be >= 0");
        error(where, std::string("expected an integer, got ") + (j.is_number() ? "a non-integer number" : j.type_name()));
    }

    bool boolean(const json& j, const std::string& where) const {
        if (!j.is_boolean()) error(where, std::string("expected true or false, got ") + j.type_name());
        return j.get<bool>();
    }

    std::string string(const json& j, const std::string& where) const {
        if (!j.is_string()) error(where, std::string("expected a string, got ") + j.type_name());
        return j.get<std::string>();
    }

    glm::vec3 vec3(const json& j, const std::string& where) const {
        if (!j.is_array() || j.size() != 3) error(where, "expected an array of 3 numbers");
        return {number(j[0], where + "[0]"), number(j[1], where + "[1]"), number(j[2], where + "[2]")};
    }

    static constexpr float kMinWorldDistance = 1e-21f, kMaxWorldDistance = 1e24f;

    // A place in the world: within the coordinates drawing allows (a translation of 3e38 overflowed the
    // scene's bounds and drew a blank frame with exit status 0).
    glm::vec3 place(const json& j, const std::string& where) const {
        const glm::vec3 p = vec3(j, where);
        for (int i = 0; i < 3; ++i)
            if (std::abs(p[i]) > kMaxCoordinate)
                error(where, printf_string("components must be within -%g..%g (the coordinates drawing allows)",
                                           double(kMaxCoordinate), double(kMaxCoordinate)));
        return p;
    }

    glm::vec3 color(const json& j, const std::string& where) const {
        glm::vec3 c = vec3(j, where);
        for (int i = 0; i < 3; ++i)
            if (c[i] < 0.0f || c[i] > 1.0f) error(where, "colour components must be in 0..1");
        return c;
    }

private:
    std::string source_;
};

// Parameters by the table (src/params/param_table.hpp): each key read as its type, checked against its
// range with the table's wording, so a scene file and the command line reject the same values alike.
double read_param_value(const ParamSpec& spec, const json& j, const Reader& r, const std::string& where) {
    double value = 0.0;
    switch (spec.type) {
        case ParamType::Bool: return r.boolean(j, where) ? 1.0 : 0.0;
        case ParamType::Choice: {
            const std::string name = r.string(j, where);
            for (size_t i = 0; i < spec.choices.size(); ++i)
                if (name == spec.choices[i]) return double(i);
            r.error(where, "'" + name + "' is " + param_value_problem(spec, -1.0).value_or("not accepted"));
        }
        case ParamType::Int:
            if (!j.is_number()) r.error(where, std::string("expected an integer, got ") + j.type_name());
            value = j.get<double>();
            break;
        case ParamType::Float: value = r.real(j, where); break;
    }
    if (auto problem = param_value_problem(spec, value)) r.error(where, *problem);
    return value;
}

json param_json(const ParamSpec& spec, double value) {
    switch (spec.type) {
        case ParamType::Bool: return json(value != 0.0);
        case ParamType::Choice: return json(format_param_value(spec, value));
        case ParamType::Int: return json(uint64_t(value));
        case ParamType::Float: break;
    }
    return number(float(value));
}

ObjectParams read_params(const json& j, const Reader& r, const std::string& where) {
    r.expect_object(j, where, scene_param_names());
    ObjectParams params;
    for (const ParamSpec& spec : param_table())
        for (const char* key : spec.alias_of)
            if (j.contains(spec.key) && j.contains(key))
                r.error(Reader::field(where, spec.key), std::string("sets ") + key + " too: give one or the other, not both");
    for (const ParamSpec& spec : param_table())
        if (j.contains(spec.key)) spec.set(params, read_param_value(spec, j[spec.key], r, Reader::field(where, spec.key)));
    try {
        validate_params(params);  // any rule that spans fields
    } catch (const Error& e) {
        r.error(where, e.what());
    }
    return params;
}

Transform read_transform(const json& j, const Reader& r, const std::string& where) {
    r.expect_object(j, where, {"translate", "rotate_deg", "scale", "matrix"});
    Transform t;
    if (j.contains("matrix")) {
        if (j.size() != 1) r.error(where, "\"matrix\" cannot be combined with translate, rotate_deg or scale");
        const json& m = j["matrix"];
        std::string w = Reader::field(where, "matrix");
        if (!m.is_array() || m.size() != 16) r.error(w, "expected an array of 16 numbers (column-major)");
        glm::mat4 matrix;
        for (int i = 0; i < 16; ++i) matrix[i / 4][i % 4] = r.number(m[i], w + "[" + std::to_string(i) + "]");
        // Flatness judged relative to the axes' scales, in double (a scale of 1e20 was called singular: its
        // determinant overflowed single precision); then each axis's scale in the same range as "scale".
        const glm::dmat3 axes(matrix);
        const glm::dvec3 lengths(glm::length(axes[0]), glm::length(axes[1]), glm::length(axes[2]));
        if (!(std::abs(glm::determinant(axes)) > 1e-6 * lengths.x * lengths.y * lengths.z))
            r.error(w, "the matrix is singular (it flattens the object)");
        // A mirroring matrix (negative determinant) is drawn with the model reflected and re-wound
        // (Transform::drawing_matrix).
        for (int c = 0; c < 3; ++c) {
            if (!(lengths[c] >= 1e-6 && lengths[c] <= 1e6)) {
                r.error(w, "column " + std::to_string(c) + " scales its axis by " + printf_string("%g", lengths[c]) +
                               ": each axis must scale by 1e-6 to 1e6, as \"scale\" does");
            }
        }
        if (matrix[0][3] != 0.0f || matrix[1][3] != 0.0f || matrix[2][3] != 0.0f || matrix[3][3] != 1.0f)
            r.error(w, "the last row must be 0, 0, 0, 1 (an affine transform)");
        for (int i = 0; i < 3; ++i)
            if (std::abs(matrix[3][i]) > kMaxCoordinate)
                r.error(w, printf_string("the translation (elements 12-14) must be within -%g..%g (the coordinates drawing "
                                         "allows)", double(kMaxCoordinate), double(kMaxCoordinate)));
        t.matrix = matrix;
        return t;
    }
    if (j.contains("translate")) t.translate = r.place(j["translate"], Reader::field(where, "translate"));
    if (j.contains("rotate_deg")) t.rotate_deg = r.vec3(j["rotate_deg"], Reader::field(where, "rotate_deg"));
    if (j.contains("scale") && j["scale"].is_array()) {
        // One scale an axis (a terrain's heights exaggerated: [1, 3, 1]): translate * rotate * scale, whose
        // unequal scales the drawing takes as a scene matrix's (README, "Unequal scales in a scene matrix").
        // A negative one mirrors the object ([-1, 1, 1]: its mirror image across its x = 0 plane).
        const std::string w = Reader::field(where, "scale");
        const glm::vec3 axes = r.vec3(j["scale"], w);
        for (int c = 0; c < 3; ++c)
            if (!(std::abs(axes[c]) >= 1e-6f) || std::abs(axes[c]) > 1e6f)
                r.error(w, std::string("the ") + "xyz"[c] + " axis's scale " + printf_string("%g", double(axes[c])) +
                               " must be in [1e-6, 1e6], or in [-1e6, -1e-6] to mirror that axis");
        t.axis_scale = axes;
        return t;
    }
    if (j.contains("scale")) {
        t.scale = r.number(j["scale"], Reader::field(where, "scale"));
        // Below 1e-6 a model of unit size approaches the denormals its drawing multiplies into (1e-16 drew a
        // black silhouette, 1e-30 nothing).
        if (!(t.scale >= 1e-6f) || t.scale > 1e6f)
            r.error(Reader::field(where, "scale"), t.scale < 0.0f ? "must be in [1e-6, 1e6] (to mirror the object, scale one "
                                                                    "axis: [-1, 1, 1])"
                                                                  : "must be in [1e-6, 1e6]");
    }
    return t;
}

// "animation": {"name": "Walk" (or an index), "start": seconds, "speed": factor, "loop": true}.
AnimationChoice read_animation(const json& j, const Reader& r, const std::string& where) {
    r.expect_object(j, where, {"name", "start", "speed", "loop"});
    AnimationChoice a;
    if (j.contains("name")) {
        const json& name = j["name"];
        const std::string w = Reader::field(where, "name");
        const double index = name.is_number() ? name.get<double>() : -1.0;
        if (name.is_number_unsigned())
            a.name = std::to_string(name.get<uint64_t>());
        else if (index >= 0.0 && index < 0x1p64 && index == std::floor(index))  // 2.0 or 1e19 is whole too
            a.name = std::to_string(static_cast<uint64_t>(index));
        else if (index >= 0x1p64 && std::isfinite(index))
            r.error(w, "animation index " + name.dump() + " is beyond any file's animations");
        else if (name.is_string() && !name.get<std::string>().empty())
            a.name = name.get<std::string>();
        else if (name.is_number())  // -1 or 0.5 said "got number", as if a number were wrong
            r.error(w, "an animation index is a whole number of 0 or more, got " + name.dump());
        else
            r.error(w, std::string("expected an animation name or index, got ") +
                           (name.is_string() ? "an empty string" : name.type_name()));
    }
    if (j.contains("start")) {
        a.start = r.number(j["start"], Reader::field(where, "start"));
        if (std::abs(a.start) > kMaxAnimationSeconds) r.error(Reader::field(where, "start"), "must be in -1e6..1e6 seconds");
    }
    if (j.contains("speed")) {
        a.speed = r.number(j["speed"], Reader::field(where, "speed"));
        if (std::abs(a.speed) > kMaxAnimationSpeed) r.error(Reader::field(where, "speed"), "must be in -1000..1000");
    }
    if (j.contains("loop")) a.loop = r.boolean(j["loop"], Reader::field(where, "loop"));
    return a;
}

json animation_json(const AnimationChoice& a) {
    json j = json::object();
    if (!a.name.empty()) j["name"] = a.name;
    j["start"] = number(float(a.start));
    j["speed"] = number(float(a.speed));
    j["loop"] = a.loop;
    return j;
}

SceneCamera read_camera(const json& j, const Reader& r, const std::string& where) {
    r.expect_object(j, where, {"yaw", "pitch", "distance", "world_distance", "target", "fov_y", "projection"});
    SceneCamera c;
    if (j.contains("yaw")) {
        c.yaw_deg = r.number(j["yaw"], Reader::field(where, "yaw"));
        // As --yaw: a camera path between yaws near the float range overflowed to a blank frame.
        if (std::abs(c.yaw_deg) > 36000.0f) r.error(Reader::field(where, "yaw"), "must be in -36000..36000 degrees");
    }
    if (j.contains("pitch")) {
        c.pitch_deg = r.number(j["pitch"], Reader::field(where, "pitch"));
        if (std::abs(c.pitch_deg) > 90.0f) r.error(Reader::field(where, "pitch"), "must be in -90..90 degrees");
    }
    if (j.contains("distance") && j.contains("world_distance"))
        r.error(where, "give either distance (a multiple of the framing distance) or world_distance, not both");
    if (j.contains("distance")) {
        c.distance = r.number(j["distance"], Reader::field(where, "distance"));
        if (!(c.distance >= 1e-4f) || c.distance > 1e4f) r.error(Reader::field(where, "distance"), "must be in [0.0001, 10000]");
    }
    if (j.contains("world_distance")) {
        float d = r.number(j["world_distance"], Reader::field(where, "world_distance"));
        // Any distance the viewer saves: a model's framing distance (a few times its size, kMinExtent to
        // kMaxCoordinate, up to 115 times its radius at a 1-degree field of view) zoomed by 1e-3..1e3
        // (camera_control.cpp); 3e38 or 1e-38 drew a blank frame.
        if (!(d >= Reader::kMinWorldDistance && d <= Reader::kMaxWorldDistance))
            r.error(Reader::field(where, "world_distance"),
                    printf_string("must be in %g..%g", double(Reader::kMinWorldDistance), double(Reader::kMaxWorldDistance)));
        c.world_distance = d;
    }
    if (j.contains("target")) c.target = r.place(j["target"], Reader::field(where, "target"));
    if (j.contains("fov_y")) {
        c.fov_y_deg = r.number(j["fov_y"], Reader::field(where, "fov_y"));
        if (!(c.fov_y_deg >= 1.0f && c.fov_y_deg <= 150.0f)) r.error(Reader::field(where, "fov_y"), "must be in 1..150 degrees");
    }
    if (j.contains("projection")) {
        const json& p = j["projection"];
        if (!p.is_string() || (p != "perspective" && p != "orthographic"))
            r.error(Reader::field(where, "projection"), "must be \"perspective\" or \"orthographic\"");
        c.orthographic = p == "orthographic";
    }
    return c;
}

json camera_json(const SceneCamera& c) {
    json j = {{"yaw", number(c.yaw_deg)}, {"pitch", number(c.pitch_deg)}};
    if (c.world_distance)
        j["world_distance"] = number(*c.world_distance);
    else
        j["distance"] = number(c.distance);
    if (c.target) j["target"] = vec3_json(*c.target);
    j["fov_y"] = number(c.fov_y_deg);
    if (c.orthographic) j["projection"] = "orthographic";
    return j;
}

// Like dump(2), but arrays of numbers stay on one line ("translate": [0, 1.5, 0]): scene files
// are meant to be read and edited by hand.
void write_pretty(const json& j, int indent, std::string& out) {
    const std::string pad(size_t(indent + 2), ' ');
    if (j.is_object() && !j.empty()) {
        out += "{\n";
        size_t i = 0;
        for (const auto& [key, value] : j.items()) {
            out += pad + json(key).dump() + ": ";
            write_pretty(value, indent + 2, out);
            out += ++i < j.size() ? ",\n" : "\n";
        }
        out += std::string(size_t(indent), ' ') + "}";
    } else if (j.is_array() && !j.empty() && !std::all_of(j.begin(), j.end(), [](const json& e) { return e.is_primitive(); })) {
        out += "[\n";
        for (size_t i = 0; i < j.size(); ++i) {
            out += pad;
            write_pretty(j[i], indent + 2, out);
            out += i + 1 < j.size() ? ",\n" : "\n";
        }
        out += std::string(size_t(indent), ' ') + "]";
    } else if (j.is_array()) {
        out += "[";
        for (size_t i = 0; i < j.size(); ++i) out += (i ? ", " : "") + j[i].dump();
        out += "]";
    } else {
        out += j.dump();
    }
}

// Relative to the scene file when the model is near it (the pair can move together), absolute when
// the relative path would climb far up the tree (a scene saved in /tmp about a model in a checkout).
std::string model_reference(const std::filesystem::path& model, const std::filesystem::path& save_dir) {
    std::filesystem::path relative = model.lexically_relative(std::filesystem::absolute(save_dir).lexically_normal());
    int ups = 0;
    for (const auto& part : relative) ups += part == "..";
    return relative.empty() || ups > 2 ? model.string() : relative.string();
}

}  // namespace

std::vector<std::string> scene_param_names() {
    std::vector<std::string> names;
    for (const ParamSpec& spec : param_table()) names.push_back(spec.key);
    return names;
}

namespace {

// Where the parser is in the document, to name a key that an object repeats: JSON allows a repeated key
// but says nothing of which one counts, and nlohmann's DOM keeps the last silently ("dmax": 20, "dmax":
// 0.1 drew with 0.1; "objects" given twice said "the scene has no objects").
class DuplicateKeys {
public:
    // The parser's callback: records the first repeated key's path and keeps parsing.
    bool operator()(int, json::parse_event_t event, json& parsed) {
        switch (event) {
            case json::parse_event_t::object_start: begin_element(), frames_.push_back({true}); break;
            case json::parse_event_t::array_start: begin_element(), frames_.push_back({false}); break;
            case json::parse_event_t::object_end:
            case json::parse_event_t::array_end: frames_.pop_back(); break;
            case json::parse_event_t::key: {
                Frame& frame = frames_.back();
                frame.key = parsed.get<std::string>();
                if (!frame.keys.insert(frame.key).second && duplicate_.empty()) duplicate_ = path();
                break;
            }
            case json::parse_event_t::value: begin_element(); break;
        }
        return true;
    }
    const std::string& duplicate() const { return duplicate_; }

private:
    struct Frame {
        bool object;
        std::set<std::string> keys;
        std::string key;  // an object's current key
        size_t next = 0;  // an array's next element
        size_t index = 0;  // an array's current element
    };
    // A value, object or array starts: in an array, it is the next element.
    void begin_element() {
        if (!frames_.empty() && !frames_.back().object) frames_.back().index = frames_.back().next++;
    }
    std::string path() const {
        std::string out;
        for (const Frame& f : frames_)
            out += f.object ? (out.empty() ? "" : ".") + f.key : "[" + std::to_string(f.index) + "]";
        return out;
    }
    std::vector<Frame> frames_;
    std::string duplicate_;
};

}  // namespace

Scene parse_scene(const std::string& text, const std::string& source, const std::filesystem::path& base_dir) {
    Reader r(source);
    json root;
    DuplicateKeys duplicates;
    try {
        root = json::parse(text, std::ref(duplicates));
        if (!duplicates.duplicate().empty()) r.error(duplicates.duplicate(), "the field is given twice (give it once)");
    } catch (const json::exception& e) {  // parse_error, and out_of_range for a number like 1e390
        std::string message = e.what();
        if (size_t bracket = message.find("] "); message.rfind("[json.exception", 0) == 0 && bracket != std::string::npos)
            message = message.substr(bracket + 2);  // drop nlohmann's "[json.exception.parse_error.101] "
        for (char& c : message)
            if (c == '\n' || c == '\r') c = ' ';
        r.error("", "not valid JSON: " + message);
    }
    r.expect_object(root, "", {"objects", "camera", "camera_path", "light", "paper", "ink", "paused"});
    Scene scene;
    scene.source = source;
    scene.base_dir = base_dir;
    if (!root.contains("objects")) r.error("objects", "required field is missing");
    const json& objects = root["objects"];
    if (!objects.is_array()) r.error("objects", std::string("expected an array, got ") + objects.type_name());
    if (objects.empty()) r.error("objects", "the scene has no objects (at least one is needed)");
    for (size_t i = 0; i < objects.size(); ++i) {
        std::string where = "objects[" + std::to_string(i) + "]";
        const json& o = objects[i];
        r.expect_object(o, where, {"model", "transform", "params", "animation", "ink"});
        SceneObject object;
        if (!o.contains("model")) r.error(Reader::field(where, "model"), "required field is missing");
        object.model = r.string(o["model"], Reader::field(where, "model"));
        if (object.model.empty()) r.error(Reader::field(where, "model"), "the model path is empty");
        if (o.contains("transform")) object.transform = read_transform(o["transform"], r, Reader::field(where, "transform"));
        if (o.contains("params")) object.params = read_params(o["params"], r, Reader::field(where, "params"));
        if (o.contains("ink")) object.params.ink = r.color(o["ink"], Reader::field(where, "ink"));
        if (o.contains("animation"))
            object.animation = read_animation(o["animation"], r, Reader::field(where, "animation"));
        scene.objects.push_back(std::move(object));
    }
    if (root.contains("camera")) scene.camera = read_camera(root["camera"], r, "camera");
    if (root.contains("camera_path")) {
        const json& path = root["camera_path"];
        if (!path.is_array() || path.empty()) r.error("camera_path", "expected a non-empty array of cameras");
        for (size_t i = 0; i < path.size(); ++i)
            scene.camera_path.push_back(read_camera(path[i], r, "camera_path[" + std::to_string(i) + "]"));
    }
    if (root.contains("light")) {
        scene.light = r.vec3(root["light"], "light");  // as written (a saved scene reads back the same)
        if (!unit_direction(scene.light)) r.error("light", "the light direction must not be the zero vector");
    }
    if (root.contains("paper")) scene.paper = r.color(root["paper"], "paper");
    if (root.contains("ink")) scene.ink = r.color(root["ink"], "ink");
    if (root.contains("paused")) scene.paused = r.boolean(root["paused"], "paused");
    return scene;
}

// Far beyond any scene written by hand or by the viewer (a camera path of 10,000 keys is about 2 MiB).
constexpr uintmax_t kMaxSceneFileBytes = uintmax_t(64) << 20;

Scene load_scene(const std::string& path) {
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (std::filesystem::is_directory(status)) fail_file(path, "is a directory, not a scene file");
    // Not opened otherwise: a FIFO would wait for a writer forever.
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) fail_file(path, "is not a regular file");
    // A scene is a few KiB of JSON that names its models: one of many MiB is not a scene, and is not read whole.
    if (const uintmax_t size = std::filesystem::file_size(path, ec); !ec && size > kMaxSceneFileBytes)
        fail_file(path, "is " + byte_size(size) + ": a scene file is at most " + byte_size(kMaxSceneFileBytes) +
                            " (it names its models; it does not hold them)");
    std::ifstream in(path, std::ios::binary);
    if (!in) fail_file(path, "cannot open the scene file (missing or unreadable)");
    std::stringstream text;
    text << in.rdbuf();
    std::filesystem::path base = std::filesystem::absolute(path).parent_path();
    Scene scene = parse_scene(text.str(), path, base);
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        std::string model = scene.model_path(i);
        const std::filesystem::file_status model_status = std::filesystem::status(model, ec);
        const std::string field = "objects[" + std::to_string(i) + "].model: ";
        if (!std::filesystem::exists(model_status)) fail_file(path, field + "no such model file: " + model);
        if (std::filesystem::is_directory(model_status)) fail_file(path, field + model + " is a directory, not a model file");
        if (!std::filesystem::is_regular_file(model_status)) fail_file(path, field + model + " is not a regular file");
    }
    return scene;
}

std::string scene_to_json(const Scene& scene, const std::filesystem::path& save_dir) {
    json objects = json::array();
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& o = scene.objects[i];
        std::filesystem::path model = std::filesystem::absolute(scene.model_path(i)).lexically_normal();
        const std::string reference = model_reference(model, save_dir);
        // JSON text is UTF-8: a file name that is not (a Latin-1 name) cannot be written into a scene.
        if (!is_valid_utf8(reference))
            fail_file(reference, "objects[" + std::to_string(i) +
                                     "].model: the path is not UTF-8, so a scene file cannot name it (rename the file)");
        json object = {{"model", reference}};
        if (o.transform.matrix) {
            json m = json::array();
            for (int k = 0; k < 16; ++k) m.push_back(number((*o.transform.matrix)[k / 4][k % 4]));
            object["transform"] = {{"matrix", m}};
        } else {
            object["transform"] = {{"translate", vec3_json(o.transform.translate)},
                                   {"rotate_deg", vec3_json(o.transform.rotate_deg)},
                                   {"scale", number(o.transform.scale)}};
            if (o.transform.axis_scale != glm::vec3(1.0f))  // written as read, the panel's uniform scale times it
                object["transform"]["scale"] = vec3_json(o.transform.scale * o.transform.axis_scale);
        }
        json params = json::object();
        for (const ParamSpec& spec : param_table())
            if (!spec.alias) params[spec.key] = param_json(spec, spec.get(o.params));
        object["params"] = params;
        if (!o.animation.is_default()) object["animation"] = animation_json(o.animation);
        if (o.params.ink) object["ink"] = vec3_json(*o.params.ink);
        objects.push_back(object);
    }
    json root = {{"objects", objects}, {"camera", camera_json(scene.camera)}};
    if (!scene.camera_path.empty()) {
        json path = json::array();
        for (const SceneCamera& c : scene.camera_path) path.push_back(camera_json(c));
        root["camera_path"] = path;
    }
    root["light"] = vec3_json(scene.light);
    root["paper"] = vec3_json(scene.paper);
    root["ink"] = vec3_json(scene.ink);
    if (scene.paused) root["paused"] = true;
    std::string text;
    write_pretty(root, 0, text);
    return text + "\n";
}

void save_scene(const std::string& path, const Scene& scene) {
    std::filesystem::path file = std::filesystem::absolute(path);
    std::error_code ec;
    std::filesystem::create_directories(file.parent_path(), ec);
    std::string text = scene_to_json(scene, file.parent_path());
    // Write beside and rename, so a failed write never leaves a half scene where a good one was.
    std::filesystem::path temporary = file;
    temporary += ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) fail_file(path, "cannot write the scene file");
        out << text;
        if (!out.flush()) fail_file(path, "cannot write the scene file (disk full?)");
    }
    std::filesystem::rename(temporary, file, ec);
    if (ec) fail_file(path, "cannot write the scene file: " + ec.message());
}

}  // namespace stipple
