#include "app/panel.hpp"
#include "app/window_place.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "app/param_widgets.hpp"
#include "mesh/mesh.hpp"

namespace stipple::app {

namespace {

constexpr ImGuiSliderFlags kClamp = ImGuiSliderFlags_AlwaysClamp;
constexpr ImGuiSliderFlags kLog = ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic;

double total_gpu_ms(const FrameStats& stats) {
    double total = 0.0;
    for (const auto& pass : stats.gpu_ms) total += pass.second;
    return total;
}

// The figures at the top keep one layout whatever the frame does, so the controls below never move under the
// mouse: the GPU's passes (more of them with lines or the toon shade on, fewer on another path) are listed at
// the panel's foot, and the background work's progress bar has its row whether or not work runs (a walkthrough's
// click aimed at the toon box landed on a label when turning lines on added two rows above it).
void figures_section(const PanelFigures& f, PanelRequests& requests) {
    if (f.stats.gpu_ms.empty())
        ImGui::Text("%.1f fps   CPU %.2f ms/frame", f.fps, f.cpu_frame_ms);
    else
        ImGui::Text("%.1f fps   CPU %.2f ms/frame   GPU %.2f ms", f.fps, f.cpu_frame_ms, total_gpu_ms(f.stats));
    hover_help("Each pass's GPU time is listed at the foot of the panel.");
    ImGui::Text("polygons            %llu", (unsigned long long)f.stats.triangles);
    ImGui::Text("candidate stipples  %llu", (unsigned long long)f.stats.candidate_stipples);
    if (f.stats.drawn_stipples >= 0)
        ImGui::Text("drawn stipples      %lld", (long long)f.stats.drawn_stipples);
    else
        ImGui::TextDisabled("drawn stipples      (not counted: --no-count-drawn)");
    ImGui::TextDisabled("%s, %ux%u, %s", f.device.c_str(), f.extent.width, f.extent.height, f.present_mode);
    hover_help(f.device + ", " + std::to_string(f.extent.width) + "x" + std::to_string(f.extent.height) + ", " +
               f.present_mode);  // the line is cut in a narrow panel
    if (!f.work_label.empty()) {  // the old stipples keep being drawn meanwhile
        std::string label = f.work_label;
        if (f.work_queued > 0) label += " (" + std::to_string(f.work_queued) + " more queued)";
        ImGui::ProgressBar(float(f.work_fraction), ImVec2(-1.0f, 0.0f), label.c_str());
    } else {
        ImGui::AlignTextToFramePadding();  // the progress bar's height: the rows below stay where they are
        ImGui::TextDisabled("stipples ready");
    }
    bool vsync = f.vsync;
    ImGui::BeginDisabled(!f.can_disable_vsync);
    if (ImGui::Checkbox("vsync (V)", &vsync)) requests.toggle_vsync = true;
    ImGui::EndDisabled();
}

void gpu_passes_section(const PanelFigures& f) {
    if (f.stats.gpu_ms.empty()) return;
    ImGui::Separator();
    ImGui::TextDisabled("GPU time per pass");
    for (const auto& [pass, ms] : f.stats.gpu_ms) ImGui::Text("  %-12s %7.3f ms", pass.c_str(), ms);
    ImGui::Text("  %-12s %7.3f ms", "total", total_gpu_ms(f.stats));
}

void scene_section(Scene& scene, const PanelFigures& f, PanelRequests& requests) {
    glm::vec3 light = scene.light;
    if (ImGui::SliderFloat3("light", &light.x, -1.0f, 1.0f, "%.2f", kClamp) && glm::length(light) > 1e-3f)
        scene.light = light;  // a zero direction would have no meaning; keep the last good one
    hover_help("Direction toward the light in view space: x right, y up, z toward you (paper §2.2).");
    ImGui::ColorEdit3("paper", &scene.paper.x);
    ImGui::ColorEdit3("ink", &scene.ink.x);
    bool orthographic = f.orthographic;
    if (ImGui::Checkbox("orthographic (O)", &orthographic)) requests.toggle_projection = true;
    hover_help("Parallel lines of sight, as technical and scientific illustrations are drawn, instead of perspective; "
               "the scale at the target is kept. Ctrl+S saves it with the camera.");
    if (ImGui::Button("frame all (F)")) requests.frame_all = true;
    ImGui::SameLine();
    if (ImGui::Button("screenshot (S)")) requests.screenshot = true;
    hover_help("PNG at window resolution, without the panel, into " + f.screenshot_dir);
    ImGui::SameLine();
    if (ImGui::Button("save scene (Ctrl+S)")) requests.save_scene = true;
    hover_help("Writes the current objects, parameters, camera, light and colours to " + f.scene_path);
    ImGui::SameLine();
    if (ImGui::Button("hide (H)")) requests.hide = true;
}

void object_section(SceneObject& object, size_t index, const std::string& name, size_t object_count, glm::vec3 scene_ink,
                    const PanelFigures& f, PanelRequests& requests) {
    ObjectParams& p = object.params;
    ImGui::PushID(int(index));
    std::string label = std::to_string(index) + ": " + name;
    const bool open = ImGui::CollapsingHeader(label.c_str(), index == 0 ? ImGuiTreeNodeFlags_DefaultOpen : 0);
    hover_help(label);  // a long file name is cut at the panel's edge
    if (open) {
        const char* section = nullptr;
        for (const ParamSpec& spec : param_table()) {
            if (spec.widget == ParamWidget::Hidden) continue;
            if (!section || std::string(section) != spec.section) {
                section = spec.section;
                ImGui::TextDisabled("%s", section);
            }
            // A round dot is drawn 1.13 times its point size across (drawn_point_size): kept within the device's points.
            const double limit = std::string(spec.key) == "point_size"
                                     ? std::clamp(double(largest_point_size_drawn_within(f.max_point_size)), spec.min, spec.max)
                                     : spec.max;
            // Generation parameters act when the edit is committed (slider released, Enter): new stipples
            // for a big model take a while, and regenerating on every slider tick would stall the viewer.
            if (draw_param_widget(spec, p, limit).committed && spec.effect == ParamEffect::Regenerate)
                requests.regenerate.push_back(index);
        }

        // The object's own ink, else the scene's (the colours above).
        bool own_ink = p.ink.has_value();
        if (ImGui::Checkbox("own ink", &own_ink)) p.ink = own_ink ? std::optional<glm::vec3>(scene_ink) : std::nullopt;
        hover_help("Draw this object's stipples, lines and toon shade in an ink of its own (a layer of that colour in "
                   "vector output); off, the scene's ink.");
        if (p.ink) {
            ImGui::SameLine();
            ImGui::ColorEdit3("object ink", &p.ink->x);
        }

        ImGui::TextDisabled("placement");
        if (object.transform.matrix) {
            ImGui::TextDisabled("matrix transform (edit it in the scene file)");
        } else {
            // Within what a scene file accepts (scene_json.cpp's place): typed as 1e30 it was saved and then refused.
            ImGui::DragFloat3("translate", &object.transform.translate.x, 0.01f, -kMaxCoordinate, kMaxCoordinate, "%.3f", kClamp);
            ImGui::SliderFloat3("rotate deg", &object.transform.rotate_deg.x, -180.0f, 180.0f, "%.0f", kClamp);
            ImGui::DragFloat("scale", &object.transform.scale, 0.01f, 1e-4f, 1e4f, "%.3f", kLog);
        }
        ImGui::BeginDisabled(object_count <= 1);
        if (ImGui::Button("remove object")) requests.remove = index;
        ImGui::EndDisabled();
    }
    ImGui::PopID();
}

}  // namespace

// Narrower windows start with the panel folded (it is 470 px wide open).
constexpr float kNarrowWindow = 1000.0f;

PanelRequests draw_panel(Scene& scene, const std::vector<std::string>& names, const PanelFigures& figures,
                         ExportPanelState& export_state) {
    PanelRequests requests;
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(470, 0), ImGuiCond_FirstUseEver);
    // The height the display the panel is drawn in leaves it (the frame's can differ for a frame after a resize).
    const float max_height = std::max(200.0f, ImGui::GetIO().DisplaySize.y - 20);
    // A window made small clamps the panel's height; grown again, the panel fits its content again (it
    // stayed 200 px tall, the timeline over its figures).
    static float clamped_at = 0.0f;   // the height limit that last clamped the panel, 0 if none
    static float last_width = 470.0f;  // as the user left it
    if (clamped_at > 0.0f && max_height > clamped_at) {
        ImGui::SetNextWindowSize(ImVec2(last_width, 0), ImGuiCond_Always);
        clamped_at = 0.0f;
    }
    ImGui::SetNextWindowSizeConstraints(ImVec2(300, 100), ImVec2(800, max_height));
    // A window too narrow for the panel beside the drawing starts with the panel folded to its title bar
    // (at 640 x 512 the open panel covered three quarters of the drawing); the title keeps the frame rate.
    ImGui::SetNextWindowCollapsed(float(figures.extent.width) < kNarrowWindow, ImGuiCond_FirstUseEver);
    // A new error unfolds it: the messages are shown inside (the same error again too, once folded).
    static uint64_t errors_seen = 0;
    if (figures.errors_said > errors_seen) ImGui::SetNextWindowCollapsed(false, ImGuiCond_Always);
    errors_seen = figures.errors_said;
    // A click on the folded title bar (not a drag, which moves it) unfolds it, not only one on its arrow.
    static bool unfold = false;
    if (unfold) ImGui::SetNextWindowCollapsed(false, ImGuiCond_Always);
    unfold = false;
    char title[64];
    std::snprintf(title, sizeof title, "stipple  %.1f fps###stipple", figures.fps);  // ### keeps one window
    static WindowPlace place;
    place.before_begin(ImGui::GetIO().DisplaySize);
    bool open = ImGui::Begin(title);
    place.after_begin(ImGui::GetIO().DisplaySize);
    ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    // Clamped by the limit, or squeezed by Dear ImGui to its least height in a display lower than the limit's
    // floor (a 50-px window made it 100 px, under the limit of 200, and the panel was never grown again); a
    // panel the user made that low by hand is left as it is.
    const bool squeezed = size.y <= 100.5f && ImGui::GetIO().DisplaySize.y - 20 < 200.0f;
    if (size.y >= max_height - 0.5f || squeezed) clamped_at = max_height;
    last_width = size.x;
    requests.rect = {pos.x, pos.y, size.x, size.y};
    requests.open = open && !ImGui::IsWindowCollapsed();  // a new window's first Begin is true while folded too
    requests.display = {ImGui::GetIO().DisplaySize.x, ImGui::GetIO().DisplaySize.y};
    // Not on the arrow (an item, which toggles the fold itself a frame later), nor after a drag (even one that
    // came back to where it began).
    if (!open && ImGui::IsWindowHovered() && !ImGui::IsAnyItemHovered() && ImGui::IsMouseReleased(ImGuiMouseButton_Left))
        unfold = ImGui::GetIO().MouseDragMaxDistanceSqr[ImGuiMouseButton_Left] < 9.0f;
    if (open) {
        ImGui::PushItemWidth(-150.0f);  // room for the labels on the right
        figures_section(figures, requests);
        ImGui::Separator();
        scene_section(scene, figures, requests);
        ImGui::Separator();
        requests.export_view = draw_export_section(export_state, figures.screenshot_dir);
        ImGui::Separator();
        ImGui::TextDisabled("drag: left orbit, right/middle pan, wheel zoom; drop model files to add them");
        for (size_t i = 0; i < scene.objects.size(); ++i)
            object_section(scene.objects[i], i, names.at(i), scene.objects.size(), scene.ink, figures, requests);
        if (!figures.messages.empty()) {
            ImGui::Separator();
            size_t first = figures.messages.size() > 6 ? figures.messages.size() - 6 : 0;
            for (size_t i = first; i < figures.messages.size(); ++i)
                ImGui::TextWrapped("%s", figures.messages[i].c_str());
        }
        gpu_passes_section(figures);
        ImGui::PopItemWidth();
    }
    ImGui::End();
    return requests;
}

}  // namespace stipple::app
