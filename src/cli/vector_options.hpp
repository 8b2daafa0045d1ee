#pragma once
// The render command's vector and print output options: -o x.svg|x.pdf|x.csv with --page, --margin,
// --pen-width, --dot-style and --fill-paper (src/export, src/app/frame_export.hpp).
#include <set>
#include <string>

#include "cli/args.hpp"
#include <optional>

#include "app/frame_export.hpp"
#include "export/plot_plan.hpp"

namespace stipple::cli {

std::set<std::string> vector_options();  // --page, --margin, --pen-width, --dot-style, --dpi, --tile
std::set<std::string> vector_flags();    // --fill-paper, --show-travel
// The export's options from the command line; throws stipple::Error naming the option.
plot::ExportOptions read_vector_options(const Args& args);
// -o x.png with --dpi: a print-resolution page (--page, --margin; --height is the screen image it enlarges).
std::optional<app::PrintOptions> read_print_options(const Args& args);

}  // namespace stipple::cli
