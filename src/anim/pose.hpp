#pragma once
// A pose: an animation evaluated at one time. The palette and the morph weights are what the
// deformation (CPU reference or shaders/deform.comp) reads.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "anim/animated_model.hpp"

namespace stipple::anim {

inline constexpr int kRestPose = -1;  // "animation" index of the rest pose (no animation)

struct Pose {
    std::vector<glm::dmat4> world;    // per node: its transform to object space
    std::vector<glm::mat4> palette;   // per palette slot: world(node) * inverse_bind
    std::vector<float> morph_weights; // AnimatedModel::morph_weight_count of them
};

// The animation an option names: its exact name first, else its index ("0", "1", ...). Unknown
// names are an error listing the model's animations.
int find_animation(const AnimatedModel& model, const std::string& name_or_index);

// Seconds into the animation: wrapped into [0, duration) when looping, else clamped to [0, duration].
// An animation of zero duration always gives 0.
double animation_time(const Animation& animation, double seconds, bool loop);

// Evaluates `animation` (or kRestPose) at `seconds`; the Pose is reused to avoid allocating per frame.
void evaluate_pose(const AnimatedModel& model, int animation, double seconds, bool loop, Pose& pose);
Pose evaluate_pose(const AnimatedModel& model, int animation, double seconds, bool loop = true);

}  // namespace stipple::anim
