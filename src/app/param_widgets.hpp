#pragma once
// One ImGui widget per parameter of the table (src/params/param_table.hpp): the panel shows every
// per-object parameter with the table's label, range and help, never a range of its own.
#include <string>

#include "params/object_params.hpp"
#include "params/param_table.hpp"

namespace stipple::app {

struct WidgetResult {
    bool changed = false;    // the value differs from before this frame
    bool committed = false;  // the edit is finished (slider released, Enter): regenerate now
};

// Draws `spec`'s widget editing `params`. `upper_limit` lowers the table's maximum for this device
// (the largest point size it draws), never raises it.
WidgetResult draw_param_widget(const ParamSpec& spec, ObjectParams& params, double upper_limit);

// The last item's help while it is hovered, wrapped at 32 ems (about 60 characters): ImGui places a tooltip
// inside the window, but one line of a long help ran past its right edge and was cut.
void hover_help(const std::string& text);

}  // namespace stipple::app
