#pragma once
// The viewer's animation timeline (issue 16): the scene clock that poses every animated object, and its
// own small window: play/pause (also Space), scrub, speed, loop, and each animated object's animation.
// Drawn only when the scene has an animated object; the renderer deforms on the GPU, so playing costs
// the frame rate only the deformation pass.
#include "app/window_place.hpp"
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.hpp"
#include "stipple/object_data.hpp"

namespace stipple::app {

class Timeline {
public:
    double time() const { return time_; }  // scene seconds
    bool playing() const { return playing_; }
    float speed() const { return speed_; }  // scene seconds per wall second
    // Play or pause; playing from the end of an animation that does not loop starts it again.
    void toggle_play(const Scene& scene, const std::vector<ObjectData>& objects);
    void set_time(double seconds) { time_ = seconds; }
    void set_playing(bool playing) { playing_ = playing; }

    // Moves the clock on by `wall_seconds` of real time (when playing). Without loop the clock stops at
    // the end of the longest animation (`length`), with it the animations wrap themselves.
    void advance(double wall_seconds, const Scene& scene, const std::vector<ObjectData>& objects);

    // The window; edits the clock and the objects' animation choices (animation, loop). Returns its
    // rectangle (x, y, width, height, in window pixels), or zeros when not drawn (nothing animated).
    glm::vec4 draw(Scene& scene, const std::vector<ObjectData>& objects, const std::vector<std::string>& names,
                   glm::vec2 window_size);

private:
    WindowPlace place_;  // its window's place, kept across a shrink of the viewer's window
    double time_ = 0.0;
    bool playing_ = true;
    float speed_ = 1.0f;  // scene seconds per wall second
};

// The scene seconds in which every animated object plays its chosen animation once (the longest
// duration over its speed): the scrub bar's length. 0 when nothing is animated.
double timeline_length(const Scene& scene, const std::vector<ObjectData>& objects);

}  // namespace stipple::app
