#pragma once
// The render command's vector and print output options: -o x.svg|x.pdf|x.csv with --page, --margin,
// --pen-width, --dot-style and --fill-paper (src/export, src/app/frame_export.hpp).
#include <set>
#include <string>

#include "cli/args.hpp"
#include "export/plot_plan.hpp"

namespace stipple::cli {

std::set<std::string> vector_options();  // --page, --margin, --pen-width, --dot-style
std::set<std::string> vector_flags();    // --fill-paper
// The export's options from the command line; throws stipple::Error naming the option.
plot::ExportOptions read_vector_options(const Args& args);

}  // namespace stipple::cli
