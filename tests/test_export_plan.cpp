// The plot plan (layers, fractional dots, the pen's path), the CSV of its dots, the statistics
// `--stats` prints, and writing by extension.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include <glm/geometric.hpp>

#include "export/csv_writer.hpp"
#include "export/drawing_fit.hpp"
#include "export/plot_file.hpp"
#include "export/plot_plan.hpp"
#include "export/plot_stats.hpp"
#include "export/polylines.hpp"
#include "support/export_helpers.hpp"
#include "support/test_paths.hpp"

namespace {

using namespace stipple::plot;
using stipple::test::grid_drawing;

// Three layers an object, numbered whether or not each has anything (a layer keeps its number from drawing
// to drawing): stipples, outline, creases. Creases are drawn with their own pen width, the frame's
// crease width where no pen is given, and with the one pen where one is.
TEST(ExportPlan, LayersNumberedPerObjectAndKind) {
    Drawing drawing = grid_drawing(3, 3);
    // Object 0 ("cube") keeps only its lines, a square outline and a crease across it; object 1 ("",
    // unnamed) has dots only.
    drawing.objects[0].crease_width_px = 0.5f;
    drawing.segments.push_back({{250, 150}, {350, 150}, 0, LineKind::Crease});
    drawing.objects.push_back({"", 1.0f});
    for (Dot& dot : drawing.dots) dot.object = 1;
    const PlotPlan plan = make_plot_plan(drawing, {});
    ASSERT_EQ(plan.layers.size(), 3u);
    EXPECT_EQ(plan.layers[0].label, "2 cube lines");
    EXPECT_EQ(plan.layers[0].kind, LayerKind::Lines);
    EXPECT_EQ(plan.layers[0].lines.size(), 1u) << "the square outline alone";
    EXPECT_EQ(plan.layers[1].label, "3 cube creases");
    EXPECT_EQ(plan.layers[1].kind, LayerKind::Creases);
    ASSERT_EQ(plan.layers[1].lines.size(), 1u) << "the crease alone";
    EXPECT_NEAR(polyline_length(plan.layers[0].lines[0]), 400.0 * plan.layout.mm_per_px, 1e-6);
    EXPECT_NEAR(polyline_length(plan.layers[1].lines[0]), 100.0 * plan.layout.mm_per_px, 1e-6);
    EXPECT_NEAR(plan.layers[0].stroke_mm, 2.0 * plan.layout.mm_per_px, 1e-9);
    EXPECT_NEAR(plan.layers[1].stroke_mm, 0.5 * plan.layout.mm_per_px, 1e-9);
    EXPECT_EQ(plan.layers[2].label, "4 object2 stipples");
    EXPECT_EQ(plan.layers[2].dots.size(), 9u);
    ExportOptions one_pen;
    one_pen.pen_width_mm = 0.3;
    const PlotPlan pen = make_plot_plan(drawing, one_pen);
    ASSERT_EQ(pen.layers.size(), 3u);
    EXPECT_EQ(pen.layers[0].stroke_mm, 0.3);
    EXPECT_EQ(pen.layers[1].stroke_mm, 0.3);
}

// The default fit: the box of what is drawn (each dot to its ink radius, each line to half its width) fills
// the page inside the margins, on a page turned as that box is; --fit frame lays out the whole frame.
TEST(ExportPlan, TheDrawingFillsThePageInsideItsMargins) {
    Drawing drawing;
    drawing.width_px = 500;
    drawing.height_px = 500;
    drawing.objects.push_back({"wide", 2.0f});
    // Dots from x 150 to 350 at y 200 and 300, ink radius 2 * sqrt(0.25) = 1; a line at y 310, 2 px wide.
    for (int x = 150; x <= 350; x += 20)
        for (int y : {200, 300}) drawing.dots.push_back({glm::vec2(float(x), float(y)), 2.0f, 0.25f, 0, 0});
    drawing.segments.push_back({{200.0f, 310.0f}, {300.0f, 310.0f}, 0, LineKind::Contour});
    ExportOptions options;  // A4, 10 mm margins, fit the drawing
    const PlotPlan plan = make_plot_plan(drawing, options);
    EXPECT_EQ(plan.fit, Fit::Drawing);
    EXPECT_DOUBLE_EQ(plan.layout.page.width_mm, 297.0) << "a box wider than tall: landscape";
    // The box: x 149..351 (202 px), y 199..311 (112 px); 277 / 202 < 190 / 112, so the width limits.
    EXPECT_NEAR(plan.layout.mm_per_px, 277.0 / 202.0, 1e-9);
    double left = 1e9, right = -1e9;
    for (const PlotDot& dot : plan.layers[0].dots) {
        left = std::min(left, dot.mm.x - dot.radius_mm);
        right = std::max(right, dot.mm.x + dot.radius_mm);
    }
    EXPECT_NEAR(left, 10.0, 1e-6);
    EXPECT_NEAR(right, 287.0, 1e-6);
    EXPECT_NEAR(plan.layout.to_mm({250.0, 255.0}).y, 105.0, 1e-9) << "centred on the page";

    options.fit = Fit::Frame;
    const PlotPlan frame = make_plot_plan(drawing, options);
    EXPECT_EQ(frame.fit, Fit::Frame);
    EXPECT_DOUBLE_EQ(frame.layout.page.width_mm, 210.0) << "a square frame: portrait";
    EXPECT_NEAR(frame.layout.mm_per_px, 190.0 / 500.0, 1e-12);

    // A few dots in an empty frame are enlarged at most kMostEnlargement times the frame's own scale (they
    // were blown up into discs of 68 mm).
    Drawing far = drawing;
    far.dots.resize(2);
    far.segments.clear();
    options.fit = Fit::Drawing;
    const PlotPlan few = make_plot_plan(far, options);
    EXPECT_EQ(few.fit, Fit::Drawing);
    EXPECT_NEAR(few.layout.mm_per_px, kMostEnlargement * std::min(few.layout.page.width_mm - 20.0, few.layout.page.height_mm - 20.0) / 500.0,
                1e-9);

    Drawing empty = drawing;
    empty.dots.clear();
    empty.segments.clear();
    options.fit = Fit::Drawing;
    const PlotPlan blank = make_plot_plan(empty, options);
    EXPECT_EQ(blank.fit, Fit::Frame) << "nothing drawn: the frame's page";
    EXPECT_NEAR(blank.layout.mm_per_px, 190.0 / 500.0, 1e-12);
    EXPECT_TRUE(blank.layers.empty());
}

// A stroke the screen draws no pixel of (no pixel centre within half its width, as line_pieces.frag keeps
// them: an object far away whose contour is a speck) is left out; one that inks a pixel is kept however short.
TEST(ExportPlan, AStrokeTheScreenDrawsNoPixelOfIsLeftOut) {
    Drawing drawing;
    drawing.width_px = 40;
    drawing.height_px = 30;
    drawing.objects.push_back({"speck", 1.0f});  // lines 1 px wide
    drawing.segments.push_back({glm::vec2(10.0f, 10.0f), glm::vec2(10.2f, 10.0f), 0, LineKind::Contour});  // centre 0.58 away
    ExportOptions options;
    options.margin_mm = 0.0;
    options.fit = Fit::Frame;
    EXPECT_TRUE(make_plot_plan(drawing, options).layers.empty()) << "nothing on the screen, nothing on the page";
    // Fitted to the drawing, the page is not fitted around the speck: nothing is drawn, so the frame's page.
    options.fit = Fit::Drawing;
    EXPECT_EQ(make_plot_plan(drawing, options).fit, Fit::Frame);
    options.fit = Fit::Frame;
    // A speck's pieces that the merge welds or folds into a stroke a little beyond the stroke's own box are left
    // out with it: they were kept, and the bunny at --distance 10000 drew a blank screen and two marks in its
    // SVG. The first 1,100 of its contour's visible pieces that frame (640 x 512, about a thousandth of a pixel
    // each, around the frame's centre), as the GPU's walk wrote them: with the boxes padded by 1e-6 px they left
    // a stroke (with 900, none).
    Drawing speck;
    speck.width_px = 640;
    speck.height_px = 512;
    speck.objects.push_back({"bunny", 1.0f});
    std::ifstream file(stipple::test::source_path("tests/data/speck_pieces.txt"));
    for (float ax, ay, bx, by; file >> ax >> ay >> bx >> by;)
        speck.segments.push_back({glm::vec2(ax, ay), glm::vec2(bx, by), 0, LineKind::Contour});
    ASSERT_GT(speck.segments.size(), 1000u);
    EXPECT_TRUE(make_plot_plan(speck, options).layers.empty()) << "the bunny's speck is left out whole";
    drawing.segments.push_back({glm::vec2(20.3f, 20.3f), glm::vec2(20.4f, 20.4f), 0, LineKind::Contour});  // 0.14 away
    const PlotPlan plan = make_plot_plan(drawing, options);
    size_t lines = 0;
    for (const PlotLayer& layer : plan.layers) lines += layer.lines.size();
    EXPECT_EQ(lines, 1u) << "the stroke over a pixel's centre is kept";
}

// A contour zig-zagging back and forth within half the screen's line, at most 1.5 px (a noisy scan's rim seen
// edge-on), is one stroke on the page even with a pen finer than that line: a 0.3 mm pen went back and forth
// over 2 mm of the bunny's rim six times. A zig-zag wider than that is drawn as it is, so that a wide line's
// curves keep their shape (AWideLinesTurnsAreKept).
TEST(ExportPlan, AZigZagWithinTheScreensLineIsOneStroke) {
    // Sideways, in pixels, against a line 4 px wide on the screen: 10 px puts the turns 1.96 px from the straight
    // line through them, within half the line (2 px) but beyond the 1.5 px bound.
    for (const float spread : {1.5f, 10.0f, 20.0f}) {
        Drawing drawing;
        drawing.width_px = 200;
        drawing.height_px = 100;
        drawing.objects.push_back({"rim", 4.0f});
        // 100 -> 140 -> 110 -> 150 -> 120 along x, each leg shifted sideways by `spread`.
        const float xs[] = {100, 140, 110, 150, 120};
        for (int i = 0; i + 1 < 5; ++i)
            drawing.segments.push_back({glm::vec2(xs[i], 50.0f + (i % 2) * spread), glm::vec2(xs[i + 1], 50.0f + ((i + 1) % 2) * spread),
                                        0, LineKind::Contour});
        ExportOptions options;
        options.margin_mm = 0.0;
        options.fit = Fit::Frame;
        options.pen_width_mm = 0.3;
        const PlotPlan plan = make_plot_plan(drawing, options);
        ASSERT_FALSE(plan.layers.empty());
        double drawn_px = 0.0;
        for (const PlotLayer& layer : plan.layers)
            for (const Polyline& line : layer.lines) drawn_px += polyline_length(line) / plan.layout.mm_per_px;
        if (spread < 2.0f)
            EXPECT_LT(drawn_px, 60.0) << "one stroke over the 50 px the zig-zag covers, not its 150";
        else
            EXPECT_GT(drawn_px, 140.0) << "a zig-zag wider than the screen's line is drawn whole";
    }
}

// A wide line's stroke keeps its shape: a contour turning back 4 px beside itself under a 12-px line was cut
// to its first arm (the fold allowed was half the line's width), a bar with a knob where the screen drew a U.
TEST(ExportPlan, AWideLinesTurnsAreKept) {
    Drawing drawing;
    drawing.width_px = 200;
    drawing.height_px = 100;
    drawing.objects.push_back({"u", 12.0f});
    drawing.segments.push_back({glm::vec2(100.0f, 50.0f), glm::vec2(120.0f, 50.0f), 0, LineKind::Contour});
    drawing.segments.push_back({glm::vec2(120.0f, 50.0f), glm::vec2(100.0f, 54.0f), 0, LineKind::Contour});
    ExportOptions options;
    options.margin_mm = 0.0;
    options.fit = Fit::Frame;
    const PlotPlan plan = make_plot_plan(drawing, options);
    double drawn_px = 0.0;
    for (const PlotLayer& layer : plan.layers)
        for (const Polyline& line : layer.lines) drawn_px += polyline_length(line) / plan.layout.mm_per_px;
    EXPECT_NEAR(drawn_px, 20.0 + std::hypot(20.0, 4.0), 0.5) << "both arms";
}

// The page holds the frame: a dot centred beyond the image's edge is left out, and a line piece that
// reaches past the edge (the GPU's runs may, by a few pixels) is cut at it; with no margin both ran off
// the paper.
TEST(ExportPlan, NothingLeavesTheFrame) {
    Drawing drawing = grid_drawing(1, 1);  // one dot at (50, 50), a square from (250, 100) to (350, 200)
    drawing.dots.push_back({glm::vec2(-0.5f, 10.0f), 1.5f, 1.0f, 0, 7});
    drawing.dots.push_back({glm::vec2(120.0f, 300.4f), 1.5f, 1.0f, 0, 8});
    drawing.dots.push_back({glm::vec2(400.0f, 0.0f), 1.5f, 1.0f, 0, 9});  // on the corner: in
    drawing.segments.push_back({glm::vec2(-3.0f, 10.0f), glm::vec2(50.0f, 10.0f), 0, LineKind::Border});
    drawing.segments.push_back({glm::vec2(-3.0f, -1.0f), glm::vec2(-1.0f, 500.0f), 0, LineKind::Border});  // all outside
    drawing.segments.push_back({glm::vec2(390.0f, 290.0f), glm::vec2(410.0f, 310.0f), 0, LineKind::Border});
    ExportOptions options;
    options.margin_mm = 0.0;
    options.simplify_mm = 0.0;
    const PlotPlan plan = make_plot_plan(drawing, options);
    size_t dots = 0;
    glm::dvec2 lo(1e30), hi(-1e30);
    for (const PlotLayer& layer : plan.layers) {
        dots += layer.dots.size();
        for (const PlotDot& dot : layer.dots) lo = glm::min(lo, dot.mm), hi = glm::max(hi, dot.mm);
        for (const Polyline& line : layer.lines)
            for (const glm::dvec2& p : line.points) lo = glm::min(lo, p), hi = glm::max(hi, p);
    }
    EXPECT_EQ(dots, 2u) << "the dots at (50, 50) and on the corner";
    const glm::dvec2 frame_lo = plan.layout.to_mm({0.0, 0.0}), frame_hi = plan.layout.to_mm({400.0, 300.0});
    EXPECT_GE(lo.x, frame_lo.x - 1e-9);
    EXPECT_GE(lo.y, frame_lo.y - 1e-9);
    EXPECT_LE(hi.x, frame_hi.x + 1e-9);
    EXPECT_LE(hi.y, frame_hi.y + 1e-9);
    EXPECT_NEAR(lo.x, frame_lo.x, 1e-9) << "the piece from x = -3 is cut at the edge, not dropped";
    EXPECT_NEAR(hi.x, frame_hi.x, 1e-9) << "the piece to (410, 310) is cut at the corner";
}

TEST(ExportPlan, FractionalDotsKeepTheirInkArea) {
    Drawing drawing = grid_drawing(2, 1);
    drawing.dots[0].intensity = 0.25f;
    drawing.dots[1].intensity = 1.0f;
    drawing.dots.push_back({glm::vec2(10.0f, 10.0f), 1.5f, 0.0f, 0, 0});    // no intensity: no dot
    drawing.dots.push_back({glm::vec2(NAN, 10.0f), 1.5f, 1.0f, 0, 0});     // nowhere: no dot
    ExportOptions options;
    options.plotter_order = false;
    const PlotPlan plan = make_plot_plan(drawing, options);
    ASSERT_EQ(plan.layers[0].dots.size(), 2u);
    const double full = 1.5 * plan.layout.mm_per_px;
    EXPECT_NEAR(plan.layers[0].dots[0].radius_mm, full * 0.5, 1e-12);  // sqrt(0.25): a quarter of the area
    EXPECT_NEAR(plan.layers[0].dots[1].radius_mm, full, 1e-12);
    EXPECT_EQ(plan.layers[0].dots[0].polygon, 0u);
    EXPECT_EQ(plan.layers[0].dots[1].polygon, 1u);
}

TEST(ExportPlan, DotStrokeGeometry) {
    // A tick's round-capped stroke has the dot's ink area.
    const double r = 0.4, pen = 0.3, length = tick_length(r, pen);
    EXPECT_NEAR(pen * length + std::numbers::pi * pen * pen / 4.0, std::numbers::pi * r * r, 1e-12);
    EXPECT_DOUBLE_EQ(tick_length(0.1, 0.3), kMinTickMm);  // a dot smaller than the pen: the shortest tick
    EXPECT_DOUBLE_EQ(tick_ink_short(r, pen), 0.0);
    // Short exactly when the length is capped, for every radius (the areas alone differ in their last bits).
    for (double radius = 0.01; radius < 3.0; radius *= 1.01)
        for (const double w : {0.05, 0.3, 0.8, 1.2})
            EXPECT_EQ(tick_ink_short(radius, w) > 0.0,
                      std::numbers::pi * (radius * radius - w * w / 4.0) / w > kMaxTickDiameters * 2.0 * radius)
                << radius << " mm, pen " << w;
    // A dot many pens wide: its tick no longer than twice its width (the ink-keeping one would be 13.4 mm for
    // this 2.27 mm dot), and what it leaves out of the dot's ink said.
    const double wide = 1.134;
    EXPECT_DOUBLE_EQ(tick_length(wide, pen), kMaxTickDiameters * 2.0 * wide);
    EXPECT_NEAR(tick_ink_short(wide, pen), std::numbers::pi * wide * wide - pen * 4.0 * wide - std::numbers::pi * pen * pen / 4.0, 1e-12);
    EXPECT_DOUBLE_EQ(circle_stroke_radius(0.4, 0.3), 0.25);
    EXPECT_DOUBLE_EQ(circle_stroke_radius(0.1, 0.3), 0.075);
    EXPECT_EQ(parse_dot_style("tick"), DotStyle::Tick);
    EXPECT_EQ(parse_dot_style("Filled"), DotStyle::Filled) << "names in any case, as --page's";
    EXPECT_EQ(parse_fit("Drawing"), Fit::Drawing);
    EXPECT_EQ(parse_fit("frame"), Fit::Frame);
    stipple::test::expect_plot_error([] { parse_fit("page"); }, "--fit 'page': expected drawing or frame");
    stipple::test::expect_plot_error([] { parse_dot_style("square"); }, "--dot-style 'square'");
}

// A plotter's pen cannot make a circle or a tick smaller than its width allows: a dot of less ink is drawn
// as that least mark with the chance of its share of the mark's ink (the same ink in expectation), where
// drawing every one at that size darkened the highlights. Filled dots are drawn at any size.
TEST(ExportPlan, DotsUnderThePensLeastMarkAreDrawnAsItByChance) {
    Drawing drawing;
    drawing.width_px = 400;
    drawing.height_px = 300;
    drawing.objects.push_back({"tiny", 1.0f});
    for (int y = 0; y < 60; ++y)
        for (int x = 0; x < 80; ++x)
            drawing.dots.push_back({glm::vec2(5.0f * x + 2.5f, 5.0f * y + 2.5f), 0.1f, 1.0f, 0, uint32_t(y * 80 + x)});
    ExportOptions options;
    options.page = parse_page("400x300mm");
    options.margin_mm = 0.0;
    options.fit = Fit::Frame;  // 1 mm a pixel: dots of 0.1 mm
    options.pen_width_mm = 0.3;
    const double all_ink = 4800.0 * std::numbers::pi * 0.01;
    for (const DotStyle style : {DotStyle::Circle, DotStyle::Tick}) {
        options.dot_style = style;
        const double least = least_mark_radius(style, 0.3);
        const PlotPlan plan = make_plot_plan(drawing, options);
        ASSERT_EQ(plan.layers.size(), 1u);
        const PlotLayer& layer = plan.layers[0];
        EXPECT_EQ(plan.small_dots, 4800u);
        for (const PlotDot& dot : layer.dots) EXPECT_DOUBLE_EQ(dot.radius_mm, least);
        const double drawn_ink = double(layer.dots.size()) * std::numbers::pi * least * least;
        std::printf("%s: least mark %.3f mm, %zu of 4800 dots drawn, ink %.3f of the dots'\n", dot_style_name(style), least,
                    layer.dots.size(), drawn_ink / all_ink);
        EXPECT_NEAR(drawn_ink / all_ink, 1.0, 0.1);
        EXPECT_LT(layer.dots.size(), 4800u / 2);
        EXPECT_EQ(make_plot_plan(drawing, options).layers[0].dots.size(), layer.dots.size()) << "the same every time";
        EXPECT_NE(format_stats(plot_stats(plan)).find("4800 dots under the pen's least mark"), std::string::npos);
    }
    // The least marks themselves: a circle's ring at its smallest inks a disc of radius 3/4 of the pen; a tick at
    // its shortest inks kMinTickMm of the pen and its round caps.
    EXPECT_DOUBLE_EQ(least_mark_radius(DotStyle::Circle, 0.4), 0.3);
    EXPECT_NEAR(tick_length(least_mark_radius(DotStyle::Tick, 0.3), 0.3), kMinTickMm, 1e-12);
    options.dot_style = DotStyle::Filled;
    EXPECT_EQ(make_plot_plan(drawing, options).layers[0].dots.size(), 4800u);
}

// Dots many pens wide as ticks: each at its longest, twice its dot's width, and the ink left out said (a 13 mm
// dash for a 2.3 mm dot read as hatching, until 2026-12-06).
TEST(ExportPlan, WideDotsAsTicksAreCappedAndTheInkLeftOutIsSaid) {
    Drawing drawing;
    drawing.width_px = 100;
    drawing.height_px = 100;
    drawing.objects.push_back({"wide", 1.0f});
    for (int i = 0; i < 10; ++i) drawing.dots.push_back({glm::vec2(10.0f * i + 5.0f, 50.0f), 1.0f, 1.0f, 0, uint32_t(i)});
    ExportOptions options;
    options.page = parse_page("100x100mm");
    options.margin_mm = 0.0;
    options.fit = Fit::Frame;
    options.pen_width_mm = 0.3;
    options.dot_style = DotStyle::Tick;
    const PlotPlan plan = make_plot_plan(drawing, options);
    ASSERT_EQ(plan.layers.size(), 1u);
    ASSERT_EQ(plan.layers[0].dots.size(), 10u);
    const double r = plan.layers[0].dots[0].radius_mm;
    ASSERT_GT(r, 0.3);
    const std::array<glm::dvec2, 2> ends = dot_stroke_ends(plan.layers[0].dots[0], DotStyle::Tick, 0.3);
    EXPECT_NEAR(glm::length(ends[1] - ends[0]), 4.0 * r, 1e-9) << "twice the dot's width";
    const PlotStats stats = plot_stats(plan);
    EXPECT_EQ(stats.capped_ticks, 10u);
    const double kept = (0.3 * 4.0 * r + std::numbers::pi * 0.09 / 4.0) / (std::numbers::pi * r * r);
    EXPECT_NEAR(stats.tick_ink_short, 1.0 - kept, 1e-9);
    EXPECT_NE(format_stats(stats).find("10 ticks at their longest"), std::string::npos) << format_stats(stats);
    options.dot_style = DotStyle::Filled;
    EXPECT_EQ(plot_stats(make_plot_plan(drawing, options)).capped_ticks, 0u);
}

// The marks as the pen draws them stay inside the margins: a tick is as long as its dot's ink asks and a
// given pen is as wide on any page, where fitting the dots' ink alone ran ticks off a page without margin.
TEST(ExportPlan, ThePensMarksStayInsideTheMargins) {
    Drawing drawing = grid_drawing(5, 4);
    for (Dot& dot : drawing.dots) dot.radius_px = 3.0f;
    for (const double margin : {0.0, 10.0}) {
        ExportOptions options;
        options.margin_mm = margin;
        options.dot_style = DotStyle::Tick;
        options.pen_width_mm = 2.0;
        const PlotPlan plan = make_plot_plan(drawing, options);
        double left = 1e9, right = -1e9, top = 1e9, bottom = -1e9;
        for (const PlotLayer& layer : plan.layers) {
            for (const PlotDot& dot : layer.dots) {
                const double half = tick_length(dot.radius_mm, layer.stroke_mm) / 2.0 + layer.stroke_mm / 2.0;
                left = std::min(left, dot.mm.x - half), right = std::max(right, dot.mm.x + half);
                top = std::min(top, dot.mm.y - layer.stroke_mm / 2.0), bottom = std::max(bottom, dot.mm.y + layer.stroke_mm / 2.0);
            }
            for (const Polyline& line : layer.lines)
                for (const glm::dvec2& p : line.points) {
                    left = std::min(left, p.x - 1.0), right = std::max(right, p.x + 1.0);
                    top = std::min(top, p.y - 1.0), bottom = std::max(bottom, p.y + 1.0);
                }
        }
        const double w = plan.layout.page.width_mm, h = plan.layout.page.height_mm;
        std::printf("margin %.0f: ink from %.3f to %.3f mm across %.0f, %.3f to %.3f down %.0f\n", margin, left, right, w, top,
                    bottom, h);
        EXPECT_GE(left, margin - 1e-6);
        EXPECT_LE(right, w - margin + 1e-6);
        EXPECT_GE(top, margin - 1e-6);
        EXPECT_LE(bottom, h - margin + 1e-6);
        EXPECT_TRUE(std::abs(right - left - (w - 2 * margin)) < 1e-3 || std::abs(bottom - top - (h - 2 * margin)) < 1e-3)
            << "it fills the page's room one way";
    }
}

// The same model twice in a scene: its layers can be told apart.
TEST(ExportPlan, ObjectsOfOneNameHaveLayersOfTheirOwn) {
    Drawing drawing = grid_drawing(2, 2);
    drawing.segments.clear();
    drawing.objects.push_back({"cube", 1.0f});
    drawing.dots.push_back({glm::vec2(20.0f, 20.0f), 1.0f, 1.0f, 1, 0});
    const PlotPlan plan = make_plot_plan(drawing, {});
    ASSERT_EQ(plan.layers.size(), 2u);
    EXPECT_EQ(plan.layers[0].label, "1 cube stipples");
    EXPECT_EQ(plan.layers[1].label, "4 cube (2) stipples");
}

TEST(ExportPlan, BadDrawingsAndOptionsAreErrors) {
    Drawing drawing = grid_drawing(2, 2);
    drawing.dots[3].object = 4;
    stipple::test::expect_plot_error([&] { make_plot_plan(drawing, {}); }, "dot 3 belongs to object 4 of 1");
    drawing = grid_drawing(2, 2);
    drawing.segments[1].object = 2;
    stipple::test::expect_plot_error([&] { make_plot_plan(drawing, {}); }, "line segment 1 belongs to object 2");
    ExportOptions options;
    options.pen_width_mm = -0.3;
    stipple::test::expect_plot_error([&] { make_plot_plan(grid_drawing(), options); }, "--pen-width");
}

TEST(ExportPlan, CsvListsDotsInPlotOrder) {
    const PlotPlan plan = make_plot_plan(grid_drawing(5, 4), {});
    std::istringstream csv(csv_document(plan));
    std::string line;
    std::getline(csv, line);
    EXPECT_EQ(line, "x_mm,y_mm,radius_mm,object,polygon");
    size_t row = 0;
    while (std::getline(csv, line)) {
        ASSERT_LT(row, plan.layers[0].dots.size());
        const PlotDot& dot = plan.layers[0].dots[row++];
        double x, y, r;
        unsigned object, polygon;
        char comma;
        std::istringstream fields(line);
        fields >> x >> comma >> y >> comma >> r >> comma >> object >> comma >> polygon;
        ASSERT_FALSE(fields.fail()) << line;
        EXPECT_NEAR(x, dot.mm.x, 0.0005);
        EXPECT_NEAR(y, dot.mm.y, 0.0005);
        EXPECT_NEAR(r, dot.radius_mm, 0.0005);
        EXPECT_EQ(object, 0u);
        EXPECT_EQ(polygon, dot.polygon);
    }
    EXPECT_EQ(row, 20u);
}

TEST(ExportPlan, StatsOfAKnownPlot) {
    // Home (0,0) -> dots at (10,0) and (20,0) -> a closed 10 mm square from (30,0).
    PlotPlan plan;
    plan.dot_style = DotStyle::Filled;
    PlotLayer dots;
    dots.kind = LayerKind::Stipples;
    dots.dots = {{glm::dvec2(10, 0), 0.5, 0, 0}, {glm::dvec2(20, 0), 0.5, 0, 1}};
    PlotLayer lines;
    lines.kind = LayerKind::Lines;
    lines.lines.push_back({{glm::dvec2(30, 0), glm::dvec2(40, 0), glm::dvec2(40, 10), glm::dvec2(30, 10)}, true});
    plan.layers = {dots, lines};
    const PlotStats stats = plot_stats(plan);
    EXPECT_EQ(stats.dots, 2u);
    EXPECT_EQ(stats.polylines, 1u);
    EXPECT_EQ(stats.pen_lifts, 3u);
    EXPECT_NEAR(stats.pen_up_mm, 30.0, 1e-12);
    EXPECT_NEAR(stats.pen_down_mm, 40.0 + 2 * 2.0 * std::numbers::pi * 0.5, 1e-12);
    EXPECT_NEAR(stats.dot_travel_mm, 10.0, 1e-12);
    EXPECT_NEAR(stats.dot_travel_bound_mm, 10.0, 1e-12);
    EXPECT_NEAR(stats.travel_ratio(), 1.0, 1e-12);
    const std::string text = format_stats(stats);
    EXPECT_EQ(text.find('\n'), std::string::npos);
    EXPECT_NE(text.find("2 dots, 1 polylines, pen down 46.3 mm, pen up 30 mm, 3 pen lifts, travel between dots 1x"), std::string::npos) << text;
    // Lines alone: no travel between dots to rate (it read "1x its lower bound (0 mm)").
    PlotPlan lines_alone = plan;
    lines_alone.layers = {lines};
    const std::string no_dots = format_stats(plot_stats(lines_alone));
    EXPECT_NE(no_dots.find("1 pen lifts, no travel between dots"), std::string::npos) << no_dots;

    // A plan of a real-sized set in plotter order stays within the target; in the given order
    // (row by row, back and forth across the grid) it does not.
    const PlotStats ordered = plot_stats(make_plot_plan(grid_drawing(30, 12), {}));
    EXPECT_LE(ordered.travel_ratio(), 1.05);  // a grid has a perfect path, and the order finds it
    ExportOptions as_given;
    as_given.plotter_order = false;
    EXPECT_GT(plot_stats(make_plot_plan(grid_drawing(30, 12), as_given)).travel_ratio(), 1.5);
}

TEST(ExportPlan, WritesByExtension) {
    const auto dir = stipple::test::temp_dir("export_plot_file");
    const PlotPlan plan = make_plot_plan(grid_drawing(), {});
    EXPECT_TRUE(is_plot_path("a/B.SVG"));
    EXPECT_FALSE(is_plot_path("b.png"));
    for (const char* name : {"d.svg", "d.PDF", "d.csv"}) {
        write_plot_file(plan, (dir / name).string());
        std::ifstream in(dir / name, std::ios::binary);
        std::string head(5, '\0');
        in.read(head.data(), 5);
        EXPECT_EQ(head, std::string(name) == "d.svg" ? "<?xml" : std::string(name) == "d.PDF" ? "%PDF-" : "x_mm,") << name;
    }
    stipple::test::expect_plot_error([&] { write_plot_file(plan, (dir / "d.png").string()); }, "d.png: unknown drawing format '.png'");
}

}  // namespace
