#pragma once
// Stretch headroom of an animated model: how many candidate stipples each polygon needs beyond its rest
// count so that it can keep its tone when an animation stretches it (a polygon at twice its rest area
// draws up to twice its rest count). Measured once per model over every animation, so that the same
// stipples serve whichever animation is chosen, and capped: the fox's Run stretches a few small polygons
// at its joints to 7x their rest area, and giving them 7x the candidates would buy little ink for much
// memory. Beyond the cap a polygon draws all its candidates and reads lighter.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "anim/animated_model.hpp"
#include "mesh/mesh.hpp"

namespace stipple::anim {

// Candidates are generated for at most this many times a polygon's rest area.
inline constexpr float kHeadroomCap = 3.0f;

struct StretchHeadroom {
    // Per triangle, in [1, cap]: its candidates are generated for this many times its rest area. Polygons
    // that never grow get 1 (as a static model); shrinking needs no headroom (it draws fewer).
    std::vector<float> per_triangle;
    float cap = kHeadroomCap;
    float max_ratio = 1.0f;           // the largest area ratio any polygon reaches, before the cap
    std::string max_animation;        // the animation where it does ("" for none)
    size_t stretched_triangles = 0;   // polygons given headroom (ratio above 1)
    size_t capped_triangles = 0;      // polygons whose ratio exceeds the cap
    size_t opened_triangles = 0;      // polygons of no area at rest that an animation opens (no stipples)
    Bounds bounds;                    // every vertex of the rest pose and of every sampled pose
    // The first animation whose sampled poses put a vertex beyond kMaxCoordinate (or at infinity), as
    // "animation 0 'Run'"; "" when every pose stays in range. Keys within range can still compose to
    // such a pose (a parent scaled 1e10 moving a child translated 1e10).
    std::string out_of_range;
    // The mean headroom weighted by rest area: the candidates grow by this factor over a static model's.
    double candidate_factor = 1.0;
};

// Samples every animation (measure_stretch's times) and takes, per triangle, the largest area ratio.
StretchHeadroom measure_headroom(const AnimatedModel& model, float cap = kHeadroomCap);

// A model that moves, with what generation and the renderer need about its motion; both null for a
// static model.
struct Motion {
    std::shared_ptr<const AnimatedModel> model;
    std::shared_ptr<const StretchHeadroom> headroom;
    explicit operator bool() const { return model != nullptr; }
};

// One line for `stipple info`, e.g. "polygons reach up to 7.04x their rest area (Run); candidates
// generated for up to 3x: 35 of 576 polygons stretched, 9 capped; 1.21x the static candidates".
std::string describe_headroom(const StretchHeadroom& headroom, size_t triangles);

}  // namespace stipple::anim
