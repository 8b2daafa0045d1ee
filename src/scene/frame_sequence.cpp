#include "scene/frame_sequence.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "core/error.hpp"

namespace stipple {

namespace {

OrbitCamera lerp(const OrbitCamera& a, const OrbitCamera& b, float t) {
    OrbitCamera c;
    c.target = glm::mix(a.target, b.target, t);
    // Distances interpolate geometrically so that a zoom proceeds at a steady rate; in double, since the
    // ratio of two distances the scene file allows (1e-21..1e24) overflows a float (a blank frame).
    c.distance = float(double(a.distance) * std::pow(double(b.distance) / double(a.distance), double(t)));
    c.yaw_deg = a.yaw_deg + (b.yaw_deg - a.yaw_deg) * t;
    c.pitch_deg = a.pitch_deg + (b.pitch_deg - a.pitch_deg) * t;
    c.fov_y_deg = a.fov_y_deg + (b.fov_y_deg - a.fov_y_deg) * t;
    c.orthographic = t < 1.0f ? a.orthographic : b.orthographic;  // a change of projection cuts at the keyframe
    return c;
}

}  // namespace

std::vector<OrbitCamera> frame_cameras(const Scene& scene, const Sphere& scene_bounds, float aspect, size_t frames,
                                       std::optional<float> orbit_deg, bool animated) {
    std::vector<OrbitCamera> cameras;
    if (orbit_deg) {
        if (frames == 0) fail("--orbit needs --frames N (N >= 1)");
        OrbitCamera base = resolve_camera(scene.camera, scene_bounds, aspect);
        for (size_t i = 0; i < frames; ++i) {
            OrbitCamera c = base;
            c.yaw_deg = base.yaw_deg + *orbit_deg * float(i) / float(frames);
            cameras.push_back(c);
        }
        return cameras;
    }
    if (scene.camera_path.empty()) {
        if (frames > 1 && !animated)
            fail("a frame sequence needs --orbit DEG, a camera_path in the scene file or an animated model");
        cameras.assign(std::max<size_t>(frames, 1), resolve_camera(scene.camera, scene_bounds, aspect));
        return cameras;
    }
    std::vector<OrbitCamera> keys;
    for (const SceneCamera& key : scene.camera_path) keys.push_back(resolve_camera(key, scene_bounds, aspect));
    if (frames == 0) return keys;
    if (keys.size() == 1 && frames > 1 && !animated)
        fail_file(scene.source, "its camera_path of one camera shows every frame the same (--frames " + std::to_string(frames) +
                                    "): give it two or more, or render one frame");
    for (size_t i = 0; i < frames; ++i) {
        if (keys.size() == 1 || frames == 1) {
            cameras.push_back(keys.front());
            continue;
        }
        // Frame 0 sits on the first keyframe and the last frame on the last one.
        float u = float(i) / float(frames - 1) * float(keys.size() - 1);
        size_t k = std::min(size_t(u), keys.size() - 2);
        cameras.push_back(lerp(keys[k], keys[k + 1], u - float(k)));
    }
    return cameras;
}

namespace {

// Finds the one frame-number conversion: its position, length and zero-padded width.
struct Conversion {
    size_t position = std::string::npos;
    size_t length = 0;
    int width = 0;
};

Conversion find_conversion(const std::string& pattern) {
    Conversion found;
    for (size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%') continue;
        if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
            ++i;
            continue;
        }
        // %d, or %0Nd (N up to 99): zero-padded. printf's %Nd pads with spaces, which no file name wants.
        size_t j = i + 1;
        const bool zero = j < pattern.size() && pattern[j] == '0';
        if (zero) ++j;
        int width = 0;
        const size_t digits_at = j;
        while (j < pattern.size() && std::isdigit((unsigned char)pattern[j]) && j - digits_at < 2)
            width = width * 10 + (pattern[j++] - '0');
        if (j >= pattern.size() || pattern[j] != 'd' || (j > digits_at && !zero))
            fail("output pattern '" + pattern + "': only %d or %0Nd (N up to 99) may stand for the frame number");
        if (found.position != std::string::npos)
            fail("output pattern '" + pattern + "' has more than one frame number");
        found = {i, j + 1 - i, width};
        i = j;
    }
    return found;
}

}  // namespace

std::string unescape_percent(const std::string& text) {
    std::string out;
    for (size_t i = 0; i < text.size(); ++i) {
        out += text[i];
        if (text[i] == '%' && i + 1 < text.size() && text[i + 1] == '%') ++i;
    }
    return out;
}

bool has_frame_number(const std::string& pattern) { return find_conversion(pattern).position != std::string::npos; }

std::string frame_path(const std::string& pattern, size_t index) {
    Conversion c = find_conversion(pattern);
    if (c.position == std::string::npos) return unescape_percent(pattern);
    std::string number = std::to_string(index);
    if (int(number.size()) < c.width) number.insert(0, size_t(c.width) - number.size(), '0');
    return unescape_percent(pattern.substr(0, c.position)) + number +
           unescape_percent(pattern.substr(c.position + c.length));
}

}  // namespace stipple
