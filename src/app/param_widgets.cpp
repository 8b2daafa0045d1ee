#include "app/param_widgets.hpp"

#include <string_view>

#include <algorithm>
#include <cstdint>
#include <string>

#include <imgui.h>

namespace stipple::app {

void hover_help(const std::string& text) {
    if (!ImGui::IsItemHovered()) return;
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 32.0f);
    ImGui::TextUnformatted(text.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

WidgetResult draw_param_widget(const ParamSpec& spec, ObjectParams& params, double upper_limit) {
    const double before = spec.get(params);
    const double lowest = param_lowest_value(spec);
    const double highest = std::min(spec.max, upper_limit);
    double value = before;
    switch (spec.type) {
        case ParamType::Bool: {
            bool on = value != 0.0;
            ImGui::Checkbox(spec.label, &on);
            value = on ? 1.0 : 0.0;
            break;
        }
        case ParamType::Choice: {
            int index = int(value);
            if (ImGui::BeginCombo(spec.label, format_param_value(spec, value).c_str())) {
                for (size_t i = 0; i < spec.choices.size(); ++i)
                    if (ImGui::Selectable(spec.choices[i], int(i) == index)) index = int(i);
                ImGui::EndCombo();
            }
            value = double(index);
            break;
        }
        case ParamType::Int: {
            if (spec.widget == ParamWidget::Input) {
                uint64_t v = uint64_t(value), step = 1, fast = 1;
                // The budget moves in large steps; a seed (also up to 2^32) is a name, stepped one by one.
                if (std::string_view(spec.key) == "max_stipples") step = 100000, fast = 1000000;
                ImGui::InputScalar(spec.label, ImGuiDataType_U64, &v, &step, &fast, "%llu");
                value = double(v);
            } else {
                int v = int(value);
                ImGui::SliderInt(spec.label, &v, int(lowest), int(highest), "%d", ImGuiSliderFlags_AlwaysClamp);
                value = double(v);
            }
            break;
        }
        case ParamType::Float: {
            float v = float(value);
            ImGuiSliderFlags flags = ImGuiSliderFlags_AlwaysClamp;
            if (spec.widget == ParamWidget::LogSlider) flags |= ImGuiSliderFlags_Logarithmic;
            ImGui::SliderFloat(spec.label, &v, float(lowest), float(highest), "%.3g", flags);
            value = double(v);
            break;
        }
    }
    if (ImGui::IsItemHovered()) hover_help(std::string(spec.help) + "\n(" + param_range_text(spec) + ")");
    // The table's range holds whatever the widget allowed (typed input, steps past the ends).
    if (spec.type == ParamType::Int || spec.type == ParamType::Float) value = std::clamp(value, lowest, highest);
    if (value != before) spec.set(params, value);
    return {value != before, ImGui::IsItemDeactivatedAfterEdit()};
}

}  // namespace stipple::app
