#pragma once
// --fit drawing: the scale and place at which the marks the pen makes fill the page inside its margins.
//
// Marks are given where the frame drew them, in pixels. A filled dot and a line drawn as wide as the frame
// drew it scale with the drawing; a plotter's dot does not only scale (a circle's ring inks at least a disc
// of radius 3/4 of the pen, a tick is as long as its dot's area asks, which grows with the square of the scale), nor
// does a line drawn with a given pen (0.3 mm on any page). So the scale is the largest at which the box of
// the marks as drawn fits, found by bisection, but at most kMostEnlargement times the scale that fits the
// whole frame (a far object, a few dots in an empty frame, was blown up into discs of 68 mm); the box is
// then centred on the page.
#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "export/page.hpp"
#include "export/plot_plan.hpp"

namespace stipple::plot {

struct FitMarks {
    DotStyle dot_style = DotStyle::Filled;
    double dot_pen_mm = kDefaultPenWidthMm;  // the pen of circle and tick dots
    std::vector<glm::dvec2> dot_px;          // centres
    std::vector<double> dot_ink_px;          // ink radius: radius * sqrt(intensity)
    std::vector<glm::dvec2> line_px;         // both ends of every visible piece of line
    std::vector<double> line_half_px;        // half the frame's width of its line (0 where a pen is given)
    double line_pen_mm = 0.0;                // the given pen, as wide on any page (0: none given)
    bool empty() const { return dot_px.empty() && line_px.empty(); }
};

// Half the width and height, in mm, of the ink of a dot of ink radius `ink_radius_mm` drawn in `style`.
glm::dvec2 dot_reach_mm(double ink_radius_mm, DotStyle style, double pen_mm);

constexpr double kMostEnlargement = 4.0;

// The layout that fills the page (turned as the marks are where its name leaves that open) with the marks of
// a frame of frame_px pixels; nothing when there are none. Throws stipple::Error for a margin that leaves no
// room or marks of the pen alone wider than that room.
std::optional<PageLayout> fit_marks(const FitMarks& marks, glm::dvec2 frame_px, const PageSize& page, double margin_mm);

}  // namespace stipple::plot
