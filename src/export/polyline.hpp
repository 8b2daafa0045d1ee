#pragma once
// A pen stroke: points joined by straight lines; a closed one also joins its last point to its
// first (the first point is not repeated at the end).
#include <vector>

#include <glm/vec2.hpp>

namespace stipple::plot {

struct Polyline {
    std::vector<glm::dvec2> points;
    bool closed = false;
};

// Length drawn with the pen down, the closing edge of a closed polyline included.
double polyline_length(const Polyline& line);

}  // namespace stipple::plot
