#pragma once
// The per-object options shared by render, view and info: read from the command line by walking the
// parameter table (src/params/param_table.hpp), so every parameter has one spelling and one range.
#include <set>
#include <string>

#include "cli/args.hpp"
#include "params/object_params.hpp"

namespace stipple::cli {

std::set<std::string> object_flags();    // the Bool parameters: --X and --no-X
std::set<std::string> object_options();  // the others: --X VALUE
// The camera, light and colours render and view take (their help's "Camera, light and colours" section):
// flags (the projection) and options with a value.
std::set<std::string> camera_flags();
std::set<std::string> camera_options();
ObjectParams read_object_params(const Args& args);  // validated

// True when any object option or flag was given (they cannot be combined with a scene file).
std::string first_object_option(const Args& args);

// Fails naming the model when its stipples at D_max `dmax` hold no candidate: there is nothing for tone to
// measure or parity to compare (every figure read 0, and they "agreed").
void require_candidates(const std::string& path, size_t candidates, double dmax, const std::string& nothing_to);

}  // namespace stipple::cli
