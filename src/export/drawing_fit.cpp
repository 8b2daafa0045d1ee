#include "export/drawing_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>

#include "core/error.hpp"

namespace stipple::plot {

namespace {

struct Box {
    glm::dvec2 min{std::numeric_limits<double>::max()}, max{std::numeric_limits<double>::lowest()};
    void add(glm::dvec2 centre, glm::dvec2 reach) {
        min = glm::min(min, centre - reach);
        max = glm::max(max, centre + reach);
    }
    glm::dvec2 size() const { return max - min; }
};

// The marks' box in mm at `mm_per_px` (origin where the frame's is), with the pens' reach; `pens` false
// gives the ink's own extent in pixels (at 1 mm a pixel, no pen), to turn the page by.
Box box_at(const FitMarks& marks, double mm_per_px, bool pens) {
    Box box;
    for (size_t i = 0; i < marks.dot_px.size(); ++i) {
        const double ink = marks.dot_ink_px[i] * mm_per_px;
        box.add(marks.dot_px[i] * mm_per_px, pens ? dot_reach_mm(ink, marks.dot_style, marks.dot_pen_mm) : glm::dvec2(ink));
    }
    for (size_t i = 0; i < marks.line_px.size(); ++i)
        box.add(marks.line_px[i] * mm_per_px, glm::dvec2(marks.line_half_px[i] * mm_per_px + (pens ? 0.5 * marks.line_pen_mm : 0.0)));
    // A single point or hairline still needs an area to scale: at least a pixel each way.
    const glm::dvec2 short_by = glm::max(glm::dvec2(mm_per_px) - box.size(), glm::dvec2(0.0));
    box.min -= 0.5 * short_by;
    box.max += 0.5 * short_by;
    return box;
}

}  // namespace

glm::dvec2 dot_reach_mm(double ink_radius_mm, DotStyle style, double pen_mm) {
    switch (style) {
        case DotStyle::Filled: return glm::dvec2(ink_radius_mm);
        case DotStyle::Circle: return glm::dvec2(circle_stroke_radius(ink_radius_mm, pen_mm) + pen_mm / 2.0);
        case DotStyle::Tick: {
            // Drawn left to right through the centre (svg_writer, pdf_writer); a dot under the least mark is
            // drawn as it (make_plot_plan).
            const double length = tick_length(std::max(ink_radius_mm, least_mark_radius(style, pen_mm)), pen_mm);
            return {length / 2.0 + pen_mm / 2.0, pen_mm / 2.0};
        }
    }
    return glm::dvec2(ink_radius_mm);
}

std::optional<PageLayout> fit_marks(const FitMarks& marks, glm::dvec2 frame_px, const PageSize& page, double margin_mm) {
    if (marks.empty()) return std::nullopt;
    const Box ink = box_at(marks, 1.0, false);
    // The page's room, and the margin's checks, as for any image of the ink's proportions.
    const PageLayout ink_fit = fit_to_page(oriented_for(page, ink.size().x, ink.size().y), margin_mm, ink.min, ink.max);
    const glm::dvec2 room = glm::dvec2(ink_fit.page.width_mm, ink_fit.page.height_mm) - 2.0 * margin_mm;
    const auto fits = [&](double mm_per_px) {
        const glm::dvec2 size = box_at(marks, mm_per_px, true).size();
        return size.x <= room.x && size.y <= room.y;
    };
    // The box grows with the scale: the largest scale that fits, by halving [lo, hi], up to the most enlargement.
    const double most = frame_px.x > 0.0 && frame_px.y > 0.0 ? kMostEnlargement * std::min(room.x / frame_px.x, room.y / frame_px.y)
                                                             : 65536.0 * ink_fit.mm_per_px;
    double lo = 0.0, hi = most;
    if (!fits(hi * 1e-9))
        fail("the dots and lines as the pen draws them do not fit the page's room inside the margins (" +
             std::to_string(int(room.x)) + " x " + std::to_string(int(room.y)) + " mm): a finer --pen-width or a smaller --margin");
    if (fits(hi)) lo = hi;
    else if (ink_fit.mm_per_px < hi && fits(ink_fit.mm_per_px)) lo = ink_fit.mm_per_px;  // a start near the answer
    for (int step = 0; step < 48 && hi - lo > 1e-12 * hi; ++step) {
        const double mid = 0.5 * (lo + hi);
        (fits(mid) ? lo : hi) = mid;
    }
    if (!(lo > 0.0)) lo = hi * 1e-9;
    PageLayout layout;
    layout.page = ink_fit.page;
    layout.margin_mm = margin_mm;
    layout.mm_per_px = lo;
    const Box box = box_at(marks, lo, true);
    layout.offset_mm = glm::dvec2(layout.page.width_mm, layout.page.height_mm) / 2.0 - 0.5 * (box.min + box.max);
    return layout;
}

}  // namespace stipple::plot
