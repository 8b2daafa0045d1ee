#pragma once
// The stipple cache's options (render, view, info) and the `stipple cache` command's helpers.
#include <set>
#include <string>

#include "cli/args.hpp"

namespace stipple::cli {

std::set<std::string> cache_options();  // --cache-dir DIR, --cache-size SIZE
// Sets the process's stipple cache (stipple_cache_settings) from them.
void apply_cache_options(const Args& args);

}  // namespace stipple::cli
