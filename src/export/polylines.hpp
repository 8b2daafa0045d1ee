#pragma once
// Line graphs chained into as few pen strokes as the walk finds.
//
// Each stroke follows edges end to end; at a junction it goes on along the straightest unused
// edge, so crossing lines stay whole. A connected part with 2k vertices of odd degree becomes k
// open strokes (no fewer can draw it), one without becomes one closed polyline; loops met on the
// way are spliced into the stroke that touches them. Every edge is drawn exactly once.
#include <vector>

#include <glm/vec2.hpp>

#include "export/segment_merge.hpp"

namespace stipple::plot {

// A pen stroke: points joined by straight lines; a closed one also joins its last point to its
// first (the first point is not repeated at the end).
struct Polyline {
    std::vector<glm::dvec2> points;
    bool closed = false;
};

// Length drawn with the pen down, the closing edge of a closed polyline included.
double polyline_length(const Polyline& line);

std::vector<Polyline> chain_edges(const LineGraph& graph);

}  // namespace stipple::plot
