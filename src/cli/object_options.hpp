#pragma once
// The per-object options shared by render and info.
#include <set>
#include <string>

#include "cli/args.hpp"
#include "render/object_params.hpp"

namespace stipple::cli {

std::set<std::string> object_flags();
std::set<std::string> object_options();
ObjectParams read_object_params(const Args& args);  // validated

}  // namespace stipple::cli
