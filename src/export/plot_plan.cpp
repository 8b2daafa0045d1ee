#include "export/plot_plan.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <numbers>
#include <optional>

#include <glm/geometric.hpp>

#include "core/error.hpp"
#include "core/hash.hpp"
#include "export/drawing_fit.hpp"
#include "export/dot_order.hpp"
#include "export/polyline_order.hpp"
#include "export/polylines.hpp"
#include "export/simplify.hpp"
#include "export/text_format.hpp"

namespace stipple::plot {

DotStyle parse_dot_style(const std::string& given) {
    const std::string name = lower_ascii(given);
    if (name == "filled") return DotStyle::Filled;
    if (name == "circle") return DotStyle::Circle;
    if (name == "tick") return DotStyle::Tick;
    fail("--dot-style '" + given + "': expected filled, circle or tick");
}

const char* dot_style_name(DotStyle style) {
    switch (style) {
        case DotStyle::Filled: return "filled";
        case DotStyle::Circle: return "circle";
        case DotStyle::Tick: return "tick";
    }
    return "filled";
}

Fit parse_fit(const std::string& given) {
    const std::string name = lower_ascii(given);
    if (name == "drawing") return Fit::Drawing;
    if (name == "frame") return Fit::Frame;
    fail("--fit '" + given + "': expected drawing or frame");
}

double least_mark_radius(DotStyle style, double pen_mm) {
    switch (style) {
        case DotStyle::Filled: return 0.0;
        case DotStyle::Circle: return circle_stroke_radius(0.0, pen_mm) + pen_mm / 2.0;
        case DotStyle::Tick: return std::sqrt(pen_mm * kMinTickMm / std::numbers::pi + pen_mm * pen_mm / 4.0);
    }
    return 0.0;
}

double circle_stroke_radius(double radius_mm, double pen_mm) { return std::max(radius_mm - pen_mm / 2.0, pen_mm / 4.0); }

std::array<glm::dvec2, 2> dot_stroke_ends(const PlotDot& dot, DotStyle style, double pen_mm) {
    if (style != DotStyle::Tick) return {dot.mm, dot.mm};
    const glm::dvec2 half(tick_length(dot.radius_mm, pen_mm) / 2.0, 0.0);
    return dot.reversed ? std::array<glm::dvec2, 2>{dot.mm + half, dot.mm - half} : std::array<glm::dvec2, 2>{dot.mm - half, dot.mm + half};
}

double tick_length(double radius_mm, double pen_mm) {
    if (!(pen_mm > 0.0)) return kMinTickMm;
    const double ink = std::numbers::pi * (radius_mm * radius_mm - pen_mm * pen_mm / 4.0);
    return std::max(std::min(ink / pen_mm, kMaxTickDiameters * 2.0 * radius_mm), kMinTickMm);
}

double tick_ink_short(double radius_mm, double pen_mm) {
    // Decided by the lengths: the areas of a tick that carries all its ink differ from the dot's in the last bits.
    const double ink = std::numbers::pi * (radius_mm * radius_mm - pen_mm * pen_mm / 4.0);
    if (!(pen_mm > 0.0) || ink / pen_mm <= kMaxTickDiameters * 2.0 * radius_mm) return 0.0;
    const double drawn = pen_mm * tick_length(radius_mm, pen_mm) + std::numbers::pi * pen_mm * pen_mm / 4.0;
    return std::max(std::numbers::pi * radius_mm * radius_mm - drawn, 0.0);
}

namespace {

// An object's name in its layers' labels: its file's, or "objectN" for none; a name that an earlier object
// has too (the same model twice in a scene) gets " (2)", " (3)", so that each layer can be told apart.
std::string layer_name(const Drawing& drawing, uint32_t object) {
    const std::string& name = drawing.objects[object].name;
    if (name.empty()) return "object" + std::to_string(object + 1);
    uint32_t earlier = 0;
    for (uint32_t k = 0; k < object; ++k) earlier += drawing.objects[k].name == name;
    return earlier ? name + " (" + std::to_string(earlier + 1) + ")" : name;
}

std::string layer_label(uint32_t number, const Drawing& drawing, uint32_t object, LayerKind kind) {
    const char* what = kind == LayerKind::Stipples ? " stipples" : kind == LayerKind::Lines ? " lines" : " creases";
    return std::to_string(number) + " " + layer_name(drawing, object) + what;
}

bool finite(glm::vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// The part of segment a-b inside the frame [0, w] x [0, h] (Liang-Barsky), or nothing. The GPU's line
// pieces may reach a few pixels past the image (a run bridged to a vertex outside it, a walk's first half
// step): the page shows the frame, and with no margin they ran off the paper.
std::optional<std::array<glm::dvec2, 2>> clip_to_frame(glm::dvec2 a, glm::dvec2 b, double w, double h) {
    double t0 = 0.0, t1 = 1.0;
    const glm::dvec2 d = b - a;
    const double p[4] = {-d.x, d.x, -d.y, d.y};
    const double q[4] = {a.x, w - a.x, a.y, h - a.y};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0.0) {
            if (q[i] < 0.0) return std::nullopt;  // parallel to this edge and outside it
            continue;
        }
        const double t = q[i] / p[i];
        if (p[i] < 0.0) t0 = std::max(t0, t);
        else t1 = std::min(t1, t);
    }
    if (t0 > t1) return std::nullopt;
    return std::array<glm::dvec2, 2>{a + t0 * d, a + t1 * d};
}

// Whether a dot's centre lies in the frame: one beyond its edge is mostly off the image (the splat inks
// the pixels of it that are in), and the page holds the frame.
bool in_frame(glm::vec2 p, uint32_t w, uint32_t h) { return p.x >= 0.0f && p.y >= 0.0f && p.x <= float(w) && p.y <= float(h); }

// The ink radius of a dot on the page: its frame radius scaled, and sqrt(intensity) of it.
double ink_radius_px(const Dot& dot) {
    return std::max(0.0, static_cast<double>(dot.radius_px)) * std::sqrt(std::clamp(static_cast<double>(dot.intensity), 0.0, 1.0));
}

// A uniform number in [0, 1) fixed by the dot (its index in the drawing, its place and polygon): the same
// command draws the same dots.
double dot_chance(const Dot& dot, uint32_t index) {
    uint32_t x = 0, y = 0;
    std::memcpy(&x, &dot.px.x, 4);
    std::memcpy(&y, &dot.px.y, 4);
    const uint64_t key = mix64(mix64((uint64_t(x) << 32 | y) ^ 0x5DEECE66Dull) ^ (uint64_t(dot.polygon) << 32 | index));
    return double(key >> 11) * 0x1.0p-53;
}

PlotLayer stipple_layer(const Drawing& drawing, std::vector<uint32_t> dot_indices, uint32_t object, PlotPlan& plan,
                        double pen_mm, bool plotter_order, glm::dvec2& pen) {
    PlotLayer layer;
    layer.number = 3 * object + 1;
    layer.label = layer_label(layer.number, drawing, object, LayerKind::Stipples);
    layer.object = object;
    layer.ink = drawing.objects[object].ink.value_or(drawing.ink);
    layer.kind = LayerKind::Stipples;
    layer.stroke_mm = pen_mm;
    // Dots under the pen's least mark: drawn as it with the chance of their share of its ink (plot_plan.hpp).
    const double least = least_mark_radius(plan.dot_style, pen_mm);
    std::vector<double> radius_mm;
    radius_mm.reserve(dot_indices.size());
    size_t kept = 0;
    for (const uint32_t i : dot_indices) {
        const Dot& dot = drawing.dots[i];
        double radius = ink_radius_px(dot) * plan.layout.mm_per_px;
        if (radius < least) {
            ++plan.small_dots;
            if (dot_chance(dot, i) >= (radius / least) * (radius / least)) continue;
            radius = least;
        }
        dot_indices[kept++] = i;
        radius_mm.push_back(radius);
    }
    dot_indices.resize(kept);
    std::vector<glm::dvec2> points;
    points.reserve(dot_indices.size());
    for (const uint32_t i : dot_indices) points.push_back(plan.layout.to_mm(glm::dvec2(drawing.dots[i].px)));
    std::vector<uint32_t> order;
    if (plotter_order) {
        order = plot_order(points, pen);
    } else {
        order.resize(points.size());
        for (uint32_t k = 0; k < order.size(); ++k) order[k] = k;
    }
    layer.dots.reserve(order.size());
    for (const uint32_t k : order) layer.dots.push_back({points[k], radius_mm[k], object, drawing.dots[dot_indices[k]].polygon});
    // A tick is drawn from its end nearer the pen: drawn all one way, the pen crossed back over each tick before
    // travelling on (the spot's pen-up travel 15% longer, a scene of 37k ticks' 1.5 times).
    for (PlotDot& dot : layer.dots) {
        const std::array<glm::dvec2, 2> ends = dot_stroke_ends(dot, plan.dot_style, pen_mm);
        dot.reversed = plan.dot_style == DotStyle::Tick && glm::length(ends[1] - pen) < glm::length(ends[0] - pen);
        pen = dot.reversed ? ends[0] : ends[1];
    }
    return layer;
}

using Piece = std::array<glm::dvec2, 2>;

// The parts of the segments inside the frame.
std::vector<Piece> pieces_in_frame(const Drawing& drawing, const std::vector<uint32_t>& segment_indices) {
    std::vector<Piece> pieces;
    pieces.reserve(segment_indices.size());
    for (const uint32_t i : segment_indices)
        if (const auto piece = clip_to_frame(glm::dvec2(drawing.segments[i].a), glm::dvec2(drawing.segments[i].b), drawing.width_px,
                                             drawing.height_px))
            pieces.push_back(*piece);
    return pieces;
}

// The frame's pixels a line of kind `kind` of `object` is drawn wide.
float line_width_px(const Drawing& drawing, uint32_t object, LayerKind kind) {
    return std::max(0.0f, kind == LayerKind::Lines ? drawing.objects[object].line_width_px : drawing.objects[object].crease_width_px);
}

// Whether the screen inks a pixel of a stroke (in pixels) drawn `width_px` wide: a pixel centre within half the
// width of it, as the line pieces' fragments keep them (shaders/line_pieces.frag). Only a stroke a few pixels
// across can miss every centre: an object far away whose visible contour is a speck drew nothing on the screen
// and a squiggle of a few millimetres in its SVG (a review, 2026-12-06: 1.7 mm, 0.46 px on the screen).
bool stroke_inks_a_pixel(const Polyline& line, double width_px) {
    if (line.points.empty()) return false;
    glm::dvec2 lo = line.points.front(), hi = lo;
    for (const glm::dvec2& p : line.points) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const double half = 0.5 * width_px;
    if (hi.x - lo.x > 4.0 || hi.y - lo.y > 4.0) return true;  // it crosses pixels' centres somewhere
    const size_t n = line.points.size();
    const size_t edges = line.closed ? n : std::max<size_t>(n - 1, 1);
    for (double y = std::floor(lo.y - half); y <= hi.y + half; ++y)
        for (double x = std::floor(lo.x - half); x <= hi.x + half; ++x) {
            const glm::dvec2 centre(x + 0.5, y + 0.5);
            for (size_t i = 0; i < edges; ++i) {
                const glm::dvec2 a = line.points[i], b = line.points[std::min((i + 1) % n, n - 1)];
                const glm::dvec2 ab = b - a;
                const double t = glm::dot(ab, ab) > 0.0 ? std::clamp(glm::dot(centre - a, ab) / glm::dot(ab, ab), 0.0, 1.0) : 0.0;
                if (glm::length(centre - (a + t * ab)) <= half) return true;
            }
        }
    return false;
}

// The pieces of the strokes the screen draws a pixel of: a speck's are left out before the page is fitted
// around what is drawn (fitted around it, a page of specks alone was enlarged onto them and came out blank).
// A piece is the speck's when both its ends lie in the speck's box, which is under 5 px across.
std::vector<Piece> pieces_the_screen_draws(std::vector<Piece> pieces, const MergeOptions& merge, double width_px) {
    std::vector<std::array<glm::dvec2, 2>> unseen;  // the boxes of the strokes left out
    for (const Polyline& line : chain_edges(merge_segments(pieces, merge))) {
        if (stroke_inks_a_pixel(line, width_px) || line.points.empty()) continue;
        glm::dvec2 lo = line.points.front(), hi = lo;
        for (const glm::dvec2& p : line.points) lo = glm::min(lo, p), hi = glm::max(hi, p);
        // Padded by what the merge may move a piece's end (its snap and collinear tolerances): a piece welded or
        // merged into the stroke a little beyond its box was kept, and a speck the screen left blank came out as
        // two marks in the SVG (the bunny at --distance 10000).
        const double pad = merge.snap_px + merge.collinear_px + 1e-6;
        unseen.push_back({lo - pad, hi + pad});
    }
    if (unseen.empty()) return pieces;
    auto inside = [](const glm::dvec2& p, const std::array<glm::dvec2, 2>& box) {
        return glm::all(glm::greaterThanEqual(p, box[0])) && glm::all(glm::lessThanEqual(p, box[1]));
    };
    // A piece the screen inks a pixel of by itself stays (the screen draws the pieces, not the merged strokes).
    std::erase_if(pieces, [&](const Piece& piece) {
        return std::any_of(unseen.begin(), unseen.end(),
                           [&](const std::array<glm::dvec2, 2>& box) { return inside(piece[0], box) && inside(piece[1], box); }) &&
               !stroke_inks_a_pixel(Polyline{{piece[0], piece[1]}, false}, width_px);
    });
    return pieces;
}

// The farthest a stroke's fold may lie from the straight line that replaces it (unfold), in pixels of the frame.
constexpr double kMostFoldPx = 1.5;

// `kind`: Lines or Creases.
PlotLayer line_layer(const Drawing& drawing, const std::vector<Piece>& pieces, uint32_t object, LayerKind kind,
                     const PlotPlan& plan, const ExportOptions& options, glm::dvec2& pen) {
    PlotLayer layer;
    layer.number = 3 * object + (kind == LayerKind::Lines ? 2 : 3);
    layer.label = layer_label(layer.number, drawing, object, kind);
    layer.object = object;
    layer.ink = drawing.objects[object].ink.value_or(drawing.ink);
    layer.kind = kind;
    layer.stroke_mm = options.pen_width_mm.value_or(line_width_px(drawing, object, kind) * plan.layout.mm_per_px);
    // Welded and merged in pixels (the frame's precision), simplified in millimetres (the pen's).
    // A fold within the stroke's own width is drawn once (unfold): half the width, and the merge's
    // tolerance for where the frame put each piece. The width is the screen's line where the pen is finer: a
    // contour zig-zagging within the screen's band (a noisy scan's rim) is one stroke there, and a pen of
    // 0.3 mm went back and forth over 2 mm of the bunny's six times (37 such folds on its page).
    // At most kMostFoldPx from the stroke, though: a wide line's own width let its curves straighten (a contour's
    // U a few pixels across under a 12-px line came out as a bar with a knob, its ink up to 6 px off the screen's).
    const double band_px = std::max(layer.stroke_mm / plan.layout.mm_per_px, double(line_width_px(drawing, object, kind)));
    const double fold_px = std::min(0.5 * band_px, kMostFoldPx) + options.merge.collinear_px;
    for (Polyline line : chain_edges(merge_segments(pieces, options.merge))) {
        line = unfold(line, fold_px);
        for (glm::dvec2& p : line.points) p = plan.layout.to_mm(p);
        layer.lines.push_back(options.simplify_mm > 0.0 ? simplify(line, options.simplify_mm) : std::move(line));
    }
    if (options.plotter_order) {
        // Folded where strokes meet within the same bound as above (a 12-px line's strokes welded and unfolded within
        // half its width took its curves straight too).
        const double fold_mm = fold_px * plan.layout.mm_per_px;
        weld_touching_strokes(layer.lines, layer.stroke_mm, fold_mm);
        order_polylines(layer.lines, pen);
        // Where a contour's visible pieces meet with a gap narrower than the pen, one stroke: the pen was
        // lifted and set down again within its own width (the bunny's contours at 800 x 640: 106 of 179
        // strokes began that close to where the last ended).
        join_close_strokes(layer.lines, layer.stroke_mm, fold_mm);
    } else if (!layer.lines.empty()) pen = layer.lines.back().closed ? layer.lines.back().points.front() : layer.lines.back().points.back();
    return layer;
}

}  // namespace

