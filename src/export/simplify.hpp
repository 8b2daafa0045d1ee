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

// Distance from p to the segment a-b.
double distance_to_segment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b);

}  // namespace stipple::plot
