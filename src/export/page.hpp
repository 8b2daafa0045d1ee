#pragma once
// The page a drawing is exported to, and where the drawing goes on it.
//
// Page names (case-insensitive): A3, A4, A5, letter, legal, or WxHmm (e.g. "300x200mm", decimals
// allowed), each optionally followed by "-portrait" or "-landscape" ("A4-landscape"). Named sizes
// are portrait unless told; WxHmm keeps the given width and height unless an orientation is named,
// which swaps them where needed. The image is fitted inside the margins with one uniform scale and
// centred; from there on every coordinate of the export is in millimetres, origin at the page's
// top-left corner, y down (as in SVG and as cairo is set up).
#include <string>

#include <glm/vec2.hpp>

namespace stipple::plot {

struct PageSize {
    double width_mm = 210.0, height_mm = 297.0;
};

// Parses a page name as above; a bad name throws stipple::Error naming it and the accepted forms.
PageSize parse_page(const std::string& name);

// Where the image lands: page_mm = offset_mm + px * mm_per_px.
struct PageLayout {
    PageSize page;
    double margin_mm = 0.0;
    double mm_per_px = 1.0;
    glm::dvec2 offset_mm{0.0};

    glm::dvec2 to_mm(glm::dvec2 px) const { return offset_mm + px * mm_per_px; }
};

// Fits a width_px x height_px image inside the margins (uniform scale, centred). Throws
// stipple::Error for an empty image, a negative margin or one that leaves no room.
PageLayout fit_to_page(const PageSize& page, double margin_mm, double width_px, double height_px);

constexpr double kPointsPerMm = 72.0 / 25.4;  // PDF user units (points) per millimetre

}  // namespace stipple::plot
