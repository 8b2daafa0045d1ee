#pragma once
// What the export receives: one frame's visible stipples and visible line pieces, in screen pixels.
//
// The renderer fills a Drawing from the GPU frame (the stipples it actually drew, after density,
// fractional intensity, hidden-stipple removal and the toon fade, and the visible parts of the
// object-space lines); everything in src/export works from this alone, on the CPU, and knows
// nothing of Vulkan. Coordinates are pixels of the rendered image: origin at the top-left corner,
// y down, so a dot at px lies where the PNG shows it.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace stipple::plot {

// One drawn stipple.
struct Dot {
    glm::vec2 px{0.0f};      // exact screen position (sub-pixel)
    float radius_px = 0.5f;  // the radius the frame draws it with
    // In (0, 1]: the stipple's fractional intensity (the paper's last stipple of a polygon) times
    // any fade. Pens cannot draw half-opaque ink, so the export keeps the ink area instead: the dot
    // is drawn at full ink with radius radius_px * sqrt(intensity) (see plot_plan.hpp).
    float intensity = 1.0f;
    uint32_t object = 0;   // index into Drawing::objects
    uint32_t polygon = 0;  // the object's polygon (triangle) the stipple lies on, for the CSV
};

enum class LineKind : uint8_t { Silhouette, Contour, Border, Crease };

// One visible piece of a line. Pieces of one line share exact (or nearly exact, see
// PolylineOptions::snap_px) endpoints; duplicates and overlaps are allowed and removed by the export.
struct Segment {
    glm::vec2 a{0.0f}, b{0.0f};
    uint32_t object = 0;
    LineKind kind = LineKind::Silhouette;
};

struct DrawnObject {
    std::string name;           // shown in the layer labels ("1 bunny stipples")
    float line_width_px = 1.0f;  // the width the frame drew its outline with (used when no pen width is set)
    float crease_width_px = 1.0f;  // and its creases
    std::optional<glm::vec3> ink;  // its own ink (ObjectParams::ink); unset: the drawing's
};

struct Drawing {
    uint32_t width_px = 0, height_px = 0;  // the image the coordinates refer to; it is fitted to the page
    std::vector<DrawnObject> objects;      // every Dot::object and Segment::object indexes this
    std::vector<Dot> dots;
    std::vector<Segment> segments;
    glm::vec3 ink{0.0f};    // colours in [0,1], the renderer's ink and paper
    glm::vec3 paper{1.0f};
};

}  // namespace stipple::plot
