#include "cli/render_request.hpp"

#include <cmath>
#include <algorithm>
#include <filesystem>
#include <set>
#include <system_error>

#include "cli/vector_options.hpp"
#include "core/error.hpp"
#include "render/tone_survey.hpp"
#include "scene/frame_sequence.hpp"

namespace stipple::cli {

namespace {

// A path as written, made absolute and normal: two patterns that name one file for different frames
// (g%d.png and g1%d.png: frame 10 and mask 0) compare equal.
std::string normal_path(const std::string& path) { return std::filesystem::absolute(path).lexically_normal().string(); }

}  // namespace

bool same_file(const std::string& a, const std::string& b) {
    std::error_code ec;
    return std::filesystem::weakly_canonical(std::filesystem::absolute(a), ec) ==
           std::filesystem::weakly_canonical(std::filesystem::absolute(b), ec);
}

std::string output_path(const std::string& pattern, size_t index, bool sequence) {
    if (sequence) return frame_path(pattern, index);
    try {
        return frame_path(pattern, index);
    } catch (const Error&) {  // not a pattern (50%.png): as written, but for %%, a literal % everywhere
        return unescape_percent(pattern);
    }
}

RenderRequest read_render_request(const Args& args) {
    if (args.has("-o") && args.has("--output"))
        fail("-o " + args.get("-o", "") + " and --output " + args.get("--output", "") + " name the output twice: give one");
    const std::string output = args.get("--output", args.get("-o", "stipple.png"));
    // -o x.svg, x.pdf or x.csv: the frame's visible stipples and lines as vector output.
    const bool vector = plot::is_plot_path(output);
    // Named by its extension: a PNG written to x.jpg would be a file its name misdescribes.
    if (!vector && !plot::is_png_path(output))
        fail("-o " + output + ": the output is named by its extension: .png, or .svg, .pdf or .csv for vector output");
    if (args.has("--mask")) {
        const std::string mask = args.get("--mask", "");
        if (!plot::is_png_path(mask)) fail("--mask " + mask + ": the coverage mask is a PNG (.png)");
        // The same file however it is named (relative, absolute, through a link), and for frame sequences
        // however the number is written (%d and %01d); the last frame is checked once the frames are known.
        if (same_file(output_path(mask, 0, false), output_path(output, 0, false)))
            fail("--mask " + mask + " is the image's own path (-o): give it another");
    }
    plot::ExportOptions vector_options = read_vector_options(args);
    if (vector) plot::check_page_for_format(output, vector_options.page.width_mm, vector_options.page.height_mm);
    // -o x.png with --dpi and --page: a print-resolution page, drawn in tiles. Vector output first: "--dpi needs
    // --page" sent the user to add a page that was then refused for the format.
    if (vector && args.has("--dpi")) fail("--dpi is for PNG output; vector output (" + output + ") has no resolution");
    if (vector && args.has("--tile")) fail("--tile is for print-resolution PNG output; vector output (" + output + ") has no tiles");
    std::optional<app::PrintOptions> print = read_print_options(args);
    if (print) app::print_layout(*print);  // its page checks (size, margins, dpi) before any drawing
    if (args.flag("--fill-paper") && plot::is_csv_path(output))
        fail("--fill-paper paints the page of SVG or PDF output; a CSV (" + output + ") has no page");
    // The option and what it sets, in the refusals below.
    const auto what_it_sets = [](const std::string& name) {
        return name + (name == "--pen-width" ? " sets the pen of SVG or PDF output's lines and dots" : " sets how SVG or PDF output draws its dots");
    };
    for (const char* name : {"--dot-style", "--pen-width"})
        if (args.has(name) && plot::is_csv_path(output))
            fail(what_it_sets(name) + "; a CSV (" + output + ") lists each dot's centre and ink radius");
    if (args.flag("--show-travel") && !plot::is_svg_path(output))
        fail("--show-travel draws the pen-up moves into an SVG: give -o x.svg (not " + output + ")");
    if (!vector && !print && args.has("--fit"))
        fail("--fit is for vector output (-o x.svg, x.pdf or x.csv) or print images (--dpi)");
    if (!vector && !print) {
        for (const char* name : {"--page", "--margin"})
            if (args.has(name)) fail(std::string(name) + " is for vector output (-o x.svg, x.pdf or x.csv) or print images (--dpi)");
        for (const char* name : {"--pen-width", "--dot-style"})
            if (args.has(name)) fail(what_it_sets(name) + ": give -o x.svg or x.pdf");
        if (args.flag("--fill-paper")) fail("--fill-paper paints the page of vector output (-o x.svg or x.pdf); a PNG has its paper");
    }
    if (print) {
        // A print image draws the stipples and lines as the screen does, at the page's resolution.
        for (const char* name : {"--pen-width", "--dot-style"})
            if (args.has(name)) fail(what_it_sets(name) + "; a print image (--dpi) draws them as the screen does");
        if (args.flag("--fill-paper")) fail("--fill-paper paints the page of vector output (-o x.svg or x.pdf); a print image has its paper");
    }
    if (print && (args.has("--repeat") || args.has("--mask")))
        fail("--dpi renders a print image; --repeat and --mask are for screen images");
    long long width = args.integer("--width", 1280), height = args.integer("--height", 1024);
    if (width < 1 || width > 16384 || height < 1 || height > 16384)
        fail("--width/--height must be between 1 and 16384 (got " + std::to_string(width) + "x" +
             std::to_string(height) + ")");
    // A print enlarges a screen frame of --height rows: --width gives it the shape of the screen image it should
    // look like (the same composition as -o x.png or x.svg at that size); without it the frame takes the page's.
    if (print && args.has("--width")) print->screen_width = uint32_t(width);
    const bool print_of_page_shape = print && !print->screen_width;
    long long device = device_index(args);
    long long repeat = args.integer("--repeat", 0);
    if (repeat < 0 || repeat > 100000) fail("--repeat = " + std::to_string(repeat) + " must be in 0..100000");
    long long queued = args.integer("--queued", 0);  // 0: by the device (OffscreenTarget::default_queued_frames)
    if (args.has("--queued") && (queued < 1 || queued > 1000)) fail("--queued = " + std::to_string(queued) + " must be in 1..1000");
    if (args.has("--queued") && repeat == 0) fail("--queued queues the frames --repeat times: give --repeat N");
    const std::string depth_cull_arg = args.get("--depth-cull", "auto");
    const std::optional<DepthCull> depth_cull = parse_depth_cull(depth_cull_arg);
    if (!depth_cull) fail("--depth-cull = " + depth_cull_arg + " must be auto, on or off");
    const std::string depth_raster_arg = args.get("--depth-raster", "auto");
    const std::optional<DepthRaster> depth_raster = parse_depth_raster(depth_raster_arg);
    if (!depth_raster) fail("--depth-raster = " + depth_raster_arg + " must be auto, compute or fixed");
    long long frames = args.integer("--frames", 0);
    if (frames < 0 || frames > 100000 || (args.has("--frames") && frames < 1))
        fail("--frames = " + std::to_string(frames) + " must be in 1..100000");
    std::optional<float> orbit;
    if (args.has("--orbit")) {
        double deg = args.number("--orbit", 0.0);
        // As typed, as --yaw says it: std::to_string wrote 1e30 in 40 digits.
        if (std::abs(deg) > 36000.0) fail("--orbit = " + args.get("--orbit", "") + " must be in -36000..36000 degrees");
        if (!args.has("--frames")) fail("--orbit needs --frames N (the number of frames of the orbit)");
        orbit = float(deg);
    }

    RenderRequest request;
    request.output = output;
    request.vector = vector;
    request.vector_options = vector_options;
    request.print = print;
    request.width = width;
    request.height = height;
    request.print_of_page_shape = print_of_page_shape;
    request.device = device;
    request.repeat = repeat;
    request.queued = queued;
    request.frames = frames;
    request.depth_cull = *depth_cull;
    request.depth_raster = *depth_raster;
    request.orbit = orbit;
    return request;
}

void check_sequence_patterns(const Args& args, const std::string& output, size_t frame_count) {
    if (!has_frame_number(output))
        fail("-o " + output + " has no frame number for " + std::to_string(frame_count) +
             " frames: use a pattern such as frames/%04d.png");
    if (args.has("--mask")) {
        const std::string mask = args.get("--mask", "");
        bool numbered = false;
        try {
            numbered = has_frame_number(mask);
        } catch (const Error& e) {
            fail(std::string("--mask: ") + e.what());  // named as --mask's pattern, not -o's
        }
        if (!numbered) fail("--mask " + mask + " has no frame number: use a pattern such as masks/%04d.png");
        // No mask frame may name an image frame's file (g1%d.png's mask 0 is g%d.png's frame 10): compared as
        // written, made absolute and normal, and the last frames through links too.
        std::set<std::string> images;
        for (size_t i = 0; i < frame_count; ++i) images.insert(normal_path(output_path(output, i, true)));
        for (size_t i = 0; i < frame_count; ++i)
            if (images.count(normal_path(output_path(mask, i, true))) ||
                (i + 1 == frame_count && same_file(output_path(mask, i, true), output_path(output, i, true))))
                fail("--mask " + mask + " names the file of an image of -o " + output + " for frame " + std::to_string(i) +
                     " (" + output_path(mask, i, true) + "): give it another");
    }
}

SceneInks warn_about_scene_inks(const Scene& scene, const RenderRequest& request, const std::string& what) {
    // D_max 0 everywhere with no line and no toon asked draws bare paper, whatever the output: said once here.
    SceneInks result;
    result.draws_nothing = std::all_of(scene.objects.begin(), scene.objects.end(), [](const SceneObject& o) {
        const ObjectParams& p = o.params;
        return p.generation.dmax == 0.0f && !p.silhouette_lines && !p.contours && !p.borders && !p.creases && !p.toon;
    });
    if (result.draws_nothing)
        std::fprintf(stderr, "stipple: warning: %s: D_max is 0 (no stipples) and no line or toon is asked: nothing is drawn\n",
                     what.c_str());
    // A scene's paper and ink of one colour draw a plain image without a word otherwise (vector output paints no
    // paper unless asked, and a CSV has no colour). Each object draws in its own ink where it has one.
    std::vector<glm::vec3>& inks = result.inks;
    for (const SceneObject& o : scene.objects) inks.push_back(o.params.ink.value_or(scene.ink));
    result.one_colour = std::all_of(inks.begin(), inks.end(), [&](glm::vec3 ink) {
        return glm::all(glm::lessThan(glm::abs(scene.paper - ink), glm::vec3(0.02f)));
    });
    if ((!request.vector || request.vector_options.fill_paper) && result.one_colour)
        std::fprintf(stderr, "stipple: warning: %s: the paper and the ink are the same colour: the drawing will not show\n",
                     what.c_str());
    // Light ink for dark paper, on a page left unpainted (vector output without --fill-paper): white paper shows.
    const bool light_ink = std::any_of(inks.begin(), inks.end(), [&](glm::vec3 ink) { return luminance(ink) > luminance(scene.paper) + 0.3f; });
    if (request.vector && !plot::is_csv_path(request.output) && !request.vector_options.fill_paper && light_ink)
        std::fprintf(stderr, "stipple: warning: %s: the ink is lighter than the paper, and %s leaves the page unpainted "
                             "(the sheet it is printed on shows): --fill-paper paints it\n",
                     what.c_str(), request.output.c_str());
    return result;
}

}  // namespace stipple::cli
