#pragma once
// Vector and print output of a frame (issue 15): the frame is drawn offscreen with the splat recording
// the stipples it actually inks (after density, fractional intensity, hidden-stipple removal and the
// toon fade), and those, with the visible lines, become an SVG, PDF or CSV through src/export. Used by
// `stipple render -o x.svg|x.pdf|x.csv` and the viewer's export button.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "export/drawing.hpp"
#include "export/plot_plan.hpp"
#include "export/plot_stats.hpp"
#include "io/png_io.hpp"
#include "render/offscreen.hpp"
#include "render/stipple_renderer.hpp"
#include "scene/scene.hpp"
#include "stipple/object_data.hpp"

namespace stipple::app {

// The scene's frames as the export reads them. Every object is drawn by the splat (its CPU-density
// variant for the CPU paths): all density paths draw the same stipples (tests/test_gpu_density_paths.cpp).
// One capture serves every frame of a sequence: made again per frame, its pipelines and the objects'
// upload took 0.4-0.9 s of each (a 200-frame SVG turntable of the bunny 177 s, its PNGs 14 s).
class DrawingCapture {
public:
    DrawingCapture(const gpu::Context& context, const Scene& scene, const std::vector<ObjectData>& objects);
    ~DrawingCapture();
    DrawingCapture(const DrawingCapture&) = delete;
    DrawingCapture& operator=(const DrawingCapture&) = delete;
    // `scene_seconds`: where animated objects are in their animations (set_scene_time).
    plot::Drawing capture(const FrameView& view, double scene_seconds = 0.0);

private:
    const gpu::Context& context_;
    const Scene& scene_;
    const std::vector<ObjectData>& objects_;
    StippleRenderer renderer_;
    std::unique_ptr<OffscreenTarget> target_;  // made for the first view's extent, again where it changes
};

// One frame's capture (DrawingCapture for one frame).
plot::Drawing capture_drawing(const gpu::Context& context, const Scene& scene, const std::vector<ObjectData>& objects,
                              const FrameView& view, double scene_seconds = 0.0);

// The last frame's visible object-space line pieces of one object as the export takes them (pixels,
// origin top-left, y down).
std::vector<plot::Segment> visible_line_segments(const StippleRenderer& renderer, size_t object);

// Print-resolution images (`-o poster.png --page A3 --dpi 600`): the page at the resolution asked for,
// the drawing inside the margins, enlarged from the screen image it would be at `screen_height` pixels
// (FrameView::detail_scale): the same stipples, as discs of the same ink, so the print has the screen's
// tone. Drawn in tiles of at most `max_tile` pixels a side.
struct PrintOptions {
    plot::PageSize page;
    double margin_mm = 10.0;
    double dpi = 300.0;
    uint32_t screen_height = 1024;
    // The screen frame's width (--width): the frame the camera composes, enlarged onto the page as vector output
    // enlarges it. Absent: the frame takes the room inside the margins' shape.
    std::optional<uint32_t> screen_width;
    uint32_t max_tile = 4096;
    // Drawing: what the screen frame draws (its pixels unlike the paper) is enlarged to fill the drawing's
    // room, at most plot::kMostEnlargement times (as vector output's --fit drawing); Frame: the whole frame.
    plot::Fit fit = plot::Fit::Drawing;
};
struct PrintLayout {
    VkExtent2D page_px{};     // the whole PNG
    VkOffset2D drawing_at{};  // where the drawing starts (the margin)
    VkExtent2D drawing_px{};  // the drawing inside the margins
    float detail_scale = 1.0f;
};
// Throws stipple::Error for a resolution out of 50..2400 dpi, a margin that leaves no room, or a page
// beyond 65536 pixels a side.
PrintLayout print_layout(const PrintOptions& options);
// The box of what `screen` draws (its extent the frame, at screen detail): its pixels unlike the paper, in the
// frame's pixels, [min, max) by pixel edges; nothing when it draws nothing. A print fitted to its drawing
// enlarges the box of its screen frame (render_print), and a bare named page is turned as the drawing's box is
// in a square frame (render).
struct DrawnBox {
    VkExtent2D frame{};
    glm::uvec2 min{0}, max{0};
};
std::optional<DrawnBox> drawn_box(const gpu::Context& context, const Scene& scene, const std::vector<ObjectData>& objects,
                                  const FrameView& screen, uint32_t max_tile, double scene_seconds = 0.0);

// `view`'s camera frames the drawing at its aspect (the screen frame's where PrintOptions::screen_width is set); its
// extent, scale and tiling come from the layout.
// `stats`, when given, receives the figures of the renderer that drew the print (render --stats), with
// the drawn stipples counted: every tile draws the whole drawing's densities, so the counts are the
// print's, and the GPU times are the last tile's.
// `fitted_drawing`, when given, says whether the drawing was fitted (--fit drawing, and something drawn).
Image render_print(const gpu::Context& context, const Scene& scene, const std::vector<ObjectData>& objects,
                   const FrameView& view, const PrintOptions& options, double scene_seconds = 0.0,
                   FrameStats* stats = nullptr, bool* fitted_drawing = nullptr);

// Captures, lays out on the page, orders for the plotter and writes `path` (.svg, .pdf or .csv).
plot::PlotStats export_frame(const gpu::Context& context, const Scene& scene, const std::vector<ObjectData>& objects,
                             const FrameView& view, const plot::ExportOptions& options, const std::string& path,
                             double scene_seconds = 0.0);
// The same with a capture kept across a sequence's frames.
plot::PlotStats export_frame(DrawingCapture& capture, const FrameView& view, const plot::ExportOptions& options,
                             const std::string& path, double scene_seconds = 0.0);

}  // namespace stipple::app
