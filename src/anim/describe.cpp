#include "anim/describe.hpp"

#include <cstdio>
#include <set>

namespace stipple::anim {

namespace {

const char* interpolation_name(Interpolation i) {
    switch (i) {
        case Interpolation::Step: return "STEP";
        case Interpolation::Linear: return "LINEAR";
        case Interpolation::CubicSpline: return "CUBICSPLINE";
    }
    return "?";
}

std::string quoted(const std::string& name) { return name.empty() ? std::string() : " '" + name + "'"; }

}  // namespace

AnimationDescription describe_animation(const AnimatedModel& model) {
    AnimationDescription d;
    for (const Animation& a : model.animations) {
        AnimationSummary s;
        s.name = a.name;
        s.duration = a.duration;
        s.channels = a.channels.size();
        s.samplers = a.samplers.size();
        std::set<Interpolation> used;
        for (const Channel& c : a.channels) used.insert(a.samplers[c.sampler].interpolation);
        for (Interpolation i : used) s.interpolations += (s.interpolations.empty() ? "" : ", ") + std::string(interpolation_name(i));
        d.animations.push_back(std::move(s));
    }
    d.rest_pose_declined = model.rest_pose_declined;
    for (const Skin& skin : model.skins) d.skins.push_back(SkinSummary{skin.name, skin.joints.size()});
    for (const MorphSet& set : model.morph_sets)
        d.morphs.push_back(MorphSummary{set.mesh_name, set.node == kNoNode ? std::string() : model.nodes[set.node].name,
                                        set.target_names});
    return d;
}

std::vector<std::string> describe_lines(const AnimationDescription& d) {
    std::vector<std::string> lines;
    char duration[32];
    for (size_t i = 0; i < d.animations.size(); ++i) {
        const AnimationSummary& a = d.animations[i];
        std::snprintf(duration, sizeof duration, "%.3f", a.duration);
        lines.push_back("animation " + std::to_string(i) + quoted(a.name) + ": " + duration + " s, " +
                        std::to_string(a.channels) + (a.channels == 1 ? " channel" : " channels") +
                        (a.interpolations.empty() ? "" : " (" + a.interpolations + ")"));
    }
    for (size_t i = 0; i < d.skins.size(); ++i)
        lines.push_back("skin " + std::to_string(i) + quoted(d.skins[i].name) + ": " + std::to_string(d.skins[i].joints) +
                        (d.skins[i].joints == 1 ? " joint" : " joints"));
    for (const MorphSummary& m : d.morphs) {
        std::string names;
        bool any = false;
        for (const std::string& n : m.target_names) any |= !n.empty();
        if (any)
            for (size_t k = 0; k < m.target_names.size(); ++k)
                names += (k ? ", '" : " ('") + m.target_names[k] + "'" + (k + 1 == m.target_names.size() ? ")" : "");
        lines.push_back("morph targets of " + (m.mesh_name.empty() ? std::string("a mesh") : "mesh '" + m.mesh_name + "'") +
                        ": " + std::to_string(m.target_names.size()) + names);
    }
    return lines;
}

}  // namespace stipple::anim
