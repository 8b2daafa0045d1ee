#pragma once
// The parameter table as text: the per-object options of `stipple --help`, and the Markdown table in
// README.md (printed by `stipple params --markdown`; a test keeps the README's copy identical).
#include <string>

namespace stipple {

// The options with their ranges and defaults, wrapped to fit 100 columns, grouped by section.
std::string param_help_text();

// One Markdown table row per parameter: scene key, command line, range, default, effect, meaning.
std::string param_markdown_table();

// The "params" object of a scene file with every parameter at its default, on wrapped lines.
std::string param_scene_example();

}  // namespace stipple
