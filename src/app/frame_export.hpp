#pragma once
// Vector and print output of a frame (issue 15): the frame is drawn offscreen with the splat recording
// the stipples it actually inks (after density, fractional intensity, hidden-stipple removal and the
// toon fade), and those, with the visible lines, become an SVG, PDF or CSV through src/export. Used by
// `stipple render -o x.svg|x.pdf|x.csv` and the viewer's export button.
#include <string>
#include <vector>

#include "export/drawing.hpp"
#include "export/plot_plan.hpp"
#include "export/plot_stats.hpp"
#include "render/stipple_renderer.hpp"
#include "scene/scene.hpp"
#include "stipple/object_data.hpp"

namespace stipple::app {

// The scene's frame as the export reads it. Every object is drawn by the splat (its CPU-density
// variant for the CPU paths): all density paths draw the same stipples (tests/test_gpu_density.cpp).
plot::Drawing capture_drawing(const gpu::Context& context, const Scene& scene, const std::vector<ObjectData>& objects,
                              const FrameView& view);

// Captures, lays out on the page, orders for the plotter and writes `path` (.svg, .pdf or .csv).
plot::PlotStats export_frame(const gpu::Context& context, const Scene& scene, const std::vector<ObjectData>& objects,
                             const FrameView& view, const plot::ExportOptions& options, const std::string& path);

}  // namespace stipple::app
