#include "anim/pose.hpp"

#include <algorithm>
#include <cmath>

#include "anim/sampling.hpp"
#include "anim/trs.hpp"
#include "core/error.hpp"

namespace stipple::anim {

int find_animation(const AnimatedModel& model, const std::string& name_or_index) {
    for (size_t i = 0; i < model.animations.size(); ++i)
        if (model.animations[i].name == name_or_index) return static_cast<int>(i);
    const bool digits = !name_or_index.empty() && name_or_index.size() < 10 &&
                        std::all_of(name_or_index.begin(), name_or_index.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (digits && static_cast<size_t>(std::stoul(name_or_index)) < model.animations.size())
        return static_cast<int>(std::stoul(name_or_index));
    // Each by its index and name, after "its animations:" ("it has 0 'A'" read as "it has no animation").
    std::string known;
    for (size_t i = 0; i < model.animations.size(); ++i)
        known += (i ? ", " : "") + std::to_string(i) + " '" + model.animations[i].name + "'";
    fail_file(model.source, "no animation '" + name_or_index + "' (" +
                                (known.empty() ? std::string("the model has no animations") : "its animations: " + known) + ")");
}

double animation_time(const Animation& animation, double seconds, bool loop) {
    const double duration = animation.duration;
    if (!(duration > 0.0) || !std::isfinite(seconds)) return 0.0;
    if (!loop) return std::clamp(seconds, 0.0, duration);
    const double t = std::fmod(seconds, duration);
    return t < 0.0 ? t + duration : t;
}

namespace {

struct LocalTransform {
    glm::dvec3 translation;
    glm::dquat rotation;
    glm::dvec3 scale;
};

}  // namespace

void evaluate_pose(const AnimatedModel& model, int animation, double seconds, bool loop, Pose& pose) {
    const size_t node_count = model.nodes.size();
    std::vector<LocalTransform> local(node_count);
    for (size_t n = 0; n < node_count; ++n)
        local[n] = {model.nodes[n].translation, model.nodes[n].rotation, model.nodes[n].scale};
    pose.morph_weights.assign(model.morph_weight_count, 0.0f);
    for (const MorphSet& set : model.morph_sets)
        std::copy(set.rest_weights.begin(), set.rest_weights.end(), pose.morph_weights.begin() + set.first_weight);

    if (animation != kRestPose) {
        STIPPLE_CHECK(animation >= 0 && static_cast<size_t>(animation) < model.animations.size(), "animation index out of range");
        const Animation& a = model.animations[animation];
        const double t = animation_time(a, seconds, loop);
        std::vector<double> value;
        for (const Channel& channel : a.channels) {
            const Sampler& sampler = a.samplers[channel.sampler];
            value.resize(sampler.components);
            sample(sampler, t, channel.path == ChannelPath::Rotation, value.data());
            LocalTransform& target = local[channel.node];
            switch (channel.path) {
                case ChannelPath::Translation: target.translation = glm::dvec3(value[0], value[1], value[2]); break;
                case ChannelPath::Rotation: target.rotation = glm::dquat(value[3], value[0], value[1], value[2]); break;
                case ChannelPath::Scale: target.scale = glm::dvec3(value[0], value[1], value[2]); break;
                case ChannelPath::Weights: {
                    const MorphSet& set = model.morph_sets[model.nodes[channel.node].morph_set];
                    for (size_t k = 0; k < value.size(); ++k) pose.morph_weights[set.first_weight + k] = static_cast<float>(value[k]);
                    break;
                }
            }
        }
    }

    pose.world.resize(node_count);
    for (int n : model.node_order) {
        const Node& node = model.nodes[n];
        const glm::dmat4 m = node.has_matrix ? node.matrix : trs_matrix(local[n].translation, local[n].rotation, local[n].scale);
        pose.world[n] = node.parent == kNoNode ? m : pose.world[node.parent] * m;
    }
    pose.palette.resize(model.palette.size());
    for (size_t s = 0; s < model.palette.size(); ++s) {
        const PaletteSlot& slot = model.palette[s];
        pose.palette[s] = slot.node == kNoNode ? glm::mat4(1.0f)
                                               : glm::mat4(pose.world[slot.node] * glm::dmat4(slot.inverse_bind));
    }
}

Pose evaluate_pose(const AnimatedModel& model, int animation, double seconds, bool loop) {
    Pose pose;
    evaluate_pose(model, animation, seconds, loop, pose);
    return pose;
}

}  // namespace stipple::anim
