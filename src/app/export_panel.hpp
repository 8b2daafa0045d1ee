#pragma once
// The panel's "export" section (issue 15): the current view as SVG or PDF, on a page with a margin,
// written next to the screenshots. The fields keep their values from frame to frame in the viewer's
// ExportPanelState; pressing the button gives an ExportRequest the viewer carries out between frames.
#include <optional>
#include <string>

#include "export/plot_plan.hpp"

namespace stipple::app {

struct ExportPanelState {
    int format = 0;              // 0: SVG, 1: PDF
    char page[32] = "A4";        // as --page takes it: A3|A4|A5|letter|legal|WxHmm [-portrait|-landscape]
    float margin_mm = 10.0f;     // the CLI's default (plot::ExportOptions)
    bool fit_drawing = true;     // --fit drawing (the default) or frame
    std::string error;           // the last page name that did not parse, shown under the field
};

struct ExportRequest {
    std::string extension;  // ".svg" or ".pdf"
    plot::ExportOptions options;
};

// Draws the section inside the panel's window; returns a request when the button was pressed with a
// page that parses (otherwise the state's error says why).
std::optional<ExportRequest> draw_export_section(ExportPanelState& state, const std::string& screenshot_dir);

}  // namespace stipple::app
