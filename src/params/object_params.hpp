#pragma once
// Everything a user sets per object: the paper's parameters, each object its own (§2.3, Fig. 3).
// Only the plain structs live here; their names, ranges, defaults' help text, scene keys and CLI
// spellings are in one table, src/params/param_table.hpp, which every entry point walks.
#include <cstdint>
#include <optional>
#include <string>

#include <glm/vec3.hpp>

namespace stipple {

// How the per-frame density reaches the stipples (Table 1's columns, and ones beyond the paper).
enum class DensityPath {
    Vertex,    // compute pass writes densities; every candidate drawn, vertex shader culls (§3.2)
    Cpu,       // CPU computes densities and lists the survivors, drawn in one draw (the "no vertex program" path)
    Indirect,  // compute pass also lists the survivors (drawn_stipples.comp); one vkCmdDrawIndirect
    Splat,     // compute pass densities, then a compute pass draws the stipples itself (no rasteriser)
    CpuSplat,  // CPU computes densities (as Cpu), the compute splat draws them (as Splat)
};

inline constexpr DensityPath kAllDensityPaths[] = {DensityPath::Vertex, DensityPath::Cpu, DensityPath::Indirect,
                                                   DensityPath::Splat, DensityPath::CpuSplat};

// Where the density is computed: the paper's Table 1 columns "no vertex program" (CPU) and
// "vertex program" (GPU), whatever then draws the stipples.
inline bool density_on_cpu(DensityPath path) { return path == DensityPath::Cpu || path == DensityPath::CpuSplat; }
inline bool draws_by_splat(DensityPath path) { return path == DensityPath::Splat || path == DensityPath::CpuSplat; }

// Which axis of the model file points up. The object is turned about its bounding-sphere centre so
// that this axis becomes +y, before the scene's transform places it (scanned and CAD models are often
// z-up; the viewer's orbit and the default light assume y-up).
enum class UpAxis { X, Y, Z, NegX, NegY, NegZ };

const char* density_path_name(DensityPath path);
std::optional<DensityPath> parse_density_path(const std::string& name);

// What shapes stipple generation (§2.1): a change to any of these makes new stipples. The parameter
// table marks exactly these fields as regenerating, and the stipple cache's key hashes them through it.
struct GenerationParams {
    // D_max: the maximum stipple density, in stipples per reference pixel^2 (see docs/paper-reading.md).
    float dmax = 0.25f;
    // Object_max: the object's stipple budget. The density actually used is
    // min(D_max, Object_max / total reference area), so the budget lowers the density evenly.
    uint64_t max_stipples = 8'000'000;
    uint64_t seed = 1;
    int relax_iterations = 5;  // whole-surface relaxation toward a Poisson-disc distribution (stipple/relax.hpp)
    // The stipples kept at a quarter of the density relaxed and ordered as a class of their own
    // (stipple/stipple_classes.hpp): evener far views and mid-tones, slower generation.
    bool coarse_class = false;
    bool progress = false;     // not a parameter: print a progress bar on stderr (only on a terminal)
};

struct ObjectParams {
    GenerationParams generation;    // D_max, Object_max, seed, relaxation (§2.1)
    bool shading = true;            // §2.2 (N.L)^n
    float shading_exponent = 1.0f;  // n
    bool extrinsic = true;          // §2.3 extrinsic distance enhancement, both regimes
    float pr = 2.0f;                // extrinsic rate (2: stipples per screen pixel stay constant)
    float min_area = 4.0f;          // minimum stipple screen area in px^2 (2..9 in the paper)
    bool intrinsic = true;          // §2.3 intrinsic depth enhancement
    float de = 2.0f;                // intrinsic rate
    float point_size = 1.5f;        // stipple diameter in pixels
    // §2.1's last stipple at its fraction's intensity (grey dots where polygons hold about one stipple); off,
    // solid or absent by the polygon's own threshold, the same ink on average (solid_dot_intensity).
    bool faint_dots = false;
    DensityPath density_path = DensityPath::Splat;  // the fastest correct path on lavapipe (stipple bench)
    // Lines, each kind its own switch (§3.1 and beyond the paper).
    bool silhouette_lines = false;    // §3.1 Raskar-Cohen: back-face edges as wide lines (image space)
    bool toon = false;                // §3.1 toon N.E ramp: surfaces darken edge-on, stipples fade there
    float silhouette_width = 4.0f;    // outline width in pixels at the object's reference size (silhouette,
                                      // contour and border lines; creases crease_weight times it)
    bool silhouette_thinning = true;  // lines thin as the projected bounding sphere shrinks (Fig. 8)
    float toon_sharpness = 4.0f;      // steepness of the toon ramps (surface darkening, stipple fade)
    // Object-space lines from the mesh's edges (beyond the paper), hidden parts removed.
    bool contours = false;            // edges between a polygon facing the viewer and one facing away
    bool borders = false;             // edges of one polygon (the rims of open surfaces)
    bool creases = false;             // edges whose polygons' normals differ by more than crease_angle
    float crease_angle = 60.0f;       // degrees
    float crease_weight = 0.5f;       // crease lines' width as a fraction of silhouette_width (interior lines
                                      // thinner than the outline, as illustrators draw them)
    // Open surfaces: polygons facing away, seen through an opening, get stipples with the flipped normal.
    bool two_sided = false;
    UpAxis up = UpAxis::Y;
    // The object's own ink (beyond the paper, which draws in black): its stipples, lines and toon shade,
    // and its layers' colour in vector output. Unset, the scene's ink. Not in the parameter table (a
    // colour, not a number): a scene file's object key "ink" and the panel set it.
    std::optional<glm::vec3> ink;
};

// Whether the object draws any kind of line from the mesh's edges (Raskar-Cohen or object-space).
inline bool draws_object_space_lines(const ObjectParams& p) { return p.contours || p.borders || p.creases; }
inline bool draws_edge_lines(const ObjectParams& p) { return p.silhouette_lines || draws_object_space_lines(p); }

// Throws stipple::Error naming the first parameter out of its range (param_table.hpp's wording).
void validate_params(const ObjectParams& params);

}  // namespace stipple
