#pragma once
// Line graphs chained into as few pen strokes as the walk finds.
//
// Each stroke follows edges end to end; at a junction it goes on along the straightest unused
// edge, so crossing lines stay whole. Strokes start at vertices of odd degree first (every such
// vertex must end a stroke), then the loops that are left are walked; a walk that ends where it
// started is a closed polyline. Every edge is drawn exactly once.
#include <vector>

#include "export/polyline.hpp"
#include "export/segment_merge.hpp"

namespace stipple::plot {

std::vector<Polyline> chain_edges(const LineGraph& graph);

}  // namespace stipple::plot
