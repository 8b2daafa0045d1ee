#pragma once
// Which direction the progressive order's slabs lie across (progressive_order.cpp): the slabs let two
// cores order the stipples at once, and a triangle too long along the direction for a slab is cut into
// pieces that are ordered apart.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace stipple {

// How wide the slabs are: about 1/slabs of the object along the direction, but at least
// min_slab_searches * search_cap spacings (stipples near a border miss their neighbour slab's placed in
// the same window, so narrower slabs leave more close pairs, and wider ones fewer slabs to share between
// the cores); a triangle reaching more than half of that, less one search cap, from its stipples'
// centroid is cut, so that the triangles kept whole fit a slab.
struct SlabRule {
    double spacing;  // the full set's hexagonal spacing
    double search_cap;  // in spacings
    int slabs;
    double min_slab_searches;
    double wanted_width(double object_size) const;
    float split_extent(double object_size) const;  // the farthest along the direction a whole triangle reaches
    double slab_count(double object_size) const;
};

struct SlabDirection {
    glm::vec3 direction{1.0f, 0.0f, 0.0f};  // unit
    float lo = 0.0f;                        // the stipples' least coordinate along it
    double size = 0.0;                      // and their span
    uint64_t cut_stipples = 0;              // in the triangles it cuts
    std::vector<float> centre, extent;      // each triangle's centroid along it and reach from that
};

// The direction for the stipples positions[first[t] .. first[t+1]) of each triangle t: the axis that cuts
// the fewest stipples' triangles, the longest on ties (every axis when no triangle is that large, as on
// a scan), among those that make at least two slabs; where every axis cuts, of four directions across
// the cut triangles' common direction the one cutting the fewest, when it cuts at most half as many.
// Long slivers side by side cut across their length (a CAD cylinder's sides, slabs across its axis)
// drew single dots on each other at a distance, 10% lighter at 1/8 of the size (make_cad_cylinder(1024),
// until 2026-12-05): slabs along the slivers leave them whole. Deterministic for any thread count.
SlabDirection choose_slab_direction(std::span<const glm::vec3> positions, std::span<const uint32_t> first,
                                    const SlabRule& rule);

}  // namespace stipple
