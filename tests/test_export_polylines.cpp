// Visible line pieces become clean pen strokes: welded, without any stretch twice, chained into
// as few polylines as possible (a closed outline into exactly one closed polyline), simplified
// within the tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <set>

#include <glm/geometric.hpp>

#include "export/polyline_order.hpp"
#include "export/polylines.hpp"
#include "export/segment_merge.hpp"
#include "export/simplify.hpp"

namespace {

using namespace stipple::plot;
using Piece = std::array<glm::dvec2, 2>;

// Cuts each edge of a closed polygon into `cuts` pieces, adds exact duplicates, overlapping
// copies (a piece spanning the middle of two others) and reversed pieces, and shuffles them.
std::vector<Piece> messy_outline(const std::vector<glm::dvec2>& corners, int cuts, double jitter, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> noise(-jitter, jitter);
    std::vector<Piece> pieces;
    for (size_t c = 0; c < corners.size(); ++c) {
        const glm::dvec2 a = corners[c], b = corners[(c + 1) % corners.size()];
        const auto at = [&](double t) { return a + t * (b - a) + glm::dvec2(noise(rng), noise(rng)); };
        for (int k = 0; k < cuts; ++k) {
            pieces.push_back({at(double(k) / cuts), at(double(k + 1) / cuts)});
            if (k % 3 == 0) pieces.push_back({at(double(k + 1) / cuts), at(double(k) / cuts)});  // duplicate, reversed
        }
        if (cuts >= 2) pieces.push_back({at(0.5 / cuts), at(1.5 / cuts)});  // overlaps two pieces in part
        if (c % 2 == 0) pieces.push_back({at(0.0), at(1.0)});                 // the whole edge again
    }
    for (size_t i = 0; i < pieces.size(); i += 2) std::swap(pieces[i][0], pieces[i][1]);
    std::shuffle(pieces.begin(), pieces.end(), rng);
    return pieces;
}

double total_length(const std::vector<Polyline>& lines) {
    double sum = 0.0;
    for (const Polyline& line : lines) sum += polyline_length(line);
    return sum;
}

// Every undirected edge of the strokes, as rounded endpoint pairs: a repeat means a stretch drawn twice.
size_t repeated_edges(const std::vector<Polyline>& lines) {
    std::set<std::array<long long, 4>> seen;
    size_t repeats = 0;
    for (const Polyline& line : lines) {
        const size_t n = line.points.size();
        for (size_t i = 0; i + 1 < n + (line.closed ? 1 : 0); ++i) {
            const glm::dvec2 a = line.points[i], b = line.points[(i + 1) % n];
            std::array<long long, 4> key{std::llround(a.x * 100), std::llround(a.y * 100), std::llround(b.x * 100), std::llround(b.y * 100)};
            if (std::make_pair(key[2], key[3]) < std::make_pair(key[0], key[1])) key = {key[2], key[3], key[0], key[1]};
            repeats += !seen.insert(key).second;
        }
    }
    return repeats;
}

// Strokes whose ends touch (closer than the pen's width) are one stroke before they are ordered, whichever ends
// meet: end to start, end to end, start to start; a stroke apart stays apart, a closed one is never welded, and
// a chain is never closed on itself (the last stroke's free end near the first's is left a gap).
TEST(ExportPolylines, StrokesWhoseEndsTouchAreWeldedIntoOne) {
    const double pen = 0.3;
    std::vector<Polyline> lines = {
        {{{0, 0}, {10, 0}}, false},           // a
        {{{10.02, 0}, {20, 0}}, false},       // b: starts where a ends
        {{{30, 0}, {20.01, 0.01}}, false},    // c: ends where b ends
        {{{-0.02, 0}, {-10, 5}}, false},      // d: starts where a starts
        {{{50, 50}, {60, 50}}, false},        // e: apart
        {{{0, 0.1}, {1, 1}, {0, 1}}, true},   // f: closed, beside a's start
    };
    weld_touching_strokes(lines, pen, 0.5 * pen);
    ASSERT_EQ(lines.size(), 3u);
    size_t open_points = 0, closed = 0;
    double longest = 0.0;
    for (const Polyline& line : lines) {
        closed += line.closed;
        if (!line.closed) open_points += line.points.size();
        if (!line.closed && line.points.size() > 2) longest = polyline_length(line);
    }
    EXPECT_EQ(closed, 1u);
    EXPECT_EQ(open_points, 10u) << "d, a, b, c in one (8 points) and e (2)";
    EXPECT_NEAR(longest, std::hypot(10.0, 5.0) + 30.0 + 0.02 + 0.02 + 0.01 * std::sqrt(2.0), 0.05);

    // A ring of strokes end to end: welded into one open stroke, not closed.
    std::vector<Polyline> ring = {{{{0, 0}, {10, 0}}, false}, {{{10, 0.01}, {10, 10}}, false}, {{{10.01, 10}, {0, 0.01}}, false}};
    weld_touching_strokes(ring, pen, 0.5 * pen);
    ASSERT_EQ(ring.size(), 1u);
    EXPECT_FALSE(ring[0].closed);
    EXPECT_EQ(ring[0].points.size(), 6u);
}

TEST(ExportPolylines, MessySquareBecomesOneClosedPolyline) {
    const std::vector<glm::dvec2> square{{100, 100}, {200, 100}, {200, 200}, {100, 200}};
    const LineGraph graph = merge_segments(messy_outline(square, 5, 0.0, 1));
    // Two sides came with a whole copy (merged into one edge each), two in 5 pieces of which the
    // first two were overlapped by a copy (merged into one): 1 + 4 + 1 + 4 edges, no copy left.
    EXPECT_EQ(graph.edges.size(), 10u);
    const std::vector<Polyline> lines = chain_edges(graph);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_TRUE(lines[0].closed);
    EXPECT_EQ(lines[0].points.size(), 10u);
    EXPECT_NEAR(total_length(lines), 400.0, 1e-9);
    EXPECT_EQ(repeated_edges(lines), 0u);
    // Simplified: the four corners, still closed.
    const Polyline corners = simplify(lines[0], 0.05);
    EXPECT_TRUE(corners.closed);
    EXPECT_EQ(corners.points.size(), 4u);
    EXPECT_NEAR(polyline_length(corners), 400.0, 1e-9);
}

TEST(ExportPolylines, MessyCircleWithJitterBecomesOneClosedPolyline) {
    std::vector<glm::dvec2> circle;
    for (int i = 0; i < 64; ++i) {
        const double a = 2.0 * std::numbers::pi * i / 64;
        circle.push_back(glm::dvec2(300, 200) + 80.0 * glm::dvec2(std::cos(a), std::sin(a)));
    }
    // Endpoints off by up to 2e-4 px, as a GPU's clipped pieces would be.
    const LineGraph graph = merge_segments(messy_outline(circle, 3, 2e-4, 2));
    EXPECT_EQ(graph.edges.size(), 32u * 1u + 32u * 2u);  // as in the square: whole copies and overlaps merged
    const std::vector<Polyline> lines = chain_edges(graph);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_TRUE(lines[0].closed);
    double perimeter = 0.0;
    for (size_t i = 0; i < circle.size(); ++i) perimeter += glm::length(circle[(i + 1) % circle.size()] - circle[i]);
    EXPECT_NEAR(total_length(lines), perimeter, 0.01);
    EXPECT_EQ(repeated_edges(lines), 0u);
}

TEST(ExportPolylines, OverlapsMergeOnlyOnOneLine) {
    // [0,2] and [1,3] and [2.5,4] on one line: one edge [0,4]. A touching [4,5] stays its own edge;
    // a parallel piece half a pixel away is another line.
    const std::vector<Piece> pieces{{glm::dvec2(0, 0), glm::dvec2(2, 0)}, {glm::dvec2(3, 0), glm::dvec2(1, 0)},
                                    {glm::dvec2(2.5, 0.0005), glm::dvec2(4, 0)}, {glm::dvec2(4, 0), glm::dvec2(5, 0)},
                                    {glm::dvec2(0, 0.5), glm::dvec2(3, 0.5)}};
    const LineGraph graph = merge_segments(pieces);
    ASSERT_EQ(graph.edges.size(), 3u);
    std::vector<double> lengths;
    for (const auto& e : graph.edges) lengths.push_back(glm::length(graph.vertices[e[1]] - graph.vertices[e[0]]));
    std::sort(lengths.begin(), lengths.end());
    EXPECT_NEAR(lengths[0], 1.0, 1e-9);
    EXPECT_NEAR(lengths[1], 3.0, 1e-9);
    EXPECT_NEAR(lengths[2], 4.0, 1e-6);
    const std::vector<Polyline> lines = chain_edges(graph);
    EXPECT_EQ(lines.size(), 2u);  // [0,5] in one stroke, the parallel line in another
    EXPECT_NEAR(total_length(lines), 8.0, 1e-6);
}

// A mesh's contour seen edge-on zig-zags: its edges fold back over each other a tenth of a pixel or two
// apart (the bunny's, at 640x512). They are one stretch of line, drawn once, not walked back and forth.
TEST(ExportPolylines, AContourFoldingBackOnItselfIsDrawnOnce) {
    const std::vector<Piece> pieces{{glm::dvec2(0, 0), glm::dvec2(6, 0.05)}, {glm::dvec2(6, 0.05), glm::dvec2(2, 0.1)},
                                    {glm::dvec2(2, 0.1), glm::dvec2(9, 0.02)}, {glm::dvec2(9, 0.02), glm::dvec2(5, -0.03)}};
    const std::vector<Polyline> lines = chain_edges(merge_segments(pieces));
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_NEAR(total_length(lines), 9.0, 0.01) << "the stretch from x = 0 to 9 once, where the pieces add up to 21";
    EXPECT_EQ(repeated_edges(lines), 0u);
}

// The same folding along a curve (a contour's zig-zag around an arc of radius 200 px): merging stays on
// the curve. Groups gather pairwise, and a group's span along one line had turned 60 folds into a chord
// 77 px off the arc.
TEST(ExportPolylines, FoldsAlongACurveStayOnIt) {
    const double radius = 200.0, step = 6.0 / radius;  // pieces 1.5 and 0.5 steps of 6 px
    auto on_arc = [&](double a) { return glm::dvec2(radius * std::cos(a), radius * std::sin(a)); };
    std::vector<Piece> pieces;
    double a = 0.0;
    for (int i = 0; i < 60; ++i) {
        pieces.push_back({on_arc(a), on_arc(a + 1.5 * step)});
        pieces.push_back({on_arc(a + 1.5 * step), on_arc(a + step)});
        a += step;
    }
    const LineGraph graph = merge_segments(pieces);
    double worst = 0.0;
    for (const auto& e : graph.edges) {
        const glm::dvec2 mid = 0.5 * (graph.vertices[e[0]] + graph.vertices[e[1]]);
        worst = std::max(worst, radius - glm::length(mid));  // the chord's sagitta
    }
    EXPECT_LT(worst, 0.5) << "a merged piece strays from the arc";
    const std::vector<Polyline> lines = chain_edges(graph);
    EXPECT_LT(total_length(lines), 1.5 * 61.5 * 6.0) << "most of the fold-backs are still drawn once";
}

// Folds a pixel apart, beyond the merge's quarter pixel but within the stroke's width: the spot's contour
// at 640x512 went (249.8,247.9) -> (256.4,243.4) -> (250.9,247.7) -> (256.9,241.7), a Z drawn three times
// (13 such turns on the spot, 43 on the bunny seen from below, until 2026-12-04). Unfolded, the stroke
// takes the straight line over the fold; ends that turn back over their stroke are dropped; what a
// stroke draws beyond its width, a sharp V or a spike that goes elsewhere, stays.
TEST(ExportPolylines, FoldsWithinTheStrokesWidthAreDrawnOnce) {
    auto length = [](const Polyline& line) { return total_length(std::vector<Polyline>{line}); };
    const Polyline z{{{249.8, 247.9}, {256.4, 243.4}, {250.9, 247.7}, {256.9, 241.7}, {270.0, 230.0}}, false};
    const Polyline flat = unfold(z, 1.2);
    EXPECT_LE(flat.points.size(), 3u);
    EXPECT_EQ(flat.points.front(), z.points.front());
    EXPECT_EQ(flat.points.back(), z.points.back());
    EXPECT_NEAR(length(flat), glm::length(z.points.back() - z.points.front()), 0.5) << "straight over the fold";
    // The same Z with its arms 3 px apart is drawn as it is: a stroke 2.4 px wide shows both.
    const Polyline wide{{{0, 0}, {7, 0}, {1, 3}, {7, 3}, {20, 3}}, false};
    EXPECT_EQ(unfold(wide, 1.2).points, wide.points);
    // A sharp V, and a spike out and back that then goes on elsewhere.
    const Polyline v{{{0, 0}, {10, 0}, {0, 4}}, false};
    EXPECT_EQ(unfold(v, 1.2).points, v.points);
    const Polyline spike{{{0, 0}, {10, 0}, {5, 0.5}, {5, 20}}, false};
    EXPECT_EQ(unfold(spike, 1.2).points, spike.points);
    // An end turning back over its stroke within the width is dropped, at either end.
    const Polyline tails{{{3, 0.5}, {0, 0}, {10, 0}, {20, 0}, {16, 0.6}}, false};
    EXPECT_EQ(unfold(tails, 1.2).points, (std::vector<glm::dvec2>{{0, 0}, {10, 0}, {20, 0}}));
    // An end that turns back past the stroke's start: the way back covers the way out, which goes.
    const Polyline past{{{0, 0}, {10, 0}, {-3, 0.5}}, false};
    EXPECT_EQ(unfold(past, 1.2).points, (std::vector<glm::dvec2>{{10, 0}, {-3, 0.5}}));
    // A closed square is left as it is.
    const Polyline square{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, true};
    EXPECT_EQ(unfold(square, 1.2).points, square.points);
}

TEST(ExportPolylines, JunctionsKeepStraightStrokes) {
    // A plus: two strokes, each straight through the centre.
    const glm::dvec2 c(50, 50);
    const std::vector<Piece> plus{{c, c + glm::dvec2(10, 0)}, {c, c - glm::dvec2(10, 0)}, {c + glm::dvec2(0, 10), c}, {c - glm::dvec2(0, 10), c}};
    const std::vector<Polyline> lines = chain_edges(merge_segments(plus));
    ASSERT_EQ(lines.size(), 2u);
    for (const Polyline& line : lines) {
        ASSERT_EQ(line.points.size(), 3u);
        EXPECT_NEAR(glm::length(line.points[2] - line.points[0]), 20.0, 1e-9);
    }
    // A "Y" (three arms) needs two strokes; a square with a tail: one stroke from the tail's end;
    // two squares sharing a corner (a figure eight): one closed stroke.
    const std::vector<Piece> y{{c, c + glm::dvec2(10, 0)}, {c, c + glm::dvec2(-5, 8)}, {c, c + glm::dvec2(-5, -8)}};
    EXPECT_EQ(chain_edges(merge_segments(y)).size(), 2u);
    std::vector<Piece> tailed{{glm::dvec2(0, 0), glm::dvec2(10, 0)}, {glm::dvec2(10, 0), glm::dvec2(10, 10)},
                              {glm::dvec2(10, 10), glm::dvec2(0, 10)}, {glm::dvec2(0, 10), glm::dvec2(0, 0)},
                              {glm::dvec2(0, 0), glm::dvec2(-10, -10)}};
    const std::vector<Polyline> one = chain_edges(merge_segments(tailed));
    ASSERT_EQ(one.size(), 1u);
    EXPECT_FALSE(one[0].closed);
    EXPECT_EQ(one[0].points.size(), 6u);
    std::vector<Piece> eight = tailed;
    eight.back() = {glm::dvec2(0, 0), glm::dvec2(-10, 0)};
    for (const Piece& piece : std::vector<Piece>{{glm::dvec2(-10, 0), glm::dvec2(-10, -10)}, {glm::dvec2(-10, -10), glm::dvec2(0, -10)}, {glm::dvec2(0, -10), glm::dvec2(0, 0)}})
        eight.push_back(piece);
    const std::vector<Polyline> loop = chain_edges(merge_segments(eight));
    ASSERT_EQ(loop.size(), 1u);
    EXPECT_TRUE(loop[0].closed);
    EXPECT_EQ(loop[0].points.size(), 8u);
    EXPECT_NEAR(polyline_length(loop[0]), 80.0, 1e-9);
}

// Every point of `original` lies within `tolerance` of the chord of `simplified` that replaced it.
void expect_within(const Polyline& original, const Polyline& simplified, double tolerance) {
    std::vector<glm::dvec2> pts = original.points, kept = simplified.points;
    if (original.closed) pts.push_back(pts[0]), kept.push_back(kept[0]);
    size_t chord = 0;
    double worst = 0.0;
    for (const glm::dvec2& p : pts) {
        if (chord + 1 < kept.size() && p == kept[chord + 1]) ++chord;
        const glm::dvec2 a = kept[chord], b = kept[std::min(chord + 1, kept.size() - 1)];
        worst = std::max(worst, distance_to_segment(p, a, b));
    }
    EXPECT_EQ(chord + 1, kept.size()) << "simplified points must be original points in order";
    EXPECT_LE(worst, tolerance);
    EXPECT_GT(worst, 0.2 * tolerance) << "the tolerance should be used, not wasted";
}

TEST(ExportPolylines, SimplificationStaysWithinTolerance) {
    std::mt19937 rng(4);
    std::normal_distribution<double> noise(0.0, 0.01);
    Polyline wave;
    for (int i = 0; i <= 2000; ++i) wave.points.push_back({i * 0.05, 5.0 * std::sin(i * 0.01) + noise(rng)});
    const Polyline simple = simplify(wave, 0.05);
    EXPECT_LT(simple.points.size(), wave.points.size() / 10);
    EXPECT_EQ(simple.points.front(), wave.points.front());
    EXPECT_EQ(simple.points.back(), wave.points.back());
    expect_within(wave, simple, 0.05);

    Polyline ring;
    ring.closed = true;
    for (int i = 0; i < 720; ++i) ring.points.push_back(10.0 * glm::dvec2(std::cos(i * std::numbers::pi / 360), std::sin(i * std::numbers::pi / 360)));
    const Polyline simple_ring = simplify(ring, 0.05);
    EXPECT_TRUE(simple_ring.closed);
    EXPECT_GE(simple_ring.points.size(), 20u);  // a 10 mm circle within 0.05 mm needs ~23 sides
    EXPECT_LT(simple_ring.points.size(), 60u);
    expect_within(ring, simple_ring, 0.05);
}

TEST(ExportPolylines, OrderEntersAtNearestEndReversingAndRotating) {
    std::vector<Polyline> lines(3);
    lines[0].points = {{100, 0}, {90, 0}};  // entered at (90,0), so reversed
    lines[1].points = {{50, 50}, {50, 5}};  // entered at (50,5), so reversed
    lines[2].closed = true;
    lines[2].points = {{20, 20}, {30, 20}, {30, 0}, {20, 0}};
    glm::dvec2 pen(0.0);
    order_polylines(lines, pen);
    ASSERT_EQ(lines.size(), 3u);
    // The loop first, entered at (20,0) and left there; then the vertical stroke from (50,5); then (90,0)->(100,0).
    EXPECT_TRUE(lines[0].closed);
    EXPECT_EQ(lines[0].points.front(), glm::dvec2(20, 0));
    EXPECT_EQ(lines[1].points.front(), glm::dvec2(50, 5));
    EXPECT_EQ(lines[2].points.front(), glm::dvec2(90, 0));
    EXPECT_EQ(pen, glm::dvec2(100, 0));
}

}  // namespace
