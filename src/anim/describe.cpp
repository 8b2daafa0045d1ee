#include "anim/describe.hpp"

#include <cstdio>
#include <set>

#include "core/error.hpp"

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

// A name from the file, as one printable line of reasonable length (a name may hold line breaks).
constexpr size_t kNameMost = 120;
std::string printable(const std::string& name) { return excerpt(name, kNameMost); }
std::string quoted(const std::string& name) {
    if (name.empty()) return {};
    std::string out = " ";  // appended in place: GCC 12 warns (-Wrestrict, a false positive) on " " + std::string&&
    out += quoted_excerpt(name, kNameMost);
    return out;
}

}  // namespace

AnimationDescription describe_animation(const AnimatedModel& model) {
    AnimationDescription d;
    for (const Animation& a : model.animations) {
        AnimationSummary s;
        s.name = a.name;
        s.duration = a.duration;
        s.channels = a.channels.size();
        s.idle_channels = a.idle_channels;
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
                        (a.interpolations.empty() ? "" : " (" + a.interpolations + ")") +
                        (a.idle_channels == 0 ? ""
                                              : ", and " + std::to_string(a.idle_channels) +
                                                    (a.idle_channels == 1 ? " that moves" : " that move") + " nothing drawn"));
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
                names += (k ? ", '" : " ('") + printable(m.target_names[k]) + "'" + (k + 1 == m.target_names.size() ? ")" : "");
        lines.push_back("morph targets of " + (m.mesh_name.empty() ? std::string("a mesh") : "mesh '" + printable(m.mesh_name) + "'") +
                        ": " + std::to_string(m.target_names.size()) + names);
    }
    return lines;
}

}  // namespace stipple::anim
