#pragma once
// Frame sequences of `stipple render`: the camera of every frame (an orbit, or the scene's camera
// path) and the numbered file each frame goes to.
#include <optional>
#include <string>
#include <vector>

#include "render/camera.hpp"
#include "scene/scene.hpp"

namespace stipple {

// Cameras of a frame sequence. With `orbit_deg`, frame i turns the scene's camera by
// orbit_deg * i / frames around the target (so 360 over N frames loops without a repeated frame).
// Without it, the scene's camera_path is sampled at `frames` evenly spaced points, linearly
// between keyframes, the first and last frames on the first and last keyframes (frames == 0: one
// frame per keyframe). Without either, one frame of the scene's camera, or `frames` of it when the
// scene is `animated` (the animation is the motion). Throws on a sequence that has no motion to follow.
std::vector<OrbitCamera> frame_cameras(const Scene& scene, const Sphere& scene_bounds, float aspect, size_t frames,
                                       std::optional<float> orbit_deg, bool animated = false);

// True when `pattern` holds a frame number conversion: %d or %0Nd (printf style; %% is a literal %).
// Throws on any other conversion or on more than one frame number.
bool has_frame_number(const std::string& pattern);

// `pattern` with its frame number replaced by `index` ("frames/%04d.png", 7 -> "frames/0007.png").
std::string frame_path(const std::string& pattern, size_t index);
// `text` with each %% made one % (a name that is no pattern, such as 50%%.png, keeps its other characters).
std::string unescape_percent(const std::string& text);

}  // namespace stipple
