#pragma once
// Douglas-Peucker simplification of pen strokes within a distance tolerance.
//
// Every dropped point lies within `tolerance` of the segment that replaces its stretch, so the
// simplified stroke never strays further than that from the original. Ends are kept; a closed
// polyline stays closed (it is split at its first point and at the point farthest from it, and the
// two halves are simplified separately).
#include "export/polylines.hpp"

namespace stipple::plot {

Polyline simplify(const Polyline& line, double tolerance);

// A stroke that turns back (by more than 150 degrees) and forward again over a stretch it has just drawn,
// lying within `tolerance` of one straight line from before the fold to after it, takes that line instead;
// a stroke that ends (or starts) by turning back over its last (first) stretch within `tolerance` drops
// it. A mesh's contour zig-zags where it is seen edge-on, and its edges fold back over each other a
// pixel or so apart, too far for the merge (segment_merge.hpp) to call them one line: the pen drew such
// a stretch two or three times within its own width. `tolerance` is what the stroke's width covers.
// Where the stroke turns back and goes elsewhere (a spike), it is left: only a pen lift could avoid it.
Polyline unfold(const Polyline& line, double tolerance);

// Distance from p to the segment a-b.
double distance_to_segment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b);

}  // namespace stipple::plot
