#pragma once
// Per-polygon stipple generation (paper §2.1): the candidate stipples of one object.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "mesh/mesh.hpp"
#include "params/object_params.hpp"

namespace stipple {

// Height in pixels of the reference view in which polygon areas are measured at generation time
// ("the initial screen area of the projected polygon", §2.1). At the reference view the object is
// framed, so its bounding-sphere radius spans kReferenceHeight/2 pixels. A fixed constant, so that
// the candidates do not depend on the window size.
inline constexpr float kReferenceHeight = 1280.0f;

struct StippleSet {
    std::vector<glm::vec3> positions;  // object space, on the surface, one per candidate stipple
    std::vector<uint32_t> triangle;    // the triangle each stipple belongs to
    // Prefix sums per triangle (size triangle_count + 1): the stipples of triangle t are
    // [first[t], first[t+1]) and are stored in progressive order, so every prefix is well spread.
    std::vector<uint32_t> first;
    // Per polygon, the fixed selection values of §2.3 (polygon_selection_values with the same seed), when
    // known: the stipple cache keeps them, since ranking a large mesh's polygons costs more than reading
    // its stipples. Empty: computed when the object is created.
    std::vector<float> selection;
    double density_per_area = 0.0;  // stipples per object-space unit area actually used
    double poisson_radius = 0.0;    // hexagonal-packing spacing at that density (object units)
    double generation_seconds = 0.0;  // or the time to read it back from the cache
    bool from_cache = false;          // read from the stipple cache (stipple_cache.hpp), not generated

    size_t size() const { return positions.size(); }
    uint32_t count(size_t t) const { return first[t + 1] - first[t]; }
};

// Deterministic for a given mesh, parameters and seed (also across thread counts).
// Zero-area triangles get no stipples. The total is within 1 of density * total area, whatever
// the tessellation. `headroom` (empty, or one factor >= 1 per triangle) generates triangle t's
// candidates for headroom[t] times its area: an animation that stretches it to that area finds enough
// (src/anim/headroom.hpp); the density per area, the reference view and the spacing stay the rest's.
StippleSet generate_stipples(const Mesh& mesh, const GenerationParams& params, std::span<const float> headroom = {});

// How many stipples generate_stipples makes for these arguments, counted without making them (a pass over
// the areas): what a device must hold is checked before a long generation.
uint64_t planned_stipple_count(const Mesh& mesh, const GenerationParams& params, std::span<const float> headroom = {});

// Stipples per object-space unit area for this mesh and parameters (the paper's N_max per area).
double stipple_density_per_area(const Mesh& mesh, const GenerationParams& params);

// The D_max the stipples are generated for: the one asked, or less where Object_max (max_stipples) caps the
// candidates (commands say so: a larger --dmax then changes nothing).
double effective_dmax(const Mesh& mesh, const GenerationParams& params);

}  // namespace stipple
