#pragma once
// The one table of per-object parameters. For each parameter: its scene-file key, its command-line
// spelling, type, range, help text, whether a change makes new stipples or only a new frame, and how
// the viewer shows it. The command line (src/cli/object_options.cpp), --help (src/cli/usage.cpp),
// scene files (src/scene/scene_json.cpp), the viewer's panel (src/app/panel.cpp), validation, the
// README's parameter list (`stipple params --markdown`) and the stipple cache's key all walk it, so
// a parameter is described once (docs/architecture.md: "Adding a parameter").
//
// Every value travels as a double: booleans as 0/1, choices as their index, integers exactly (all
// ranges are below 2^53).
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "params/object_params.hpp"

namespace stipple {

enum class ParamType { Bool, Int, Float, Choice };

// What a change costs: new stipples (generation, §2.1) or only the next frame.
enum class ParamEffect { Regenerate, Frame };

enum class ParamWidget {
    Checkbox,
    Slider,     // linear
    LogSlider,  // logarithmic: ranges spanning decades
    Input,      // a number field with +/- steps (large integers)
    Combo,      // choices
    Hidden,     // not on the panel (aliases kept for old command lines and scenes)
};

struct ParamSpec {
    const char* key;      // scene-file key, e.g. "dmax"
    const char* cli;      // command-line name without dashes, e.g. "dmax" for --dmax; a Bool has --X and --no-X
    const char* label;    // the panel's label
    const char* section;  // heading it is listed under (--help, panel, README)
    const char* help;     // what it does, with the paper's section; one sentence or two
    ParamType type;
    double min = 0.0, max = 0.0;  // the range of Int and Float values
    bool min_open = false;        // the minimum itself is excluded ("> 0")
    std::span<const char* const> choices;  // Choice: the accepted names, by index
    ParamEffect effect = ParamEffect::Frame;
    ParamWidget widget = ParamWidget::Slider;
    // An alias is read from the command line and scene files but never written, shown or listed as
    // a parameter of its own: it sets other parameters (e.g. the old --silhouette none|lines|toon|both).
    bool alias = false;
    double (*get)(const ObjectParams&) = nullptr;
    void (*set)(ObjectParams&, double) = nullptr;
    // An alias: the keys of the parameters it sets. Giving it with any of them is an error (which one
    // wins would be an accident of the table's order).
    std::span<const char* const> alias_of = {};
};

// Every parameter, in the order --help, the panel and saved scenes list them.
std::span<const ParamSpec> param_table();

// The entry with this scene key, or null.
const ParamSpec* find_param(std::string_view key);

// "> 0 and <= 16", "0..100", "one of vertex, cpu, ...", "true or false".
std::string param_range_text(const ParamSpec& spec);

// The value as written in scenes and shown in --help: "0.25", "8000000", "true", "splat".
std::string format_param_value(const ParamSpec& spec, double value);

// Why `value` is not acceptable for `spec`, e.g. "20 is out of range: it must be > 0 and <= 16";
// nothing when it is. The one wording every entry point uses, each prefixing where the value came
// from ("--dmax = " on the command line, "<file>: objects[0].params.dmax: " in a scene file).
std::optional<std::string> param_value_problem(const ParamSpec& spec, double value);

// Parses command-line text for a non-Bool parameter; throws stipple::Error prefixed "--<cli>", or "<key>"
// with named_by_key (a viewer script sets parameters by their scene keys).
double parse_param_text(const ParamSpec& spec, const std::string& text, bool named_by_key = false);

// The smallest value a slider or input may hold: the minimum, or just above it when it is excluded.
double param_lowest_value(const ParamSpec& spec);

// True when going from `a` to `b` needs new stipples: a Regenerate parameter differs.
bool needs_regeneration(const ObjectParams& a, const ObjectParams& b);

// The values of the Regenerate parameters of `generation`, in table order: what the stipple cache's
// key hashes and what makes two objects share their stipples.
std::vector<double> generation_values(const GenerationParams& generation);

// The parameter's command-line spellings: {"--dmax"} or, for a Bool, {"--shading", "--no-shading"}.
std::vector<std::string> param_cli_names(const ParamSpec& spec);

}  // namespace stipple
