#include "params/param_table.hpp"

#include <algorithm>
#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "core/decimal.hpp"
#include "core/error.hpp"

namespace stipple {

namespace {

using P = ObjectParams;

constexpr const char* kDensityPathNames[] = {"vertex", "cpu", "indirect", "splat", "cpu-splat"};
constexpr const char* kSilhouetteNames[] = {"none", "lines", "toon", "both"};
constexpr const char* kUpAxisNames[] = {"x", "y", "z", "-x", "-y", "-z"};  // UpAxis's order

// The old single switch for both §3.1 methods, read into the two independent ones.
constexpr const char* kSilhouetteAliasOf[] = {"silhouette_lines", "toon"};
double silhouette_alias_get(const P& p) { return double(int(p.silhouette_lines) | int(p.toon) << 1); }
void silhouette_alias_set(P& p, double v) {
    const int mode = int(v);
    p.silhouette_lines = (mode & 1) != 0;
    p.toon = (mode & 2) != 0;
}

// The sections, in the order they are listed.
constexpr const char* kGeneration = "stipple generation (§2.1; a change makes new stipples)";
constexpr const char* kShading = "shading and distance (§2.2, §2.3)";
constexpr const char* kDrawing = "drawing";
constexpr const char* kLines = "lines (§3.1)";

const ParamSpec kTable[] = {
    {"dmax", "dmax", "D_max", kGeneration,
     "D_max, the maximum stipple density in stipples per reference pixel^2 (the object framed in a "
     "1280-pixel-high reference view); with pr 2 also the stipples per screen pixel^2; 0 draws no stipples "
     "(lines and the toon ramp alone)",
     ParamType::Float, 0.0, 16.0, false, {}, ParamEffect::Regenerate, ParamWidget::LogSlider, false,
     [](const P& p) { return double(p.generation.dmax); }, [](P& p, double v) { p.generation.dmax = float(v); }},
    {"max_stipples", "max-stipples", "budget", kGeneration,
     "Object_max, the object's stipple budget; the density is lowered evenly when D_max would exceed it (an animated model's candidates add its stretch headroom on top)",
     ParamType::Int, 1.0, 2.0e9, false, {}, ParamEffect::Regenerate, ParamWidget::Input, false,
     [](const P& p) { return double(p.generation.max_stipples); },
     [](P& p, double v) { p.generation.max_stipples = uint64_t(v); }},
    {"seed", "seed", "seed", kGeneration, "seed of the stipple placement", ParamType::Int, 0.0, 4294967295.0, false,
     {}, ParamEffect::Regenerate, ParamWidget::Input, false, [](const P& p) { return double(p.generation.seed); },
     [](P& p, double v) { p.generation.seed = uint64_t(v); }},
    {"relax_iterations", "relax-iterations", "relaxation steps", kGeneration,
     "relaxation steps toward a Poisson-disc distribution", ParamType::Int, 0.0, 100.0, false, {},
     ParamEffect::Regenerate, ParamWidget::Slider, false,
     [](const P& p) { return double(p.generation.relax_iterations); },
     [](P& p, double v) { p.generation.relax_iterations = int(v); }},
    {"coarse_class", "coarse-class", "quarter as a class", kGeneration,
     "the stipples a polygon keeps at a quarter of its density (far views, mid-tones) relaxed among themselves "
     "first, then held while the others are relaxed around them, then 2 more steps for all, and ordered first "
     "(polygons of up to 64 stipples): that quarter spreads nearly as evenly as the whole set (delta-bar 0.81 "
     "instead of 0.70; the whole set's 0.855), for generation 15-45% slower (more where polygons hold few "
     "stipples)",
     ParamType::Bool, 0, 0, false, {}, ParamEffect::Regenerate, ParamWidget::Checkbox, false,
     [](const P& p) { return double(p.generation.coarse_class); }, [](P& p, double v) { p.generation.coarse_class = v != 0.0; }},

    {"shading", "shading", "shading", kShading,
     "§2.2 shading by (N.L)^n: fewer stipples toward the light (off: the light takes none away; the distance, "
     "orientation and depth terms still apply: --no-extrinsic --no-intrinsic too for the paper's uniform stippling, "
     "where every candidate is drawn: at the default --dmax they cover the surface, so take a lower one, e.g. 0.05)",
     ParamType::Bool, 0, 0, false, {}, ParamEffect::Frame, ParamWidget::Checkbox, false,
     [](const P& p) { return double(p.shading); }, [](P& p, double v) { p.shading = v != 0.0; }},
    {"shading_exponent", "shading-exponent", "exponent n", kShading,
     "n in the shading term (N.L)^n; a larger n keeps more stipples toward the light", ParamType::Float, 0.0, 64.0,
     true, {}, ParamEffect::Frame, ParamWidget::LogSlider, false, [](const P& p) { return double(p.shading_exponent); },
     [](P& p, double v) { p.shading_exponent = float(v); }},
    {"extrinsic", "extrinsic", "extrinsic", kShading,
     "§2.3 extrinsic distance enhancement, both regimes (large polygons, probabilistic selection of small ones)",
     ParamType::Bool, 0, 0, false, {}, ParamEffect::Frame, ParamWidget::Checkbox, false,
     [](const P& p) { return double(p.extrinsic); }, [](P& p, double v) { p.extrinsic = v != 0.0; }},
    {"pr", "pr", "pr", kShading,
     "extrinsic distance enhancement rate (2: stipples per screen pixel stay constant as the object moves away)",
     ParamType::Float, 0.0, 8.0, false, {}, ParamEffect::Frame, ParamWidget::Slider, false,
     [](const P& p) { return double(p.pr); }, [](P& p, double v) { p.pr = float(v); }},
    {"min_area", "min-area", "min area px^2", kShading,
     "minimum stipple screen area in px^2 at the default D_max (a lower D_max widens it in proportion): polygons projecting smaller are drawn by probabilistic selection",
     ParamType::Float, 2.0, 9.0, false, {}, ParamEffect::Frame, ParamWidget::Slider, false,
     [](const P& p) { return double(p.min_area); }, [](P& p, double v) { p.min_area = float(v); }},
    {"intrinsic", "intrinsic", "intrinsic", kShading, "§2.3 intrinsic depth enhancement", ParamType::Bool, 0, 0,
     false, {}, ParamEffect::Frame, ParamWidget::Checkbox, false, [](const P& p) { return double(p.intrinsic); },
     [](P& p, double v) { p.intrinsic = v != 0.0; }},
    {"de", "de", "de", kShading, "intrinsic depth enhancement rate (smaller exaggerates near and far)",
     ParamType::Float, 0.0, 16.0, true, {}, ParamEffect::Frame, ParamWidget::LogSlider, false,
     [](const P& p) { return double(p.de); }, [](P& p, double v) { p.de = float(v); }},

    {"point_size", "point-size", "point size px", kDrawing,
     "stipple size in pixels: the side of a square dot up to 2.5, above it a round one of the same area (a "
     "diameter 1.13 times as large), whose polygon's fractional last dot is smaller rather than fainter (square "
     "dots enlarged close up beyond 2.5 are discs of their area too)", ParamType::Float, 1.0, 64.0, false, {},
     ParamEffect::Frame, ParamWidget::Slider, false, [](const P& p) { return double(p.point_size); },
     [](P& p, double v) { p.point_size = float(v); }},
    {"faint_dots", "faint-dots", "faint last dots", kDrawing,
     "a polygon's last stipple drawn at its fractional intensity, as the paper's §2.1 (grey dots where polygons "
     "hold about a stipple each: a fine mesh framed, lit surfaces); off, it is solid or absent by a threshold of "
     "the polygon's own (its selection value of §2.3), the same ink on average, fading only over a tenth of "
     "a stipple's density", ParamType::Bool, 0, 0, false, {}, ParamEffect::Frame, ParamWidget::Checkbox, false,
     [](const P& p) { return double(p.faint_dots); }, [](P& p, double v) { p.faint_dots = v != 0.0; }},
    {"density_path", "density-path", "density path", kDrawing,
     "where the density is computed and what draws the stipples: vertex (compute pass, the vertex shader "
     "culls: the paper's vertex program), cpu (CPU densities, only survivors submitted), indirect (compute "
     "pass lists the survivors, one draw), splat (a compute pass draws the stipples, the fastest on lavapipe), "
     "cpu-splat (CPU densities drawn by the splat)",
     ParamType::Choice, 0, 0, false, kDensityPathNames, ParamEffect::Frame, ParamWidget::Combo, false,
     [](const P& p) { return double(int(p.density_path)); },
     [](P& p, double v) { p.density_path = DensityPath(int(v)); }},
    {"two_sided", "two-sided", "two-sided", kDrawing,
     "polygons facing away, seen through an opening of an open surface, get stipples and shading with "
     "their normal flipped (by the outside's tone rule)",
     ParamType::Bool, 0, 0, false, {}, ParamEffect::Frame, ParamWidget::Checkbox, false,
     [](const P& p) { return double(p.two_sided); }, [](P& p, double v) { p.two_sided = v != 0.0; }},
    {"up", "up", "up axis", kDrawing,
     "the model's up axis: the object is turned about its bounding-sphere centre so that this axis points "
     "up (+y), before the scene's transform",
     ParamType::Choice, 0, 0, false, kUpAxisNames, ParamEffect::Frame, ParamWidget::Combo, false,
     [](const P& p) { return double(int(p.up)); }, [](P& p, double v) { p.up = UpAxis(int(v)); }},

    {"silhouette_lines", "silhouette-lines", "silhouette lines", kLines,
     "Raskar-Cohen silhouette lines: the edges of polygons facing away drawn as wide lines behind the "
     "front faces' depth",
     ParamType::Bool, 0, 0, false, {}, ParamEffect::Frame, ParamWidget::Checkbox, false,
     [](const P& p) { return double(p.silhouette_lines); }, [](P& p, double v) { p.silhouette_lines = v != 0.0; }},
    {"toon", "toon", "toon", kLines, "the toon N.E ramp: surfaces darken where seen edge-on, stipples fade there",
     ParamType::Bool, 0, 0, false, {}, ParamEffect::Frame, ParamWidget::Checkbox, false,
     [](const P& p) { return double(p.toon); }, [](P& p, double v) { p.toon = v != 0.0; }},
    {"silhouette_width", "silhouette-width", "outline width px", kLines,
     "line width in pixels of silhouette, contour and border lines (creases are crease_weight times as wide); "
     "with thinning, the width where the object is framed in the default 1280x1024 image (its bounding sphere "
     "1024 px across), thinner as it shrinks on screen", ParamType::Float, 1.0, 64.0, false, {},
     ParamEffect::Frame, ParamWidget::Slider, false, [](const P& p) { return double(p.silhouette_width); },
     [](P& p, double v) { p.silhouette_width = float(v); }},
    {"silhouette_thinning", "thinning", "thinning", kLines,
     "lines thin as the object's projected bounding sphere shrinks (Fig. 8)", ParamType::Bool, 0, 0, false, {},
     ParamEffect::Frame, ParamWidget::Checkbox, false, [](const P& p) { return double(p.silhouette_thinning); },
     [](P& p, double v) { p.silhouette_thinning = v != 0.0; }},
    {"toon_sharpness", "toon-sharpness", "toon sharpness", kLines,
     "steepness of the toon ramps (surface darkening, stipple fade)", ParamType::Float, 0.5, 64.0, false, {},
     ParamEffect::Frame, ParamWidget::LogSlider, false, [](const P& p) { return double(p.toon_sharpness); },
     [](P& p, double v) { p.toon_sharpness = float(v); }},
    {"contours", "contours", "contours", kLines,
     "object-space contour lines (beyond the paper): edges between a polygon facing the viewer and one "
     "facing away, hidden parts removed, drawn at silhouette_width centred on the edge (a silhouette line of that "
     "width shows only its part outside the front faces, about half)",
     ParamType::Bool, 0, 0, false, {}, ParamEffect::Frame, ParamWidget::Checkbox, false,
     [](const P& p) { return double(p.contours); }, [](P& p, double v) { p.contours = v != 0.0; }},
    {"borders", "borders", "borders", kLines,
     "object-space border lines: edges of one polygon (the rims of open surfaces), hidden parts removed",
     ParamType::Bool, 0, 0, false, {}, ParamEffect::Frame, ParamWidget::Checkbox, false,
     [](const P& p) { return double(p.borders); }, [](P& p, double v) { p.borders = v != 0.0; }},
    {"creases", "creases", "creases", kLines,
     "object-space crease lines: edges whose polygons' normals differ by more than the crease angle, "
     "hidden parts removed",
     ParamType::Bool, 0, 0, false, {}, ParamEffect::Frame, ParamWidget::Checkbox, false,
     [](const P& p) { return double(p.creases); }, [](P& p, double v) { p.creases = v != 0.0; }},
    {"crease_angle", "crease-angle", "crease angle deg", kLines,
     "the dihedral angle in degrees above which an edge is a crease", ParamType::Float, 0.0, 180.0, false, {},
     ParamEffect::Frame, ParamWidget::Slider, false, [](const P& p) { return double(p.crease_angle); },
     [](P& p, double v) { p.crease_angle = float(v); }},
    {"crease_weight", "crease-weight", "crease weight", kLines,
     "crease lines' width as a fraction of silhouette_width: interior lines thinner than the outline, as "
     "illustrators draw them (thinned alike, down to a pixel)",
     ParamType::Float, 0.1, 4.0, false, {}, ParamEffect::Frame, ParamWidget::Slider, false,
     [](const P& p) { return double(p.crease_weight); }, [](P& p, double v) { p.crease_weight = float(v); }},
    {"silhouette", "silhouette", "silhouette", kLines,
     "the old single switch: none, lines (silhouette lines), toon, or both; sets silhouette_lines and toon",
     ParamType::Choice, 0, 0, false, kSilhouetteNames, ParamEffect::Frame, ParamWidget::Hidden, true,
     silhouette_alias_get, silhouette_alias_set, kSilhouetteAliasOf},
};

std::string shortest(double value, ParamType type) {
    if (type == ParamType::Int) return std::to_string((long long)std::llround(value));
    // Floats in their shortest form that reads back to the same float ("0.15", not 0.15000000596...).
    char text[32];
    auto result = std::to_chars(text, text + sizeof(text), float(value));
    return std::string(text, result.ptr);
}

std::string choices_text(const ParamSpec& spec) {
    std::string text;
    for (const char* name : spec.choices) text += std::string(text.empty() ? "" : ", ") + name;
    return text;
}

}  // namespace

const char* density_path_name(DensityPath path) {
    const int index = int(path);
    return index >= 0 && index < int(std::size(kDensityPathNames)) ? kDensityPathNames[index] : "?";
}

std::optional<DensityPath> parse_density_path(const std::string& name) {
    for (size_t i = 0; i < std::size(kDensityPathNames); ++i)
        if (name == kDensityPathNames[i]) return DensityPath(int(i));
    return std::nullopt;
}

std::span<const ParamSpec> param_table() { return kTable; }

const ParamSpec* find_param(std::string_view key) {
    for (const ParamSpec& spec : kTable)
        if (key == spec.key) return &spec;
    return nullptr;
}

std::string param_range_text(const ParamSpec& spec) {
    switch (spec.type) {
        case ParamType::Bool: return "true or false";
        case ParamType::Choice: return "one of " + choices_text(spec);
        case ParamType::Int: return shortest(spec.min, spec.type) + ".." + shortest(spec.max, spec.type);
        case ParamType::Float: break;
    }
    return std::string(spec.min_open ? "> " : ">= ") + shortest(spec.min, spec.type) + " and <= " +
           shortest(spec.max, spec.type);
}

std::string format_param_value(const ParamSpec& spec, double value) {
    switch (spec.type) {
        case ParamType::Bool: return value != 0.0 ? "true" : "false";
        case ParamType::Choice: {
            const int index = int(value);
            return index >= 0 && index < int(spec.choices.size()) ? spec.choices[size_t(index)] : "?";
        }
        case ParamType::Int:
        case ParamType::Float: break;
    }
    return shortest(value, spec.type);
}

namespace {

// For a value too small for single precision, which would be 0: 0 only where the range has it.
std::string underflow_hint(const ParamSpec& spec) {
    const bool zero_allowed = spec.min_open ? 0.0 > spec.min : 0.0 >= spec.min;
    return zero_allowed ? " (single precision holds it as 0: give 0, or at least 1e-38)"
                        : " (single precision holds it as 0: give at least 1e-38)";
}

// Whether decimal text names a nonzero number (a digit 1-9 before any exponent): "1e-400", which a double
// holds as 0, is not 0.
bool names_nonzero(const std::string& text) {
    return text.substr(0, text.find_first_of("eE")).find_first_of("123456789") != std::string::npos;
}

}  // namespace

std::optional<std::string> param_value_problem(const ParamSpec& spec, double value) {
    switch (spec.type) {
        case ParamType::Bool: return std::nullopt;
        case ParamType::Choice:
            if (value >= 0.0 && value < double(spec.choices.size()) && value == std::floor(value)) return std::nullopt;
            return "not one of " + choices_text(spec);
        case ParamType::Int:
            // In double's shortest form: single precision rounded 4294967295.5 to "4294967296 is not an integer".
            if (std::isfinite(value) && value != std::floor(value)) {
                char text[32];
                return std::string(text, std::to_chars(text, text + sizeof(text), value).ptr) + " is not an integer";
            }
            break;
        case ParamType::Float: break;
    }
    // Judged as stored: a Float parameter is a float, so 1e-300 (stored as 0) is below "> 0".
    const double stored = spec.type == ParamType::Float ? double(float(value)) : value;
    const bool above = spec.min_open ? stored > spec.min : stored >= spec.min;
    // Nor is a nonzero value that single precision holds as 0 taken for 0 (--dmax 1e-300 would draw nothing).
    const bool underflows = spec.type == ParamType::Float && value != 0.0 && stored == 0.0;
    if (std::isfinite(stored) && above && stored <= spec.max && !underflows) return std::nullopt;
    if (!std::isfinite(value)) return "the number is not finite";
    const bool whole = spec.type == ParamType::Int && std::abs(value) < 1e15;
    // A value that single precision cannot hold is shown as given ("1e-300", not "0").
    const float as_float = float(value);
    const bool fits_float = std::isfinite(as_float) && (as_float != 0.0f || value == 0.0);
    std::string shown;
    if (whole || fits_float) {
        shown = shortest(value, whole ? ParamType::Int : ParamType::Float);
    } else {
        char text[32];
        shown.assign(text, std::to_chars(text, text + sizeof(text), value).ptr);
    }
    return shown + " is out of range: it must be " + param_range_text(spec) + (underflows ? underflow_hint(spec) : "");
}

double parse_param_text(const ParamSpec& spec, const std::string& text, bool named_by_key) {
    const std::string where = named_by_key ? std::string(spec.key) : "--" + std::string(spec.cli);
    if (spec.type == ParamType::Choice) {
        for (size_t i = 0; i < spec.choices.size(); ++i)
            if (text == spec.choices[i]) return double(i);
        fail(where + " '" + text + "' is not one of " + choices_text(spec));
    }
    if (spec.type == ParamType::Bool) fail(where + " takes no value");
    const std::optional<double> value = parse_decimal(text);
    if (!value) fail(where + ": '" + text + "' is not " + (spec.type == ParamType::Int ? "an integer" : "a finite number"));
    if (spec.type == ParamType::Float && *value == 0.0 && names_nonzero(text))
        fail(where + " = " + text + " is out of range: it must be " + param_range_text(spec) + underflow_hint(spec));
    if (auto problem = param_value_problem(spec, *value)) fail(where + " = " + *problem);
    return *value;
}

double param_lowest_value(const ParamSpec& spec) {
    if (!spec.min_open) return spec.min;
    return spec.min + std::max(1e-6 * (spec.max - spec.min), 1e-9);
}

void validate_params(const ObjectParams& params) {
    for (const ParamSpec& spec : kTable)
        if (auto problem = param_value_problem(spec, spec.get(params))) fail("--" + std::string(spec.cli) + " = " + *problem);
    if (params.ink)
        for (int i = 0; i < 3; ++i)
            if (!((*params.ink)[i] >= 0.0f && (*params.ink)[i] <= 1.0f)) fail("ink: colour components must be in 0..1");
}

bool needs_regeneration(const ObjectParams& a, const ObjectParams& b) {
    return std::any_of(std::begin(kTable), std::end(kTable), [&](const ParamSpec& spec) {
        return spec.effect == ParamEffect::Regenerate && spec.get(a) != spec.get(b);
    });
}

std::vector<double> generation_values(const GenerationParams& generation) {
    ObjectParams params;
    params.generation = generation;
    std::vector<double> values;
    for (const ParamSpec& spec : kTable)
        if (spec.effect == ParamEffect::Regenerate) values.push_back(spec.get(params));
    return values;
}

std::vector<std::string> param_cli_names(const ParamSpec& spec) {
    const std::string name = "--" + std::string(spec.cli);
    if (spec.type != ParamType::Bool) return {name};
    return {name, "--no-" + std::string(spec.cli)};
}

}  // namespace stipple
