// Animations: samplers (key times and values) and channels (which node property they drive), every
// count and type checked against the use, so that sampling can trust what it reads.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <utility>

#include "anim/gltf_reading.hpp"
#include "core/error.hpp"
#include "mesh/gltf_accessor.hpp"

namespace stipple::anim {

namespace {

const std::vector<int> kNormalizedTypes = {TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                           TINYGLTF_COMPONENT_TYPE_SHORT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};

std::string indexed(const std::string& array, size_t i) { return array + "[" + std::to_string(i) + "]"; }

bool parse_path(const std::string& text, ChannelPath& path) {
    if (text == "translation") path = ChannelPath::Translation;
    else if (text == "rotation") path = ChannelPath::Rotation;
    else if (text == "scale") path = ChannelPath::Scale;
    else if (text == "weights") path = ChannelPath::Weights;
    else return false;
    return true;
}

class AnimationReader {
public:
    AnimationReader(const std::string& path, const tinygltf::Model& gltf, const LoadOptions& options, AnimatedModel& model)
        : path_(path), gltf_(gltf), accessors_(path, gltf, options), model_(model) {}

    void run() {
        for (size_t a = 0; a < gltf_.animations.size(); ++a) model_.animations.push_back(read_animation(a));
    }

private:
    Animation read_animation(size_t index) {
        const tinygltf::Animation& in = gltf_.animations[index];
        const std::string field = indexed("animations", index);
        Animation animation;
        animation.name = in.name;
        animation.samplers.resize(in.samplers.size());
        std::vector<int> sampler_use(in.samplers.size(), -1);  // the ChannelPath a sampler was read for
        std::set<std::pair<int, int>> driven;                   // (node, ChannelPath) of the channels read
        for (size_t s = 0; s < in.samplers.size(); ++s)
            read_times(in.samplers[s], field + indexed(".samplers", s), animation.samplers[s]);
        for (size_t c = 0; c < in.channels.size(); ++c) {
            const tinygltf::AnimationChannel& channel = in.channels[c];
            const std::string channel_field = field + indexed(".channels", c);
            ChannelPath path;
            // Channels without a node or with a path of an extension (KHR_animation_pointer) drive
            // nothing this program draws.
            if (channel.target_node < 0 || !parse_path(channel.target_path, path)) {
                ++animation.idle_channels;
                continue;
            }
            if (static_cast<size_t>(channel.target_node) >= model_.nodes.size())
                fail_file(path_, channel_field + ".target.node: node " + std::to_string(channel.target_node) + " does not exist");
            if (channel.sampler < 0 || static_cast<size_t>(channel.sampler) >= in.samplers.size())
                fail_file(path_, channel_field + ".sampler: sampler " + std::to_string(channel.sampler) + " does not exist");
            const Node& node = model_.nodes[channel.target_node];
            if (node.has_matrix && path != ChannelPath::Weights)
                fail_file(path_, channel_field + ": node " + std::to_string(channel.target_node) +
                                     " has a matrix, which glTF does not allow to animate");
            uint32_t components = path == ChannelPath::Rotation ? 4 : 3;
            if (path == ChannelPath::Weights) {
                if (node.morph_set < 0) {
                    // A node outside the drawn scene has no morph set even when its mesh has targets:
                    // its weights move nothing drawn.
                    if (has_morph_targets(channel.target_node)) {
                        ++animation.idle_channels;
                        continue;
                    }
                    fail_file(path_, channel_field + ": node " + std::to_string(channel.target_node) +
                                         " has no morph targets to weight");
                }
                components = static_cast<uint32_t>(model_.morph_sets[node.morph_set].rest_weights.size());
            }
            const int s = channel.sampler;
            Sampler& sampler = animation.samplers[s];
            const std::string sampler_field = field + indexed(".samplers", s);
            // Translation and scale read their values alike (three floats a key), so one sampler may
            // drive both (glTF allows any sampler whose output suits the property).
            const int reading = path == ChannelPath::Scale ? static_cast<int>(ChannelPath::Translation) : static_cast<int>(path);
            if (sampler_use[s] < 0) {
                read_values(in.samplers[s], sampler_field, path, components, sampler);
                sampler_use[s] = reading;
            } else if (sampler_use[s] != reading || sampler.components != components) {
                fail_file(path_, channel_field + ": sampler " + std::to_string(s) +
                                     " also drives a property whose values it cannot hold (" + read_as(sampler_use[s], sampler.components) +
                                     " and " + read_as(reading, components) + ")");
            }
            // glTF: one channel per node and property (which of two would win is not said).
            if (!driven.insert({channel.target_node, static_cast<int>(path)}).second)
                fail_file(path_, channel_field + ".target: node " + std::to_string(channel.target_node) + "'s " +
                                         channel.target_path + " is driven by an earlier channel of this animation too "
                                         "(one channel per node and property)");
            animation.channels.push_back(Channel{static_cast<uint32_t>(s), channel.target_node, path});
        }
        for (const Channel& channel : animation.channels)
            animation.duration = std::max(animation.duration, animation.samplers[channel.sampler].times.back());
        return animation;
    }

    void read_times(const tinygltf::AnimationSampler& in, const std::string& field, Sampler& sampler) {
        if (in.interpolation == "LINEAR" || in.interpolation.empty()) sampler.interpolation = Interpolation::Linear;
        else if (in.interpolation == "STEP") sampler.interpolation = Interpolation::Step;
        else if (in.interpolation == "CUBICSPLINE") sampler.interpolation = Interpolation::CubicSpline;
        else fail_file(path_, field + ".interpolation: unknown interpolation '" + in.interpolation + "'");
        sampler.times = accessors_.floats(in.input, TINYGLTF_TYPE_SCALAR, {}, field + ".input");
        if (sampler.times.empty()) fail_file(path_, field + ".input: has no keys");
        check_times(sampler.times, field + ".input", in.input);
        if (sampler.interpolation == Interpolation::CubicSpline && sampler.times.size() < 2)
            fail_file(path_, field + ": CUBICSPLINE needs at least 2 keys");
    }

