#include "render/object_params.hpp"

#include <cmath>
#include <sstream>

#include "core/error.hpp"

namespace stipple {

namespace {

void check_range(const char* name, double value, double lo, double hi, bool lo_open = false) {
    bool ok = std::isfinite(value) && (lo_open ? value > lo : value >= lo) && value <= hi;
    if (!ok) {
        std::ostringstream out;
        out << name << " = " << value << " is out of range: it must be " << (lo_open ? "> " : ">= ") << lo
            << " and <= " << hi;
        fail(out.str());
    }
}

}  // namespace

const char* density_path_name(DensityPath path) {
    switch (path) {
        case DensityPath::Vertex: return "vertex";
        case DensityPath::Cpu: return "cpu";
        case DensityPath::Indirect: return "indirect";
        case DensityPath::Splat: return "splat";
        case DensityPath::CpuSplat: return "cpu-splat";
    }
    return "?";
}

std::optional<DensityPath> parse_density_path(const std::string& name) {
    for (DensityPath p : kAllDensityPaths)
        if (name == density_path_name(p)) return p;
    return std::nullopt;
}

const char* silhouette_mode_name(SilhouetteMode mode) {
    switch (mode) {
        case SilhouetteMode::None: return "none";
        case SilhouetteMode::Lines: return "lines";
        case SilhouetteMode::Toon: return "toon";
        case SilhouetteMode::Both: return "both";
    }
    return "?";
}

std::optional<SilhouetteMode> parse_silhouette_mode(const std::string& name) {
    for (SilhouetteMode m : {SilhouetteMode::None, SilhouetteMode::Lines, SilhouetteMode::Toon, SilhouetteMode::Both})
        if (name == silhouette_mode_name(m)) return m;
    return std::nullopt;
}

void validate_params(const ObjectParams& params) {
    check_range("--dmax", params.generation.dmax, 0.0, 16.0, true);
    check_range("--max-stipples", double(params.generation.max_stipples), 1.0, 2.0e9);
    check_range("--relax-iterations", params.generation.relax_iterations, 0, 100);
    check_range("--shading-exponent", params.shading_exponent, 0.0, 64.0, true);
    check_range("--pr", params.pr, 0.0, 8.0);
    check_range("--min-area", params.min_area, 2.0, 9.0);
    check_range("--de", params.de, 0.0, 16.0, true);
    check_range("--point-size", params.point_size, 1.0, 64.0);
    check_range("--silhouette-width", params.silhouette_width, 1.0, 64.0);
    check_range("--toon-sharpness", params.toon_sharpness, 0.5, 64.0);
}

}  // namespace stipple
