#include "cli/vector_options.hpp"

#include "core/error.hpp"

namespace stipple::cli {

std::set<std::string> vector_options() { return {"--page", "--margin", "--pen-width", "--dot-style"}; }
std::set<std::string> vector_flags() { return {"--fill-paper"}; }

plot::ExportOptions read_vector_options(const Args& args) {
    plot::ExportOptions options;
    if (args.has("--page")) options.page = plot::parse_page(args.get("--page", ""));
    if (args.has("--margin")) {
        options.margin_mm = args.number("--margin", options.margin_mm);
        if (!(options.margin_mm >= 0.0 && options.margin_mm <= 500.0))
            fail("--margin = " + args.get("--margin", "") + " must be in 0..500 mm");
    }
    if (args.has("--pen-width")) {
        const double pen = args.number("--pen-width", plot::kDefaultPenWidthMm);
        if (!(pen > 0.0 && pen <= 10.0)) fail("--pen-width = " + args.get("--pen-width", "") + " must be in (0, 10] mm");
        options.pen_width_mm = pen;
    }
    if (args.has("--dot-style")) options.dot_style = plot::parse_dot_style(args.get("--dot-style", ""));
    options.fill_paper = args.flag("--fill-paper");
    return options;
}

}  // namespace stipple::cli
