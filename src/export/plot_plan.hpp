#pragma once
// A Drawing laid out on a page and put in plotter order: what the SVG, PDF and CSV writers and
// the statistics read.
//
// Layers: one per object and kind, stipples, outline lines then creases, numbered 3k+1, 3k+2 and 3k+3 for
// object k (the numbers stay the same whichever layers are empty; empty layers are left out), labelled
// "<number> <object name> stipples|lines|creases" as the AxiDraw driver expects. Everything is in
// millimetres on the page (see page.hpp). The pen starts at the page's top-left corner (a
// plotter's home) and visits the layers in number order; within a layer the dots follow
// dot_order.hpp and the strokes polyline_order.hpp, each starting where the pen is.
//
// Fractional dots: pens cannot draw half-opaque ink, so a dot of intensity i (the paper's last,
// fractional stipple of a polygon, or a faded one) is drawn at full ink with radius r * sqrt(i):
// the same ink area, hence the same tone, as the screen's dot of radius r at opacity i.
//
// Dots under the pen's least mark: a plotter's pen cannot make a circle or a tick smaller than its own
// width allows (least_mark_radius), and drawn at that size a dot of less ink darkened the highlights (on
// the bunny with a 0.3-mm pen, 2,594 of 19,752 dots; a highlight came out 2.8 times as dark as the filled
// page). Such a dot is drawn as the least mark with the chance of its share of that mark's ink, decided by
// a hash of the dot, as the paper's probabilistic polygon selection does for polygons under a stipple's
// area (§2.3): the same ink in expectation. Filled dots are drawn at any size.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "export/drawing.hpp"
#include "export/page.hpp"
#include "export/polylines.hpp"
#include "export/segment_merge.hpp"

namespace stipple::plot {

// How dots are drawn. Filled: a filled circle (print, PDF). Circle: a stroked circle whose ink
// reaches the dot's radius (plotters). Tick: a short round-capped stroke the pen draws without
// stopping, as long as gives the dot's ink area (plotters; fastest).
enum class DotStyle { Filled, Circle, Tick };
DotStyle parse_dot_style(const std::string& name);  // "filled" | "circle" | "tick"
const char* dot_style_name(DotStyle style);

constexpr double kDefaultPenWidthMm = 0.3;

// What is fitted inside the page's margins. Drawing: the box of what is drawn (the dots' and the lines'
// ink), so the object fills the page as a print should. Frame: the whole frame, empty paper included
// (the page as the screen shows it; frames of a sequence then line up).
enum class Fit { Drawing, Frame };
Fit parse_fit(const std::string& name);  // "drawing" | "frame"

struct ExportOptions {
    PageSize page;  // parse_page("A4") by default: its orientation follows what is fitted (oriented_for)
    double margin_mm = 10.0;
    Fit fit = Fit::Drawing;
    // The pen: the stroke of the lines and of circle and tick dots. Absent: the lines keep the
    // width the frame drew them with, scaled to the page (so a print matches the screen image),
    // and circle and tick dots use kDefaultPenWidthMm.
    std::optional<double> pen_width_mm;
    DotStyle dot_style = DotStyle::Filled;
    bool fill_paper = false;  // paint the page in the paper colour (print); a plotter's paper is the paper
    bool show_travel = false;  // SVG: add the pen-up moves in light red, in a layer the AxiDraw software does not plot
    bool plotter_order = true;  // false: dots in the order given and strokes as chained (to compare)
    double simplify_mm = 0.05;  // Douglas-Peucker tolerance of the strokes
    MergeOptions merge;         // welding and overlap tolerances, in pixels
};

// Creases have a layer of their own, drawn with a pen of their own width (ObjectParams::crease_weight).
enum class LayerKind { Stipples, Lines, Creases };

struct PlotDot {
    glm::dvec2 mm{0.0};
    double radius_mm = 0.0;  // ink radius: radius_px * mm_per_px * sqrt(intensity)
    uint32_t object = 0, polygon = 0;
    bool reversed = false;  // tick style: drawn right to left, from its end nearer where the pen was
};

struct PlotLayer {
    uint32_t number = 0;
    std::string label;  // "<number> <name> stipples|lines"
    uint32_t object = 0;
    LayerKind kind = LayerKind::Stipples;
    double stroke_mm = 0.0;  // pen width of this layer's strokes (lines, or circle and tick dots)
    glm::vec3 ink{0.0f};     // its pen's colour: its object's ink (a pen per colour on a plotter)
    std::vector<PlotDot> dots;
    std::vector<Polyline> lines;
};

struct PlotPlan {
    PageLayout layout;
    size_t small_dots = 0;  // dots under the pen's least mark, of which those drawn (as it) are in the layers
    Fit fit = Fit::Drawing;  // as asked; Frame where nothing was drawn
    DotStyle dot_style = DotStyle::Filled;
    glm::vec3 ink{0.0f}, paper{1.0f};  // the scene's (each layer draws in its object's ink, PlotLayer::ink)
    bool fill_paper = false;
    bool show_travel = false;
    glm::dvec2 home{0.0};  // where the pen starts
    std::vector<PlotLayer> layers;
};

// Throws stipple::Error for a drawing that cannot be laid out (no size, a dot or segment naming a
// missing object) or a bad option.
PlotPlan make_plot_plan(const Drawing& drawing, const ExportOptions& options);

// The stroked geometry of a dot of ink radius r drawn with a pen of width w:
// Circle style: the centre-line radius, r - w/2 (the ink's outer edge at r), at least w/4.
double circle_stroke_radius(double radius_mm, double pen_mm);
// Tick style: the stroke length L with w*L + pi*w^2/4 = pi*r^2 (the dot's ink area), at least
// kMinTickMm so that every driver lowers the pen, and at most kMaxTickDiameters times the dot's width 2r: a dot
// many pens wide would otherwise be a long dash (a 2.3 mm dot and a 0.3 mm pen made a 13 mm stroke, and the
// page read as hatching; a review, 2026-12-06). A capped tick inks less than its dot (tick_ink_short).
double tick_length(double radius_mm, double pen_mm);
constexpr double kMinTickMm = 0.02;
constexpr double kMaxTickDiameters = 2.0;
// The ink area a capped tick leaves out of its dot's (0 for a tick that carries it all).
double tick_ink_short(double radius_mm, double pen_mm);
// Where the pen goes down for a dot and where it lifts: a tick's two ends (horizontal, through the centre, in
// the order PlotDot::reversed says), a filled disc's or circle's centre (the driver's own start on it).
std::array<glm::dvec2, 2> dot_stroke_ends(const PlotDot& dot, DotStyle style, double pen_mm);
// The ink radius of the least mark a pen of width pen_mm makes for a dot (the radius of a disc of its ink):
// a circle's ring inks no less than a disc of radius 3/4 of the pen (its centre line at pen/4), a tick no
// shorter than kMinTickMm; 0 for filled dots, which are drawn at any size.
double least_mark_radius(DotStyle style, double pen_mm);

}  // namespace stipple::plot
