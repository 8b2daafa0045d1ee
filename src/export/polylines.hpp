#pragma once
// Line graphs chained into as few pen strokes as the walk finds.
//
// Each stroke follows edges end to end; at a junction it goes on along the straightest unused
// edge, so crossing lines stay whole. A connected part with 2k vertices of odd degree becomes k
// open strokes (no fewer can draw it), one without becomes one closed polyline; loops met on the
// way are spliced into the stroke that touches them. Every edge is drawn exactly once.
#include <vector>

#include "export/polyline.hpp"
#include "export/segment_merge.hpp"

namespace stipple::plot {

std::vector<Polyline> chain_edges(const LineGraph& graph);

}  // namespace stipple::plot
