#include "app/export_panel.hpp"

#include <imgui.h>

#include "app/param_widgets.hpp"
#include "core/error.hpp"

namespace stipple::app {

std::optional<ExportRequest> draw_export_section(ExportPanelState& state, const std::string& screenshot_dir) {
    std::optional<ExportRequest> request;
    ImGui::TextDisabled("export the view (the stipples and lines drawn)");
    ImGui::RadioButton("SVG", &state.format, 0);
    ImGui::SameLine();
    ImGui::RadioButton("PDF", &state.format, 1);
    ImGui::SameLine();
    ImGui::InputText("page", state.page, sizeof state.page);
    hover_help("A3, A4, A5, letter, legal or WxHmm, with -portrait or -landscape (as --page; a bare A4 is "
               "turned as the drawing is)");
    ImGui::SliderFloat("margin mm", &state.margin_mm, 0.0f, 50.0f, "%.1f", ImGuiSliderFlags_AlwaysClamp);
    ImGui::Checkbox("fit the drawing", &state.fit_drawing);
    hover_help("on: what is drawn fills the page inside the margins; off: the whole window's view (as --fit)");
    const char* label = state.format == 0 ? "export SVG" : "export PDF";
    if (ImGui::Button(label)) {
        try {
            ExportRequest r;
            r.extension = state.format == 0 ? ".svg" : ".pdf";
            r.options.page = plot::parse_page(state.page);
            r.options.margin_mm = state.margin_mm;
            r.options.fit = state.fit_drawing ? plot::Fit::Drawing : plot::Fit::Frame;
            state.error.clear();
            request = std::move(r);
        } catch (const Error& e) {
            state.error = e.what();  // a page name still being typed: say so, export nothing
        }
    }
    hover_help("stipple-NNNN" + std::string(state.format == 0 ? ".svg" : ".pdf") + " in " + screenshot_dir);
    if (!state.error.empty()) ImGui::TextWrapped("%s", state.error.c_str());
    return request;
}

}  // namespace stipple::app
