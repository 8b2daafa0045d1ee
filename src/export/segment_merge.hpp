#pragma once
// Visible line pieces made into a clean graph: endpoints welded, every stretch of line once.
//
// The frame hands over line pieces as it found them: each piece of an edge on its own, an edge
// shared by two polygons possibly twice, pieces split at visibility changes overlapping a little.
// Drawn as they come, a plotter would draw some lines twice (the ink bleeds, the paper wears) and
// lift the pen at every piece. Here endpoints closer than snap_px become one vertex, zero-length
// pieces go, and pieces lying on one line (within collinear_px) that overlap are merged into the
// union of their extents, so that no stretch is left twice; chaining (polylines.hpp) follows.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

namespace stipple::plot {

struct MergeOptions {
    double snap_px = 1e-3;       // endpoints this close are the same point
    // Pieces whose ends lie this close to each other's line are on one line. A quarter of a pixel: a
    // mesh's contour zig-zags, its edges folding back over each other a tenth of a pixel or two apart,
    // and at 1e-2 px those stretches survived as separate pieces that the chain then walked back and
    // forth (the bunny's contours at 640x512: 221 mm of 908 drawn two or three times, 13.7 mm of 652
    // now). Lines half a pixel apart stay two (at 0.5 px the retracing fell to 0.7 mm, but such lines
    // were joined by diagonals between their ends).
    double collinear_px = 0.25;
};

struct LineGraph {
    std::vector<glm::dvec2> vertices;
    std::vector<std::array<uint32_t, 2>> edges;  // no two overlap, none has zero length
};

LineGraph merge_segments(std::span<const std::array<glm::dvec2, 2>> pieces, const MergeOptions& options = {});

}  // namespace stipple::plot
