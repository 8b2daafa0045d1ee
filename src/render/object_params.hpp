#pragma once
// Everything a user sets per object: the paper's parameters, each object its own (§2.3, Fig. 3).
#include <optional>
#include <string>

#include "stipple/stipple_set.hpp"

namespace stipple {

// How the per-frame density reaches the stipples (Table 1's columns, and one beyond the paper).
enum class DensityPath {
    Vertex,    // compute pass writes densities; every candidate drawn, vertex shader culls (§3.2)
    Cpu,       // CPU computes densities; only surviving ranges are submitted (the "no vertex program" path)
    Indirect,  // compute pass also writes compacted draws; vkCmdDrawIndirectCount
    Splat,     // compute pass densities, then a compute pass draws the stipples itself (no rasteriser)
    CpuSplat,  // CPU computes densities (as Cpu), the compute splat draws them (as Splat)
};

inline constexpr DensityPath kAllDensityPaths[] = {DensityPath::Vertex, DensityPath::Cpu, DensityPath::Indirect,
                                                   DensityPath::Splat, DensityPath::CpuSplat};

// Where the density is computed: the paper's Table 1 columns "no vertex program" (CPU) and
// "vertex program" (GPU), whatever then draws the stipples.
inline bool density_on_cpu(DensityPath path) { return path == DensityPath::Cpu || path == DensityPath::CpuSplat; }
inline bool draws_by_splat(DensityPath path) { return path == DensityPath::Splat || path == DensityPath::CpuSplat; }

const char* density_path_name(DensityPath path);
std::optional<DensityPath> parse_density_path(const std::string& name);

// Silhouettes (§3.1): Raskar-Cohen back-face lines, the toon N.E ramp, both, or none.
enum class SilhouetteMode { None, Lines, Toon, Both };

const char* silhouette_mode_name(SilhouetteMode mode);
std::optional<SilhouetteMode> parse_silhouette_mode(const std::string& name);
inline bool has_lines(SilhouetteMode m) { return m == SilhouetteMode::Lines || m == SilhouetteMode::Both; }
inline bool has_toon(SilhouetteMode m) { return m == SilhouetteMode::Toon || m == SilhouetteMode::Both; }

struct ObjectParams {
    GenerationParams generation;    // D_max, Object_max, seed (§2.1)
    bool shading = true;            // §2.2 (N.L)^n
    float shading_exponent = 1.0f;  // n
    bool extrinsic = true;          // §2.3 extrinsic distance enhancement, both regimes
    float pr = 2.0f;                // extrinsic rate (2: stipples per screen pixel stay constant)
    float min_area = 4.0f;          // minimum stipple screen area in px^2 (2..9 in the paper)
    bool intrinsic = true;          // §2.3 intrinsic depth enhancement
    float de = 2.0f;                // intrinsic rate
    float point_size = 1.5f;        // stipple diameter in pixels
    DensityPath density_path = DensityPath::Splat;  // the fastest correct path on lavapipe (stipple bench)
    SilhouetteMode silhouette = SilhouetteMode::None;
    float silhouette_width = 4.0f;    // Raskar-Cohen line width in pixels at the object's reference size
    bool silhouette_thinning = true;  // lines thin as the projected bounding sphere shrinks (Fig. 8)
    float toon_sharpness = 4.0f;      // steepness of the toon ramps (surface darkening, stipple fade)
};

// Throws stipple::Error naming the parameter, its value and the accepted range.
void validate_params(const ObjectParams& params);

}  // namespace stipple
