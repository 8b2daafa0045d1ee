#pragma once
// The order a plotter draws strokes in: from the pen, always on to the nearest free end.
//
// An open stroke may be entered at either end (it is reversed when entered at its last point), a
// closed one at any of its points (it is rotated to start there, and the pen comes back to that
// point). The nearest end is found with a NearestAliveGrid over all entry points.
#include <vector>

#include <glm/vec2.hpp>

#include "export/polylines.hpp"

namespace stipple::plot {

// Reorders (and reverses or rotates) `lines` in place; `pen` moves to where the last one ends.
void order_polylines(std::vector<Polyline>& lines, glm::dvec2& pen);

// Strokes whose ends lie closer than `gap_mm` (the pen's width: their round caps meet) made one before they
// are ordered, wherever they come in the order: the order goes on from where the pen is and only joins a stroke
// that starts where the last ended, so two strokes meeting end to end, or start to start, cost a pen lift (the
// ogre's outline at 640 x 512 had ends 0.02-0.03 mm apart with a 0.48 mm pen; a review, 2026-12-06). Nearest
// ends first, each end once, a chain never closed on itself; open strokes only. Unfolded as join_close_strokes.
void weld_touching_strokes(std::vector<Polyline>& lines, double gap_mm, double fold_mm);

// Strokes in plotting order whose gap (from where one ends to where the next starts) is narrower than `gap_mm`
// are made one: with the pen's width as the gap, their round caps already meet, so the pen stays down across it
// (the bridge inks a sliver more than the two caps did). A closed stroke is neither joined nor joined to. A joined
// stroke is unfolded within `fold_mm` (simplify.hpp unfold; the plan's own fold bound): pieces that overlap where
// they meet made it step back over its last stretch and on again.
void join_close_strokes(std::vector<Polyline>& lines, double gap_mm, double fold_mm);

}  // namespace stipple::plot
