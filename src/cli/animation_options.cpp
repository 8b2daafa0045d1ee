#include "cli/animation_options.hpp"

#include <cmath>

#include "core/error.hpp"

namespace stipple::cli {

std::set<std::string> animation_options() { return {"--animation", "--time", "--fps"}; }

void apply_animation_option(const Args& args, Scene& scene) {
    if (!args.has("--animation")) return;
    const std::string name = args.get("--animation", "");
    if (!scene.source.empty())
        fail("--animation cannot be combined with a scene file (" + scene.source +
             "): name each object's animation in the file (\"animation\": {\"name\": ...})");
    if (name.empty()) fail("--animation needs an animation name or index");
    for (SceneObject& object : scene.objects) object.animation.name = name;
}

bool any_animated(const std::vector<ObjectData>& objects) {
    for (const ObjectData& o : objects)
        if (o.motion) return true;
    return false;
}

AnimationClock read_animation_clock(const Args& args, bool animated, bool camera_path) {
    AnimationClock clock;
    for (const char* option : {"--time", "--fps"})
        if (args.has(option) && !animated)
            fail(std::string(option) + " needs an animated model (a glTF file with animations that move it): nothing in this scene moves");
    if (args.has("--time")) {
        clock.time = args.number("--time", 0.0);
        if (std::abs(clock.time) > 1e6) fail("--time = " + args.get("--time", "") + " must be in -1e6..1e6 seconds");
    }
    if (args.has("--fps")) {
        if (!args.has("--frames") && !camera_path)
            fail("--fps needs --frames N (the number of frames to render) or a scene's camera_path");
        clock.fps = args.number("--fps", 30.0);
        // Below a frame a thousand seconds the frames' times leave any animation (1e-308: 1e308 s apart).
        if (!(clock.fps >= 0.001) || clock.fps > 1000.0) fail("--fps = " + args.get("--fps", "") + " must be in 0.001..1000");
    }
    return clock;
}

}  // namespace stipple::cli
