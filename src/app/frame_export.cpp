#include "app/frame_export.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>

#include "core/error.hpp"
#include "core/printf_string.hpp"
#include "export/drawing_fit.hpp"
#include "export/plot_file.hpp"
#include "gpu/context.hpp"
#include "io/png_io.hpp"
#include "render/offscreen.hpp"
#include "render/tiled_render.hpp"
#include "scene/scene_content.hpp"

namespace stipple::app {

namespace {

// The scene's objects in `renderer`, each drawn by the splat (its CPU-density variant for the CPU paths):
// all density paths draw the same stipples (tests/test_gpu_density_paths.cpp), and the splat has no point-size
// limit and records what it inks.
// `outline_as_contours`: vector output, which has no image-space lines (below).
void add_splat_objects(StippleRenderer& renderer, const Scene& scene, const std::vector<ObjectData>& objects,
                       double scene_seconds, bool outline_as_contours = false) {
    STIPPLE_CHECK(scene.objects.size() == objects.size(), "one ObjectData per scene object");
    for (size_t i = 0; i < objects.size(); ++i) {
        ObjectParams params = scene.objects[i].params;
        params.density_path = density_on_cpu(params.density_path) ? DensityPath::CpuSplat : DensityPath::Splat;
        if (outline_as_contours && params.silhouette_lines) params.contours = true;
        renderer.add_object(*objects[i].mesh, *objects[i].stipples, scene.objects[i].transform.drawing_matrix(), params,
                            objects[i].motion);
    }
    set_scene_time(renderer, scene, objects, scene_seconds);
}

}  // namespace

std::vector<plot::Segment> visible_line_segments(const StippleRenderer& renderer, size_t object) {
    std::vector<plot::Segment> segments;
    for (const gpu::LinePiece& p : renderer.read_line_pieces(object).pieces)
        segments.push_back({{p.ax, p.ay}, {p.bx, p.by}, uint32_t(object), plot::LineKind(p.kind)});
    return segments;
}

PrintLayout print_layout(const PrintOptions& options) {
    if (!(options.dpi >= 50.0 && options.dpi <= 2400.0))
        fail(printf_string("--dpi = %g must be in 50..2400", options.dpi));
    const double px_per_mm = options.dpi / 25.4;
    const double inner_w = options.page.width_mm - 2.0 * options.margin_mm, inner_h = options.page.height_mm - 2.0 * options.margin_mm;
    if (!(options.margin_mm >= 0.0) || inner_w < 1.0 || inner_h < 1.0)
        fail("--margin " + printf_string("%g", options.margin_mm) + " mm leaves no room on the page");
    PrintLayout layout;
    layout.page_px = {uint32_t(std::lround(options.page.width_mm * px_per_mm)), uint32_t(std::lround(options.page.height_mm * px_per_mm))};
    if (layout.page_px.width > 65536 || layout.page_px.height > 65536)
        fail("the page is " + std::to_string(layout.page_px.width) + "x" + std::to_string(layout.page_px.height) +
             " pixels at " + std::to_string(int(options.dpi)) + " dpi: at most 65536 a side (lower --dpi)");
    // Asked before drawing: a page beyond what a PNG holds was drawn (minutes at 2400 dpi) and then refused.
    if (!png_size_writable(layout.page_px.width, layout.page_px.height, 4))
        fail("the page is " + std::to_string(layout.page_px.width) + "x" + std::to_string(layout.page_px.height) +
             " pixels at " + std::to_string(int(options.dpi)) +
             " dpi: more than a PNG of 2 GiB of pixels (lower --dpi or the page size, or write SVG or PDF)");
    const uint32_t margin = uint32_t(std::lround(options.margin_mm * px_per_mm));
    layout.drawing_at = {int32_t(margin), int32_t(margin)};
    layout.drawing_px = {std::max(1u, layout.page_px.width - 2 * margin), std::max(1u, layout.page_px.height - 2 * margin)};
    layout.detail_scale = float(layout.drawing_px.height) / float(options.screen_height);
    return layout;
}

namespace {

// The frame a print enlarges: the drawing's aspect at `screen_height` rows.
VkExtent2D screen_frame(const PrintLayout& layout, uint32_t screen_height) {
    const double aspect = double(layout.drawing_px.width) / double(layout.drawing_px.height);
    return {uint32_t(std::max(1.0, std::round(double(screen_height) * aspect))), screen_height};
}

// The box of the pixels of `screen` (its extent the frame, at screen detail) unlike the paper. Drawn in tiles
// where the frame is larger than one target holds (a --height of thousands).
std::optional<DrawnBox> box_of_drawing(const gpu::Context& context, StippleRenderer& renderer, const FrameView& screen,
                                       uint32_t max_tile) {
    DrawnBox box;
    box.frame = screen.extent;
    const Image image = render_tiled(context, renderer, screen, max_tile);
    const glm::ivec3 paper(glm::round(glm::clamp(screen.paper_color, 0.0f, 1.0f) * 255.0f));
    glm::uvec2 lo(UINT32_MAX), hi(0);
    for (uint32_t y = 0; y < box.frame.height; ++y)
        for (uint32_t x = 0; x < box.frame.width; ++x) {
            const uint8_t* p = &image.pixels[(size_t(y) * box.frame.width + x) * size_t(image.channels)];
            // A hair of tolerance: the faintest fractional dot is not worth a larger box.
            if (std::abs(p[0] - paper.r) <= 1 && std::abs(p[1] - paper.g) <= 1 && std::abs(p[2] - paper.b) <= 1) continue;
            lo = glm::min(lo, glm::uvec2(x, y));
            hi = glm::max(hi, glm::uvec2(x + 1, y + 1));
        }
    if (hi.x <= lo.x || hi.y <= lo.y) return std::nullopt;
    box.min = lo, box.max = hi;
    return box;
}

// The print's image and the part of it inside the margins, for a drawing fitted to its room: `box`, widened by
// a pixel (a print's disc reaches past the screen's square by an eighth of its side), enlarged by the most that
// fits, at most plot::kMostEnlargement times the scale at which the whole frame fits (the frame may have a shape
// of its own, --width), and centred in the room. Where the box lies
// against the frame's edge, the room would reach past the frame, which shows nothing there: the region drawn
// is the part inside the image, placed `at` that far into the room, and the rest is paper.
struct FittedPrint {
    VkExtent2D image{};
    VkRect2D region{};
    VkOffset2D at{};
};
FittedPrint fit_to_room(const DrawnBox& box, VkExtent2D room) {
    const glm::dvec2 frame(box.frame.width, box.frame.height);
    const glm::dvec2 lo = glm::max(glm::dvec2(box.min) - 1.0, glm::dvec2(0.0));
    const glm::dvec2 hi = glm::min(glm::dvec2(box.max) + 1.0, frame);
    const glm::dvec2 size = hi - lo;
    const glm::dvec2 room_px(room.width, room.height);
    const double whole = std::min(room_px.x / frame.x, room_px.y / frame.y);  // print pixels per screen pixel
    const double scale = std::clamp(std::min(room_px.x / size.x, room_px.y / size.y), whole, plot::kMostEnlargement * whole);
    FittedPrint fitted;
    fitted.image = {uint32_t(std::max(1L, std::lround(frame.x * scale))), uint32_t(std::max(1L, std::lround(frame.y * scale)))};
    const glm::dvec2 image(fitted.image.width, fitted.image.height);
    const glm::dvec2 centre = 0.5 * (lo + hi) * image / frame;
    const glm::dvec2 origin = glm::round(centre - 0.5 * room_px);  // the room's corner in the image, maybe outside it
    const glm::dvec2 begin = glm::max(origin, glm::dvec2(0.0)), end = glm::min(origin + room_px, image);
    fitted.region = {{int32_t(begin.x), int32_t(begin.y)}, {uint32_t(end.x - begin.x), uint32_t(end.y - begin.y)}};
    fitted.at = {int32_t(begin.x - origin.x), int32_t(begin.y - origin.y)};
    return fitted;
}

}  // namespace

std::optional<DrawnBox> drawn_box(const gpu::Context& context, const Scene& scene, const std::vector<ObjectData>& objects,
                                  const FrameView& screen, uint32_t max_tile, double scene_seconds) {
    StippleRenderer renderer(context, kColorFormat, context.depth_format, RendererOptions{});
    add_splat_objects(renderer, scene, objects, scene_seconds);
    return box_of_drawing(context, renderer, screen, max_tile);
}

Image render_print(const gpu::Context& context, const Scene& scene, const std::vector<ObjectData>& objects,
                   const FrameView& view, const PrintOptions& options, double scene_seconds, FrameStats* stats,
                   bool* fitted_drawing) {
    const PrintLayout layout = print_layout(options);
    RendererOptions renderer_options;
    renderer_options.count_drawn = stats != nullptr;
    StippleRenderer renderer(context, kColorFormat, context.depth_format, renderer_options);
    add_splat_objects(renderer, scene, objects, scene_seconds);
    FrameView print = view;
    print.extent = layout.drawing_px;
    print.detail_scale = layout.detail_scale;
    std::optional<VkRect2D> region;
    VkOffset2D at{0, 0};  // where the drawn region goes in the room
    if (fitted_drawing) *fitted_drawing = false;
    const VkExtent2D screen_extent = options.screen_width ? VkExtent2D{*options.screen_width, options.screen_height}
                                                          : screen_frame(layout, options.screen_height);
    auto fit = [&](const DrawnBox& box) {
        const FittedPrint fitted = fit_to_room(box, layout.drawing_px);
        print.extent = fitted.image;
        print.detail_scale = float(fitted.image.height) / float(options.screen_height);
        region = fitted.region;
        at = fitted.at;
    };
    // A frame of its own shape, whole: enlarged until it fits the room, and centred (also a fitted drawing's frame
    // where nothing is drawn: the view's projection has the frame's shape, not the room's).
    const DrawnBox whole_frame{screen_extent, {0, 0}, {screen_extent.width, screen_extent.height}};
    if (options.screen_width) fit(whole_frame);
    if (options.fit == plot::Fit::Drawing) {
        FrameView screen = view;
        screen.extent = screen_extent;
        screen.detail_scale = 1.0f;
        if (const std::optional<DrawnBox> box = box_of_drawing(context, renderer, screen, options.max_tile)) {
            // The frame's image enlarged, of which the drawing's box is drawn: the stipples and their discs are
            // those of the screen frame, as in a print of the whole frame.
            fit(*box);
            if (fitted_drawing) *fitted_drawing = true;
        }
    }
    const Image drawing = render_tiled(context, renderer, print, options.max_tile, region);
    if (stats) *stats = renderer.stats();
    Image page;
    page.width = int(layout.page_px.width);
    page.height = int(layout.page_px.height);
    page.channels = 4;
    page.pixels.resize(size_t(page.width) * page.height * 4);
    const glm::u8vec4 paper(glm::round(glm::clamp(view.paper_color, 0.0f, 1.0f) * 255.0f), 255);
    for (size_t i = 0; i < page.pixels.size(); i += 4) std::memcpy(&page.pixels[i], &paper, 4);
    const size_t x0 = size_t(layout.drawing_at.x + at.x), y0 = size_t(layout.drawing_at.y + at.y);
    for (int y = 0; y < drawing.height; ++y)
        std::memcpy(&page.pixels[((y0 + y) * page.width + x0) * 4], &drawing.pixels[size_t(y) * drawing.width * 4],
                    size_t(drawing.width) * 4);
    return page;
}

namespace {

RendererOptions recording_visible() {
    RendererOptions options;
    options.record_visible = true;
    return options;
}

}  // namespace

DrawingCapture::DrawingCapture(const gpu::Context& context, const Scene& scene, const std::vector<ObjectData>& objects)
    : context_(context), scene_(scene), objects_(objects),
      renderer_(context, kColorFormat, context.depth_format, recording_visible()) {
    // The Raskar-Cohen lines (§3.1) are back-face edges drawn wide under the surface: only their visible
    // fringe shows, so they have no visible pieces to export. Their vector form is the outline they trace,
    // the contour edges (between a polygon facing the viewer and one facing away), walked against the
    // depth pass and exported as the object's silhouette. (An open mesh's depth pass then keeps its back
    // faces, as for contours: on the bunny 2 of 51,716 exported dots differ from the screen's.)
    add_splat_objects(renderer_, scene, objects, 0.0, true);
}

DrawingCapture::~DrawingCapture() = default;

plot::Drawing DrawingCapture::capture(const FrameView& view, double scene_seconds) {
    const Scene& scene = scene_;
    const std::vector<ObjectData>& objects = objects_;
    StippleRenderer& renderer = renderer_;  // the names the drawing's reading below has always used
    set_scene_time(renderer, scene, objects, scene_seconds);
    if (!target_ || target_->extent().width != view.extent.width || target_->extent().height != view.extent.height) {
        target_.reset();
        target_ = std::make_unique<OffscreenTarget>(context_, view.extent);
    }
    target_->draw(renderer, view);

    plot::Drawing drawing;
    drawing.width_px = view.extent.width;
    drawing.height_px = view.extent.height;
    drawing.ink = view.ink_color;
    drawing.paper = view.paper_color;
    for (size_t i = 0; i < objects.size(); ++i) {
        const ObjectGpu& object = renderer.object(i);
        // The contours stand for the silhouette where only it was asked for (below). On screen a Raskar-Cohen
        // line shows only its half outside the surface (the front faces hide the other half): stroked at its
        // whole width about the contour, the export inked 28-37% more outline than the screen, and at a width
        // of 64 px covered the stipples beside it.
        const ObjectParams& asked = scene.objects[i].params;
        const bool contours_are_silhouette = asked.silhouette_lines && !asked.contours;
        // (Borders share the layer and its width, drawn whole on screen: with them the width stays whole.)
        const float outline_width =
            contours_are_silhouette && !asked.borders ? 0.5f * object.frame.line_width : object.frame.line_width;
        drawing.objects.push_back({std::filesystem::path(scene.objects[i].model).stem().string(), outline_width,
                                   object.frame.crease_width, object.params.ink});
        const std::vector<uint32_t>& first = object.geometry.first_stipple;
        const float radius = stipple_ink_radius(object.params.point_size);  // the same ink as on screen
        for (const gpu::VisibleStipple& s : renderer.read_visible_stipples(i)) {
            // The polygon whose candidates hold this index.
            const uint32_t polygon = uint32_t(std::upper_bound(first.begin(), first.end(), s.index) - first.begin() - 1);
            // Enlarged as the frame draws it where the candidates cannot carry the density (stipple_scale).
            drawing.dots.push_back({{s.x, s.y}, radius * s.scale, s.intensity, uint32_t(i), polygon});
        }
        // The visible pieces of the object-space lines (contours, borders, creases), walked against the
        // depth pass on the GPU; the contours stand for the silhouette where only it was asked for.
        for (plot::Segment segment : visible_line_segments(renderer, i)) {
            if (contours_are_silhouette && segment.kind == plot::LineKind::Contour) segment.kind = plot::LineKind::Silhouette;
            drawing.segments.push_back(segment);
        }
    }
    return drawing;
}

plot::Drawing capture_drawing(const gpu::Context& context, const Scene& scene, const std::vector<ObjectData>& objects,
                              const FrameView& view, double scene_seconds) {
    return DrawingCapture(context, scene, objects).capture(view, scene_seconds);
}

plot::PlotStats export_frame(DrawingCapture& capture, const FrameView& view, const plot::ExportOptions& options,
                             const std::string& path, double scene_seconds) {
    const plot::PlotPlan plan = plot::make_plot_plan(capture.capture(view, scene_seconds), options);
    plot::write_plot_file(plan, path);
    return plot::plot_stats(plan);
}

plot::PlotStats export_frame(const gpu::Context& context, const Scene& scene, const std::vector<ObjectData>& objects,
                             const FrameView& view, const plot::ExportOptions& options, const std::string& path,
                             double scene_seconds) {
    DrawingCapture capture(context, scene, objects);
    return export_frame(capture, view, options, path, scene_seconds);
}

}  // namespace stipple::app
