#pragma once
// The page a drawing is exported to, and where the drawing goes on it.
//
// Page names (case-insensitive): A3, A4, A5, letter, legal, or WxHmm (e.g. "300x200mm", decimals
// allowed), each optionally followed by "-portrait" or "-landscape" ("A4-landscape"). Named sizes
// take the drawing's orientation unless told (landscape for a drawing wider than tall: oriented_for);
// WxHmm keeps the given width and height unless an orientation is named, which swaps them where
// needed. An area of the image (the whole frame, or what is drawn: ExportOptions::fit) is fitted
// inside the margins with one uniform scale and centred; from there on every coordinate of the
// export is in millimetres, origin at the page's top-left corner, y down (as in SVG and as cairo is
// set up).
#include <string>

#include <glm/vec2.hpp>

namespace stipple::plot {

struct PageSize {
    double width_mm = 210.0, height_mm = 297.0;
    // Whether the name fixed the orientation ("-portrait", "-landscape", or WxHmm): a bare named size
    // follows the drawing (oriented_for).
    bool orientation_given = false;
};

// Parses a page name as above; a bad name throws stipple::Error naming it and the accepted forms.
PageSize parse_page(const std::string& name);

// `page` turned to the drawing's orientation where its name left that open: landscape for a drawing
// wider than tall, portrait otherwise. A page whose orientation was given is returned as it is.
PageSize oriented_for(PageSize page, double width, double height);

// Where the image lands: page_mm = offset_mm + px * mm_per_px.
struct PageLayout {
    PageSize page;
    double margin_mm = 0.0;
    double mm_per_px = 1.0;
    glm::dvec2 offset_mm{0.0};

    glm::dvec2 to_mm(glm::dvec2 px) const { return offset_mm + px * mm_per_px; }
};

// Fits the area [min_px, max_px] of an image inside the margins (uniform scale, centred on the page).
// Throws stipple::Error for an empty area, a negative margin or one that leaves no room.
PageLayout fit_to_page(const PageSize& page, double margin_mm, glm::dvec2 min_px, glm::dvec2 max_px);
// The whole of a width_px x height_px image.
inline PageLayout fit_to_page(const PageSize& page, double margin_mm, double width_px, double height_px) {
    return fit_to_page(page, margin_mm, glm::dvec2(0.0), glm::dvec2(width_px, height_px));
}

constexpr double kPointsPerMm = 72.0 / 25.4;  // PDF user units (points) per millimetre

}  // namespace stipple::plot
