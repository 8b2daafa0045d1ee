#pragma once
// The coarse class of a triangle's stipples: those it keeps at a quarter of its density.
//
// A triangle drawn at density fraction f keeps its first stipples (paper §2.1: "only the number of
// stipples per polygon varies"), k + 0.5 < f N_t of them on average (stipple/quality.hpp). Far views and
// dark tones draw short prefixes, so the stipples kept at f = 1/4 are a set that is seen on its own, at
// twice the full set's spacing. With the coarse_class parameter (off by default: it costs generation time),
// generation treats them as a class of their own (multi-class blue noise, Wei 2010): relaxed among
// themselves first, then fixed while the others are relaxed around them (relax.hpp), and ordered before the
// others within their triangle (progressive_order.hpp).
//
// On a sphere of 100k triangles and 400k stipples, delta-bar of the prefixes at f = 1/8, 1/4, 1/2, 3/4 and
// 1 are 0.626, 0.700, 0.701, 0.771, 0.855 without the class and 0.691, 0.809, 0.696, 0.770, 0.855 with it
// (docs/paper-reading.md has more). One class rather than several: a prototype with fixed classes
// at 1/8, 1/4 and 1/2 as well left the whole set at 0.77 (the finer classes, fixed, leave the others too
// little room).
#include <cstdint>

namespace stipple {

// Triangles of more stipples have no coarse class: their ordering chooses each prefix among many
// candidates already (delta-bar about 0.75 at every fraction), and with the class their prefixes below a
// quarter, chosen from it alone, were less even (a CAD cylinder's tone across a 16x range of size drifted
// 1.05-1.06 instead of 1.02-1.04).
inline constexpr uint32_t kCoarseClassMaxStipples = 64;

// The number of k in [0, N) with k + 0.5 < N / 4, for a triangle of N stipples with a coarse class.
constexpr uint32_t coarse_count(uint32_t stipples) {
    return stipples < 3 || stipples > kCoarseClassMaxStipples ? 0u : (stipples - 3u) / 4u + 1u;
}

static_assert(coarse_count(2) == 0 && coarse_count(3) == 1 && coarse_count(4) == 1 && coarse_count(6) == 1 &&
              coarse_count(7) == 2 && coarse_count(64) == 16 && coarse_count(65) == 0);

}  // namespace stipple
