#include "app/timeline.hpp"

#include <algorithm>
#include <cmath>

#include <imgui.h>

#include "anim/pose.hpp"
#include "app/param_widgets.hpp"
#include "core/error.hpp"
#include "scene/scene_content.hpp"

namespace stipple::app {

namespace {

bool all_loop(const Scene& scene, const std::vector<ObjectData>& objects) {
    for (size_t i = 0; i < objects.size(); ++i)
        if (objects[i].motion && !scene.objects[i].animation.loop) return false;
    return true;
}

// Whether the clock runs on past the longest animation: while any object loops, something still moves (the
// others hold their last pose, as render draws them). With one object looping and one not, the clock stopped
// at the end and froze the looping one too.
bool any_loop(const Scene& scene, const std::vector<ObjectData>& objects) {
    for (size_t i = 0; i < objects.size(); ++i)
        if (objects[i].motion && scene.objects[i].animation.loop) return true;
    return false;
}

// "1 'Walk'": how the chooser lists an animation.
std::string animation_label(const anim::AnimatedModel& model, size_t index) {
    const std::string& name = model.animations[index].name;
    std::string label = std::to_string(index);
    if (!name.empty()) label += ' ', label += quoted_excerpt(name, 120);
    return label;
}

}  // namespace

double timeline_length(const Scene& scene, const std::vector<ObjectData>& objects) {
    double length = 0.0;
    for (size_t i = 0; i < objects.size() && i < scene.objects.size(); ++i) {
        if (!objects[i].motion) continue;
        const AnimationChoice& choice = scene.objects[i].animation;
        const int index = resolve_animation(objects[i], choice);
        if (index < 0 || std::abs(choice.speed) < 1e-6) continue;
        length = std::max(length, double(objects[i].motion.model->animations[size_t(index)].duration) / std::abs(choice.speed));
    }
    return length;
}

void Timeline::toggle_play(const Scene& scene, const std::vector<ObjectData>& objects) {
    playing_ = !playing_;
    // At the end the clock stops (advance); played again from there it would stop at once, and Play
    // would seem to do nothing.
    if (playing_ && !any_loop(scene, objects) && time_ >= timeline_length(scene, objects)) time_ = 0.0;
}

void Timeline::advance(double wall_seconds, const Scene& scene, const std::vector<ObjectData>& objects) {
    if (!playing_) return;
    time_ += double(speed_) * wall_seconds;
    const double length = timeline_length(scene, objects);
    if (!any_loop(scene, objects) && time_ >= length) {  // the end holds: nothing more would move
        time_ = length;
        playing_ = false;
    }
}

glm::vec4 Timeline::draw(Scene& scene, const std::vector<ObjectData>& objects, const std::vector<std::string>& names,
                         glm::vec2 window_size) {
    if (std::none_of(objects.begin(), objects.end(), [](const ObjectData& o) { return bool(o.motion); }))
        return glm::vec4(0.0f);
    // Beside the panel where the window is wide enough, else as far right as it fits (at x = 490 a window
    // of 640 showed a third of it).
    const float x = std::clamp(window_size.x - 450.0f, 10.0f, 490.0f);
    // A row for each animated object's choice under the controls: its height fitted to them, and at the
    // foot of the window, but at most half the window high, scrolled beyond that (eleven foxes ran below
    // the window's edge, their rows out of reach).
    const float animated = float(std::count_if(objects.begin(), objects.end(), [](const ObjectData& o) { return bool(o.motion); }));
    const float fitted = 136.0f + 24.0f * animated, most = std::max(160.0f, 0.5f * window_size.y);
    ImGui::SetNextWindowPos(ImVec2(x, std::max(10.0f, window_size.y - std::min(fitted, most) - 10.0f)), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(440, fitted > most ? most : 0.0f), ImGuiCond_FirstUseEver);
    place_.before_begin(ImGui::GetIO().DisplaySize);
    const bool open = ImGui::Begin("timeline");
    place_.after_begin(ImGui::GetIO().DisplaySize);
    const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    if (open) {
        ImGui::PushItemWidth(-120.0f);
        if (ImGui::Button(playing_ ? "pause (space)" : "play (space)")) toggle_play(scene, objects);
        ImGui::SameLine();
        ImGui::Text("scene time %.3f s", time_);
        const double length = timeline_length(scene, objects);
        const bool loop = all_loop(scene, objects), some_loop = any_loop(scene, objects);
        // Looping, the bar shows where in the longest animation the clock is; dragging it moves the clock there.
        float shown = float(length > 0.0 ? (some_loop ? std::fmod(std::max(time_, 0.0), length) : std::min(time_, length)) : 0.0);
        if (ImGui::SliderFloat("time", &shown, 0.0f, float(length), "%.3f s", ImGuiSliderFlags_AlwaysClamp))
            time_ = shown;
        ImGui::SliderFloat("speed", &speed_, 0.05f, 4.0f, "%.2fx",
                           ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic);
        bool loop_edit = loop;
        // Unticked while only some objects loop (as their scene file says): a tick makes them all loop.
        if (ImGui::Checkbox(some_loop && !loop ? "loop (some objects)###loop" : "loop###loop", &loop_edit)) {
            for (size_t i = 0; i < objects.size(); ++i)
                if (objects[i].motion) scene.objects[i].animation.loop = loop_edit;
            // Looping, the clock may be many cycles on: without loop it would stand past the end at once.
            // It keeps its place in the cycle the bar shows.
            if (!loop_edit && length > 0.0) time_ = std::fmod(std::max(time_, 0.0), length);
        }
        for (size_t i = 0; i < objects.size(); ++i) {
            if (!objects[i].motion) continue;
            const anim::AnimatedModel& model = *objects[i].motion.model;
            AnimationChoice& choice = scene.objects[i].animation;
            const size_t current = size_t(std::max(resolve_animation(objects[i], choice), 0));
            const std::string label = std::to_string(i) + ": " + names.at(i);
            const bool choosing = ImGui::BeginCombo(label.c_str(), animation_label(model, current).c_str());
            if (!choosing) hover_help(label);  // a long file name is cut at the window's edge
            if (choosing) {
                for (size_t a = 0; a < model.animations.size(); ++a) {
                    const bool selected = a == current;
                    if (ImGui::Selectable(animation_label(model, a).c_str(), selected)) {
                        // By name when it has one (a saved scene reads better), else by index.
                        const std::string& name = model.animations[a].name;
                        choice.name = name.empty() || anim::find_animation(model, name) != int(a) ? std::to_string(a) : name;
                    }
                    if (selected) ImGui::SetItemDefaultFocus();
                }
                ImGui::EndCombo();
            }
        }
        ImGui::PopItemWidth();
    }
    ImGui::End();
    return glm::vec4(pos.x, pos.y, size.x, size.y);
}

}  // namespace stipple::app
