#pragma once
// The animation options of render and view (issue 16): --animation NAME|N picks what the MODELs play,
// --time SECONDS sets the scene clock of the (first) frame, and render's --fps F spaces a --frames N
// sequence. A scene file names each object's animation, start and speed itself.
#include <set>
#include <string>
#include <vector>

#include "cli/args.hpp"
#include "scene/scene.hpp"
#include "stipple/object_data.hpp"

namespace stipple::cli {

std::set<std::string> animation_options();  // --animation, --time, --fps

// --animation for the MODELs given on the command line (every one of them plays it). Combined with a
// scene file it is an error naming the file (the file sets each object's animation).
void apply_animation_option(const Args& args, Scene& scene);

// Whether any object of the loaded scene is animated.
bool any_animated(const std::vector<ObjectData>& objects);

struct AnimationClock {
    double time = 0.0;  // --time: the scene clock of the first frame, seconds
    double fps = 30.0;  // --fps: frames per scene second of a sequence
    double frame_time(size_t frame) const { return time + double(frame) / fps; }
};

// --time and --fps, checked: finite, --fps in [0.001, 1000] and only with --frames or a camera_path (a
// sequence), and neither when nothing in the scene is animated (they would change nothing).
AnimationClock read_animation_clock(const Args& args, bool animated, bool camera_path = false);

}  // namespace stipple::cli