    // glTF's key times start at 0 or later and strictly increase. Times all below 0 gave the animation a
    // negative duration, and it stood still at its last key without a word; a repeated time passed.
    void check_times(const std::vector<float>& times, const std::string& field, int accessor) const {
        if (times[0] < 0.0f)
            fail_file(path_, field + ": key 0 of accessor " + std::to_string(accessor) + " is at time " + format(times[0]) +
                                 "; glTF's key times start at 0 or later");
        for (size_t k = 1; k < times.size(); ++k) {
            const std::string key = "key " + std::to_string(k) + " (time " + format(times[k]) + ")";
            const std::string before = "key " + std::to_string(k - 1) + " (time " + format(times[k - 1]) + ")";
            if (times[k] < times[k - 1]) fail_file(path_, field + ": " + key + " comes before " + before + "; times must increase");
            if (times[k] == times[k - 1])
                fail_file(path_, field + ": " + key + " is at the time of " + before + "; times must increase");
        }
    }

    void read_values(const tinygltf::AnimationSampler& in, const std::string& field, ChannelPath path,
                     uint32_t components, Sampler& sampler) {
        const std::string output = field + ".output";
        if (path == ChannelPath::Rotation)
            sampler.values = accessors_.floats(in.output, TINYGLTF_TYPE_VEC4, kNormalizedTypes, output);
        else if (path == ChannelPath::Weights)
            sampler.values = accessors_.floats(in.output, TINYGLTF_TYPE_SCALAR, kNormalizedTypes, output);
        else
            sampler.values = accessors_.floats(in.output, TINYGLTF_TYPE_VEC3, {}, output);
        sampler.components = components;
        const size_t keys = sampler.times.size();
        const size_t per_key = (sampler.interpolation == Interpolation::CubicSpline ? 3 : 1) *
                               (path == ChannelPath::Weights ? components : 1);
        const size_t elements = sampler.values.size() / (path == ChannelPath::Weights ? 1 : components);
        if (elements == keys * per_key) {
            check_magnitudes(sampler.values, path == ChannelPath::Weights ? 1 : components, output);
            // A key of no length is no rotation (a node's own rotation of (0, 0, 0, 0) is refused the same way): it
            // was drawn as no turn at all. A CUBICSPLINE key's tangents may be zero; its value may not.
            if (path == ChannelPath::Rotation)
                for (size_t k = 0; k < keys; ++k) {
                    const size_t at = 4 * (per_key == 3 ? 3 * k + 1 : k);
                    const float* q = &sampler.values[at];
                    const double length = std::sqrt(double(q[0]) * q[0] + double(q[1]) * q[1] + double(q[2]) * q[2] + double(q[3]) * q[3]);
                    if (!(length > 1e-6))
                        fail_file(path_, output + ": key " + std::to_string(k) + " is (" + format(q[0]) + ", " + format(q[1]) + ", " +
                                             format(q[2]) + ", " + format(q[3]) + "), not a rotation quaternion");
                }
            return;
        }
        std::string why;
        if (per_key != 1) {
            why = " (expected " + std::to_string(keys * per_key) + ": ";
            if (path == ChannelPath::Weights) why += std::to_string(components) + " morph weights";
            if (path == ChannelPath::Weights && sampler.interpolation == Interpolation::CubicSpline) why += " times ";
            if (sampler.interpolation == Interpolation::CubicSpline) why += "3 for CUBICSPLINE";
            why += " per key)";
        }
        fail_file(path_, field + ": input has " + std::to_string(keys) + " keys, output " + std::to_string(elements) + why);
    }

    // A key beyond kMaxCoordinate (a translation or morph weight of 3e38) would move the model to
    // infinity and draw a blank frame with exit status 0; no real animation comes near it.
    void check_magnitudes(const std::vector<float>& values, size_t per_element, const std::string& field) const {
        for (size_t i = 0; i < values.size(); ++i)
            if (std::abs(values[i]) > kMaxCoordinate)
                fail_file(path_, field + ": element " + std::to_string(i / per_element) + " holds " + format(values[i]) +
                                     ", beyond the +-" + format(kMaxCoordinate) + " an animation may reach");
    }

    bool has_morph_targets(int node) const {
        const int mesh = gltf_.nodes[static_cast<size_t>(node)].mesh;
        if (mesh < 0 || static_cast<size_t>(mesh) >= gltf_.meshes.size()) return false;
        for (const tinygltf::Primitive& primitive : gltf_.meshes[static_cast<size_t>(mesh)].primitives)
            if (!primitive.targets.empty()) return true;
        return false;
    }

    // How a sampler's values are read, for the message when two channels disagree.
    static std::string read_as(int reading, uint32_t components) {
        switch (static_cast<ChannelPath>(reading)) {
            case ChannelPath::Rotation: return "rotations";
            case ChannelPath::Weights: return std::to_string(components) + " morph weights a key";
            default: return "translations or scales";
        }
    }

    static std::string format(float value) {
        char text[32];
        std::snprintf(text, sizeof text, "%g", static_cast<double>(value));
        return text;
    }

    const std::string& path_;
    const tinygltf::Model& gltf_;
    AccessorReader accessors_;
    AnimatedModel& model_;
};

}  // namespace

void read_gltf_animations(const std::string& path, const tinygltf::Model& gltf, const LoadOptions& options,
                          AnimatedModel& model) {
    AnimationReader(path, gltf, options, model).run();
}

}  // namespace stipple::anim
