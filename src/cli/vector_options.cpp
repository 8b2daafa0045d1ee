#include "cli/vector_options.hpp"

#include "core/error.hpp"

namespace stipple::cli {

std::set<std::string> vector_options() { return {"--page", "--margin", "--fit", "--pen-width", "--dot-style", "--dpi", "--tile"}; }
std::set<std::string> vector_flags() { return {"--fill-paper", "--show-travel"}; }

plot::ExportOptions read_vector_options(const Args& args) {
    plot::ExportOptions options;
    if (args.has("--page")) options.page = plot::parse_page(args.get("--page", ""));
    if (args.has("--margin")) {
        options.margin_mm = args.number("--margin", options.margin_mm);
        if (!(options.margin_mm >= 0.0 && options.margin_mm <= 500.0))
            fail("--margin = " + args.get("--margin", "") + " must be in 0..500 mm");
    }
    if (args.has("--fit")) options.fit = plot::parse_fit(args.get("--fit", ""));
    if (args.has("--pen-width")) {
        const double pen = args.number("--pen-width", plot::kDefaultPenWidthMm);
        if (!(pen > 0.0 && pen <= 10.0)) fail("--pen-width = " + args.get("--pen-width", "") + " must be in (0, 10] mm");
        options.pen_width_mm = pen;
    }
    if (args.has("--dot-style")) options.dot_style = plot::parse_dot_style(args.get("--dot-style", ""));
    options.fill_paper = args.flag("--fill-paper");
    options.show_travel = args.flag("--show-travel");
    return options;
}

std::optional<app::PrintOptions> read_print_options(const Args& args) {
    if (!args.has("--dpi")) {
        if (args.has("--tile")) fail("--tile is for print-resolution images: give --dpi too");
        return std::nullopt;
    }
    if (!args.has("--page")) fail("--dpi needs --page (the page the image is printed on, e.g. A3)");
    app::PrintOptions print;
    print.page = plot::parse_page(args.get("--page", ""));
    print.margin_mm = read_vector_options(args).margin_mm;
    print.dpi = args.number("--dpi", print.dpi);
    const long long height = args.integer("--height", print.screen_height);
    if (height < 64 || height > 16384) fail("--height = " + std::to_string(height) + " must be in 64..16384");
    print.screen_height = uint32_t(height);
    const long long tile = args.integer("--tile", print.max_tile);
    if (tile < 64 || tile > 16384) fail("--tile = " + std::to_string(tile) + " must be in 64..16384 pixels");
    print.max_tile = uint32_t(tile);
    if (args.has("--fit")) print.fit = plot::parse_fit(args.get("--fit", ""));
    return print;
}

}  // namespace stipple::cli
