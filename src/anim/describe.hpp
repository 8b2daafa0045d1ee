#pragma once
// What `stipple info` lists about a model's animation: its animations (durations, channels), skins
// (joints) and morph targets (names where the file gives them).
#include <string>
#include <vector>

#include "anim/animated_model.hpp"

namespace stipple::anim {

struct AnimationSummary {
    std::string name;
    double duration = 0.0;  // seconds
    size_t channels = 0;
    size_t idle_channels = 0;  // Animation::idle_channels
    size_t samplers = 0;
    std::string interpolations;  // the kinds its channels use, e.g. "LINEAR, STEP"
};

struct SkinSummary {
    std::string name;
    size_t joints = 0;
};

struct MorphSummary {
    std::string mesh_name;
    std::string node_name;
    std::vector<std::string> target_names;  // "" where unnamed
};

struct AnimationDescription {
    std::vector<AnimationSummary> animations;
    std::vector<SkinSummary> skins;
    std::vector<MorphSummary> morphs;
    bool rest_pose_declined = false;  // AnimatedModel::rest_pose_declined
};

AnimationDescription describe_animation(const AnimatedModel& model);

// One line per item, e.g. "animation 1 'Walk': 0.708 s, 21 channels (LINEAR)", "skin 0: 24 joints",
// "morph targets of mesh 'Cube': 2 ('thin', 'angle')". Empty when nothing animates the model.
std::vector<std::string> describe_lines(const AnimationDescription& description);

}  // namespace stipple::anim