PlotPlan make_plot_plan(const Drawing& drawing, const ExportOptions& options) {
    if (options.pen_width_mm && !(*options.pen_width_mm > 0.0 && *options.pen_width_mm < 100.0))
        fail("--pen-width " + std::to_string(*options.pen_width_mm) + ": must be a positive width in millimetres");
    PlotPlan plan;
    plan.dot_style = options.dot_style;
    plan.ink = drawing.ink;
    plan.paper = drawing.paper;
    plan.fill_paper = options.fill_paper;
    plan.show_travel = options.show_travel;

    const uint32_t objects = static_cast<uint32_t>(drawing.objects.size());
    std::vector<std::vector<uint32_t>> dots_of(objects), segments_of(objects), creases_of(objects);
    for (uint32_t i = 0; i < drawing.dots.size(); ++i) {
        const Dot& dot = drawing.dots[i];
        if (dot.object >= objects)
            fail("export: dot " + std::to_string(i) + " belongs to object " + std::to_string(dot.object) + " of " + std::to_string(objects));
        // A dot of no intensity or no size leaves no ink; one at no finite place cannot be drawn.
        if (dot.intensity > 0.0f && dot.radius_px > 0.0f && finite(dot.px) && in_frame(dot.px, drawing.width_px, drawing.height_px))
            dots_of[dot.object].push_back(i);
    }
    for (uint32_t i = 0; i < drawing.segments.size(); ++i) {
        const Segment& segment = drawing.segments[i];
        if (segment.object >= objects)
            fail("export: line segment " + std::to_string(i) + " belongs to object " + std::to_string(segment.object) + " of " +
                 std::to_string(objects));
        (segment.kind == LineKind::Crease ? creases_of : segments_of)[segment.object].push_back(i);
    }
    std::vector<std::vector<Piece>> line_pieces(objects), crease_pieces(objects);
    for (uint32_t object = 0; object < objects; ++object) {
        line_pieces[object] = pieces_the_screen_draws(pieces_in_frame(drawing, segments_of[object]), options.merge,
                                                      line_width_px(drawing, object, LayerKind::Lines));
        crease_pieces[object] = pieces_the_screen_draws(pieces_in_frame(drawing, creases_of[object]), options.merge,
                                                        line_width_px(drawing, object, LayerKind::Creases));
    }

    const double dot_pen = options.pen_width_mm.value_or(kDefaultPenWidthMm);
    std::optional<PageLayout> fitted;
    if (options.fit == Fit::Drawing) {
        FitMarks marks;
        marks.dot_style = options.dot_style;
        marks.dot_pen_mm = dot_pen;
        marks.line_pen_mm = options.pen_width_mm.value_or(0.0);
        for (uint32_t object = 0; object < objects; ++object) {
            for (const uint32_t i : dots_of[object]) {
                marks.dot_px.push_back(glm::dvec2(drawing.dots[i].px));
                marks.dot_ink_px.push_back(ink_radius_px(drawing.dots[i]));
            }
            for (const LayerKind kind : {LayerKind::Lines, LayerKind::Creases})
                for (const Piece& piece : kind == LayerKind::Lines ? line_pieces[object] : crease_pieces[object])
                    for (const glm::dvec2& end : piece) {
                        marks.line_px.push_back(end);
                        marks.line_half_px.push_back(options.pen_width_mm ? 0.0 : 0.5 * line_width_px(drawing, object, kind));
                    }
        }
        fitted = fit_marks(marks, glm::dvec2(drawing.width_px, drawing.height_px), options.page, options.margin_mm);
    }
    // Nothing drawn (or the frame asked for): the frame, as the screen shows it.
    plan.fit = fitted ? Fit::Drawing : Fit::Frame;
    plan.layout = fitted ? *fitted
                         : fit_to_page(oriented_for(options.page, drawing.width_px, drawing.height_px), options.margin_mm,
                                       drawing.width_px, drawing.height_px);

    glm::dvec2 pen = plan.home;
    for (uint32_t object = 0; object < objects; ++object) {
        if (!dots_of[object].empty()) {
            PlotLayer dots = stipple_layer(drawing, dots_of[object], object, plan, dot_pen, options.plotter_order, pen);
            if (!dots.dots.empty()) plan.layers.push_back(std::move(dots));  // all under the pen's mark, none drawn: no layer
        }
        for (const LayerKind kind : {LayerKind::Lines, LayerKind::Creases}) {
            const std::vector<Piece>& pieces = kind == LayerKind::Lines ? line_pieces[object] : crease_pieces[object];
            if (pieces.empty()) continue;
            PlotLayer lines = line_layer(drawing, pieces, object, kind, plan, options, pen);
            if (!lines.lines.empty()) plan.layers.push_back(std::move(lines));
        }
    }
    return plan;
}

}  // namespace stipple::plot
