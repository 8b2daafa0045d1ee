#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <cstdio>
#include <map>
#include <optional>
#include <set>
#include <tuple>

#include "core/unit_direction.hpp"
#include "anim/pose.hpp"
#include "cli/animation_options.hpp"
#include "cli/args.hpp"
#include "cli/cache_options.hpp"
#include "app/frame_export.hpp"
#include "cli/commands.hpp"
#include "cli/render_request.hpp"
#include "cli/vector_options.hpp"
#include "export/plot_file.hpp"
#include "export/text_format.hpp"
#include "cli/object_options.hpp"
#include "core/error.hpp"
#include "core/printf_string.hpp"
#include "core/progress.hpp"
#include "core/timing.hpp"
#include "gpu/context.hpp"
#include "io/output_file.hpp"
#include "io/png_io.hpp"
#include "render/object_gpu.hpp"
#include "render/offscreen.hpp"
#include "render/tone_survey.hpp"
#include "render/tiled_render.hpp"
#include "scene/frame_sequence.hpp"
#include "scene/scene_content.hpp"
#include "scene/scene_json.hpp"
#include "stipple/stipple_set.hpp"

namespace stipple::cli {

namespace {

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

// Why the fixed-function depth pass ran where --depth-raster compute was asked (depth_by_compute_this_frame).
std::string fixed_depth_reason(DepthRaster asked, const gpu::Context& context, const Scene& scene) {
    if (asked != DepthRaster::Compute) return "";
    if (std::any_of(scene.objects.begin(), scene.objects.end(), [](const SceneObject& o) { return o.params.toon; }))
        return "; fixed, not compute: a toon object's shading needs the fixed-function pass";
    if (!depth_raster_by_compute(asked, context)) return "; fixed, not compute: this device has no 64-bit atomics";
    return "; fixed, not compute";
}

// The object options belong to a model given on the command line; a scene file sets them per object.
void reject_object_options_with_scene(const Args& args, const std::string& scene) {
    const std::string name = first_object_option(args);
    if (!name.empty()) fail(name + " cannot be combined with a scene file (" + scene + "): set it per object in the file");
}

// Whether every pixel of the image is the same colour. A caller counts it bare paper (no dot, no line, no toon grey)
// where the image shows the paper somewhere: a frame's pixels no surface covers, a print's margins; a tiled image
// uniform all over is taken as paper too (one solid colour over every pixel of a large image is not a drawing).
bool is_blank(const Image& image) {
    const size_t step = size_t(std::max(image.channels, 1));
    for (size_t i = step; i + step <= image.pixels.size(); i += step)
        if (!std::equal(image.pixels.begin() + std::ptrdiff_t(i), image.pixels.begin() + std::ptrdiff_t(i + step), image.pixels.begin()))
            return false;
    return true;
}

// Whether the image's first pixel is the paper's colour, as the colour target stores it (8-bit, rounded).
bool shows_paper(const Image& image, const glm::vec3& paper) {
    if (image.pixels.empty() || image.channels < 3) return true;
    for (int c = 0; c < 3; ++c)
        if (std::abs(int(image.pixels[size_t(c)]) - int(std::lround(std::clamp(paper[c], 0.0f, 1.0f) * 255.0f))) > 1) return false;
    return true;
}

}  // namespace

Scene scene_from_command_line(const Args& args, const std::string& what) {
    Scene scene;
    if (args.positionals().empty()) {
        scene.objects.push_back({default_model_path(), {}, read_object_params(args)});
    } else if (args.positionals().size() == 1 && is_scene_file(args.positionals()[0])) {
        reject_object_options_with_scene(args, args.positionals()[0]);
        scene = load_scene(args.positionals()[0]);
    } else {
        for (const std::string& path : args.positionals())
            if (is_scene_file(path)) fail(what + " takes one SCENE.json on its own, not with other files (" + path + ")");
        ObjectParams params = read_object_params(args);
        // Paths stay as typed, so that loader errors name the file as the user wrote it.
        for (const std::string& path : args.positionals()) scene.objects.push_back({path, {}, params});
    }
    apply_animation_option(args, scene);
    // Explicit view options override the scene's camera and light.
    if (args.has("--yaw")) {
        const double yaw = args.number("--yaw", 0.0);
        if (std::abs(yaw) > 36000.0) fail("--yaw = " + args.get("--yaw", "") + " must be in -36000..36000 degrees");
        scene.camera.yaw_deg = float(yaw);
    }
    if (args.has("--pitch")) {
        const double pitch = args.number("--pitch", 0.0);
        if (std::abs(pitch) > 90.0) fail("--pitch = " + args.get("--pitch", "") + " must be in -90..90 degrees");
        scene.camera.pitch_deg = float(pitch);
    }
    if (args.has("--distance")) {
        double distance = args.number("--distance", 1.0);
        // Below 1e-4 of the framing distance the camera sits inside any model and the projection degenerates
        // (--distance 1e-20 counted every candidate drawn on a blank frame).
        if (!(distance >= 1e-4) || distance > 1e4)
            fail("--distance = " + args.get("--distance", "") + " must be in [0.0001, 10000]");
        scene.camera.distance = float(distance);
        scene.camera.world_distance.reset();
    }
    if (args.has("--light")) {
        const std::optional<glm::vec3> light = unit_direction(args.vec3("--light", scene.light));
        if (!light) fail("--light must not be the zero vector");
        scene.light = *light;
    }
    if (args.flag("--orthographic") && args.flag("--perspective")) fail("--orthographic and --perspective: give one of them");
    if (args.flag("--orthographic")) scene.camera.orthographic = true;
    if (args.flag("--perspective")) scene.camera.orthographic = false;
    scene.paper = args.colour("--paper", scene.paper);
    scene.ink = args.colour("--ink", scene.ink);
    return scene;
}

CommandOptions render_command_options() {
    CommandOptions accepted{object_flags(), object_options()};
    accepted.flags.insert({"--stats", "--list-devices", "--verbose"});
    accepted.flags.merge(camera_flags());
    accepted.flags.merge(vector_flags());
    accepted.options.merge(cache_options());
    accepted.options.merge(vector_options());
    accepted.options.merge(camera_options());
    accepted.options.insert({"--repeat", "-o", "--output", "--mask", "--width", "--height", "--device", "--frames", "--orbit",
                             "--depth-cull", "--depth-raster", "--queued"});
    accepted.options.merge(animation_options());
    return accepted;
}

int run_render(const std::vector<std::string>& argv) {
    const CommandOptions accepted = render_command_options();
    Args args(argv, accepted.flags, accepted.options);
    apply_cache_options(args);

    if (args.flag("--list-devices")) {
        for (const std::string& line : gpu::Context::list_devices()) std::printf("%s\n", line.c_str());
        return 0;
    }
    args.expect_at_most_positionals(1, "render takes at most one MODEL or SCENE.json");
    const RenderRequest request = read_render_request(args);
    const std::string& output = request.output;
    const bool vector = request.vector;
    plot::ExportOptions vector_options = request.vector_options;
    std::optional<app::PrintOptions> print = request.print;
    const long long width = request.width, height = request.height;
    const bool print_of_page_shape = request.print_of_page_shape;
    const long long frames = request.frames, repeat = request.repeat;
    long long queued = request.queued;
    const std::optional<float> orbit = request.orbit;
    Scene scene = scene_from_command_line(args, "render");
    // The projection, not the placement: a camera_path's frames are drawn in the one asked too (the viewer shows
    // the scene's camera and keeps the path as it was for Ctrl+S).
    if (args.flag("--orthographic") || args.flag("--perspective"))
        for (SceneCamera& key : scene.camera_path) key.orthographic = scene.camera.orthographic;
    const std::string what = scene.source.empty() ? scene.model_path(0) : scene.source;
    const SceneInks scene_inks = warn_about_scene_inks(scene, request, what);
    const bool draws_nothing = scene_inks.draws_nothing, one_colour = scene_inks.one_colour;
    const std::vector<glm::vec3>& inks = scene_inks.inks;
    // A scene's camera_path places every frame's camera: options that set the scene's camera, or turn it,
    // would be silently ignored.
    if (!scene.camera_path.empty()) {
        for (const char* name : {"--yaw", "--pitch", "--distance", "--orbit"})
            if (args.has(name))
                fail_file(scene.source, std::string(name) + " sets the camera, but the scene's camera_path places every frame's "
                                        "camera: edit the path, or render without it");
    }

    // Where the files go, once the options are known good and before the model is read and its stipples made
    // (a frame sequence: its first frame's).
    check_output_writable(args.has("--output") ? "--output" : "-o", output_path(output, 0, false));
    if (args.has("--mask")) check_output_writable("--mask", output_path(args.get("--mask", ""), 0, false));

    // The models first: what depends on them is checked before their stipples are generated (minutes for a
    // large model at a high density), and before Vulkan starts.
    auto start = std::chrono::steady_clock::now();
    SceneContent content = load_scene_models(scene);
    double prepare_seconds = seconds_since(start);

    const bool animated = any_animated(content.objects);
    const AnimationClock clock = read_animation_clock(args, animated, !scene.camera_path.empty());
    float aspect = float(width) / float(height);
    if (print_of_page_shape) {
        const VkExtent2D drawing = app::print_layout(*print).drawing_px;
        aspect = float(drawing.width) / float(drawing.height);
    }
    Sphere bounds = scene_bounds(scene, content.objects);
    std::vector<OrbitCamera> cameras = frame_cameras(scene, bounds, aspect, size_t(frames), orbit, animated);
    const bool sequence = cameras.size() > 1;
    // The frames of a sequence line up on their pages unless told otherwise: each fitted to its own
    // drawing would be scaled and moved from frame to frame.
    if (sequence && !args.has("--fit")) {
        vector_options.fit = plot::Fit::Frame;
        if (print) print->fit = plot::Fit::Frame;
    }
    if (sequence) check_sequence_patterns(args, output, cameras.size());
    if (sequence && repeat > 0) fail("--repeat times one frame; it cannot be combined with a frame sequence");

    gpu::ContextOptions context_options;
    context_options.device_index = int(request.device);
    context_options.verbose = args.flag("--verbose");
    gpu::Context context(context_options);
    VkExtent2D extent{uint32_t(width), uint32_t(height)};
    RendererOptions renderer_options;
    renderer_options.count_drawn = args.flag("--stats");
    renderer_options.depth_cull = request.depth_cull;
    renderer_options.depth_raster = request.depth_raster;
    // Larger than one render target holds on this device (the splat's pixel words are one storage buffer):
    // the image is drawn in tiles, as a print is.
    const bool tiled = !print && !fits_one_target(context, extent);
    if (tiled) {
        const uint32_t side = largest_tile_side(context);
        const std::string why = std::to_string(width) + "x" + std::to_string(height) +
                                " is drawn in tiles on this device (one frame holds at most " +
                                std::to_string(uint64_t(side) * side) + " pixels, e.g. " + std::to_string(side) + "x" +
                                std::to_string(side) + ")";
        if (vector) fail("-o " + output + ": vector output reads one frame, and " + why);
        if (args.has("--mask")) fail("--mask needs one frame, and " + why);
        if (repeat > 0) fail("--repeat times one frame, and " + why);
    }
    // A print is drawn by a renderer of its own (app::render_print), and so is vector output
    // (app::export_frame): this one would only hold a second copy of every object's buffers, unless the
    // screen's frame is asked for too (its mask, figures or timings).
    const bool screen_frame = !vector || args.has("--mask") || args.flag("--stats") || repeat > 0;
    // Whether this device can hold the stipples, counted before they are made: the scene's objects together,
    // twice where vector output's renderer and the screen's both hold them, and vector output's lists.
    const std::vector<uint64_t> planned = planned_scene_stipples(scene, content);
    const int copies = vector && screen_frame && !print ? 2 : 1;
    uint64_t planned_bytes = 0;
    const std::string twice = copies == 2 ? " (held twice: vector output with --stats, --mask or --repeat draws the screen's frame too)" : "";
    for (int copy = 0; copy < copies; ++copy)
        for (size_t i = 0; i < planned.size(); ++i) {
            const uint64_t list = vector && copy == 0 ? check_scene_visible_list_fits(context, scene, i, planned[i]) : 0;
            planned_bytes += check_scene_object_fits(context, scene, content, i, planned[i], planned_bytes, twice, list) + list;
        }
    // A D_max the stipple budget caps draws as the cap does: a larger one changes nothing, so it is said (once for
    // the copies of one model).
    std::set<std::tuple<const Mesh*, float, uint64_t>> told;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const GenerationParams& generation = scene.objects[i].params.generation;
        if (!told.insert({content.objects[i].mesh.get(), generation.dmax, generation.max_stipples}).second) continue;
        if (const double dmax = effective_dmax(*content.objects[i].mesh, generation); dmax < 0.999 * double(generation.dmax))
            std::fprintf(stderr, "stipple: note: %s: D_max %g is capped at %g by the stipple budget (max_stipples %llu)\n",
                         scene.model_path(i).c_str(), double(generation.dmax), dmax, (unsigned long long)generation.max_stipples);
    }
    start = std::chrono::steady_clock::now();
    make_scene_stipples(scene, content);
    prepare_seconds += seconds_since(start);
    // A print fitted to its drawing is on a page turned as that drawing is (its first frame's), where the page's
    // name leaves the orientation open, as vector output's is; the cameras then frame the turned page. The
    // drawing is judged in a square frame: in the page's own frame, a scene the camera crops (a camera closer
    // than framing) showed a tall part of itself in a portrait frame and stayed portrait.
    // A frame of the screen's own shape (--width) is judged as it is: its drawing, or with --fit frame the frame.
    bool print_turned = false;
    if (print && !print->page.orientation_given) {
        std::optional<plot::PageSize> turned;
        if (print->fit == plot::Fit::Frame && print->screen_width) {
            turned = plot::oriented_for(print->page, double(width), double(height));
        } else if (print->fit == plot::Fit::Drawing) {
            const VkExtent2D frame = print->screen_width ? extent : VkExtent2D{print->screen_height, print->screen_height};
            const OrbitCamera camera = print->screen_width ? cameras[0] : frame_cameras(scene, bounds, 1.0f, size_t(frames), orbit, animated)[0];
            const FrameView first = scene_frame_view(scene, camera, bounds, frame);
            if (const std::optional<app::DrawnBox> box = app::drawn_box(context, scene, content.objects, first, print->max_tile,
                                                                        animated ? clock.frame_time(0) : 0.0))
                turned = plot::oriented_for(print->page, box->max.x - box->min.x, box->max.y - box->min.y);
        }
        if (turned && turned->width_mm != print->page.width_mm) {
            print->page = *turned;
            print_turned = true;
            if (print_of_page_shape) {
                const VkExtent2D drawing = app::print_layout(*print).drawing_px;
                aspect = float(drawing.width) / float(drawing.height);
                cameras = frame_cameras(scene, bounds, aspect, size_t(frames), orbit, animated);
            }
        }
    }
    StippleRenderer renderer(context, kColorFormat, context.depth_format, renderer_options);
    if (!print && screen_frame) add_scene_objects(renderer, scene, content.objects);
    std::optional<OffscreenTarget> target;
    if (!tiled && !print && screen_frame) target.emplace(context, extent);

    // Frames are written as they are drawn (a long orbit needs no more memory than one frame).
    ProgressBar bar("Rendering frames", sequence);
    RenderedFrame frame;
    plot::PlotStats last_plot;  // vector output: the last frame's
    size_t empty_pages = 0;     // frames (vector output: pages) with nothing drawn
    size_t empty_small_dots = 0;  // on them, dots under the pen's least mark (none drawn by chance)
    FrameStats print_stats;     // a print's, from the renderer that draws it (app::render_print)
    bool print_fitted = false;  // the last print's drawing fitted to its page (not when it drew nothing)
    FrameView view;
    double render_seconds = 0.0;
    std::optional<app::DrawingCapture> capture;  // vector output: one for every frame of the sequence
    for (size_t i = 0; i < cameras.size(); ++i) {
        // A print's camera frames the drawing inside the page's margins (render_print sets its pixels).
        view = scene_frame_view(scene, cameras[i], bounds, print_of_page_shape ? app::print_layout(*print).drawing_px : extent);
        if (animated && !print && screen_frame) set_scene_time(renderer, scene, content.objects, clock.frame_time(i));
        auto render_start = std::chrono::steady_clock::now();
        if (print) {
            const Image page = app::render_print(context, scene, content.objects, view, *print, animated ? clock.frame_time(i) : 0.0,
                                                 args.flag("--stats") ? &print_stats : nullptr, &print_fitted);
            render_seconds = seconds_since(render_start);
            write_png(output_path(output, i, sequence), page, print->dpi);
            empty_pages += is_blank(page);
            bar.update(double(i + 1) / double(cameras.size()));
            continue;
        }
        if (tiled) {
            const Image image = render_tiled(context, renderer, view, largest_tile_side(context));
            render_seconds = seconds_since(render_start);
            write_png(output_path(output, i, sequence), image);
            empty_pages += is_blank(image);
            bar.update(double(i + 1) / double(cameras.size()));
            continue;
        }
        if (screen_frame) frame = target->render(renderer, view);
        render_seconds = seconds_since(render_start);
        if (vector) {
            if (!capture) capture.emplace(context, scene, content.objects);
            last_plot = app::export_frame(*capture, view, vector_options, output_path(output, i, sequence),
                                          animated ? clock.frame_time(i) : 0.0);
            if (last_plot.dots == 0 && last_plot.polylines == 0) {
                ++empty_pages;
                empty_small_dots += last_plot.small_dots;
            }
        } else {
            write_png(output_path(output, i, sequence), frame.color);
            // Blank where its one colour is the paper's: a surface may cover the frame in uniform ink (toon), a line
            // a tiny frame (2x2 drew black and was said empty), and faces that only hide (the inside of a model with
            // holes, seen from within, under object-space lines) may cover it in paper (said drawn until 2026-12-06).
            empty_pages += is_blank(frame.color) && shows_paper(frame.color, scene.paper);
        }
        if (args.has("--mask")) write_png(output_path(args.get("--mask", ""), i, sequence), frame.coverage_mask());
        bar.update(double(i + 1) / double(cameras.size()));
    }
    if (sequence) bar.finish();
    // A blank page is written (a user's script may expect the file), but said: the object was out of view,
    // or too far or too light for a dot, or asked for no stipples.
    const bool no_stipples = std::all_of(scene.objects.begin(), scene.objects.end(),
                                         [](const SceneObject& o) { return o.params.generation.dmax == 0.0f; });
    if (empty_pages > 0 && !draws_nothing && !one_colour)
        std::fprintf(stderr, "stipple: warning: %s: nothing is drawn (no dot, no line)%s\n",
                     sequence ? printf_string("%zu of %zu %s", empty_pages, cameras.size(), vector ? "pages" : "frames").c_str() : output_path(output, 0, false).c_str(),
                     empty_small_dots ? printf_string(" - its %zu dots are under the pen's least mark and none was drawn as it by "
                                                      "chance: a finer --pen-width, or --dot-style filled",
                                                      empty_small_dots).c_str()
                     : no_stipples ? " - D_max is 0 (no stipples) and no line is drawn"
                                   : " - the object is out of view (or the camera inside it), or too far or too light for a dot");

    // Timed frames after the first (which warms caches and the driver's shader compilation).
    std::vector<double> frame_ms;
    std::map<std::string, std::vector<double>> pass_ms;
    if (queued == 0) queued = OffscreenTarget::default_queued_frames(context);
    for (long long i = 0; i < repeat; ++i) {
        frame_ms.push_back(target->draw_queued(renderer, view, int(queued)));
        for (const auto& [pass, ms] : renderer.stats().gpu_ms) pass_ms[pass].push_back(ms);
    }

    if (args.flag("--stats")) {
        // A print is drawn by a renderer of its own (the splat, in tiles); `renderer` drew nothing then.
        const FrameStats& stats = print ? print_stats : renderer.stats();
        const bool in_tiles = tiled || print.has_value();
        // The tone as `tone` measures it (measure_ink: from the paper's luminance toward the ink's over the covered
        // pixels, 1 - luminance for black on white), grey ink included:
        // counting the pixels darker than half (until 2026-12-05) read a faint drawing's 1.08% as 0.1%.
        // Objects of inks of other luminances have no one scale from paper to ink.
        const bool one_ink_luminance = std::all_of(inks.begin(), inks.end(), [&](glm::vec3 c) {
            return std::abs(luminance(c) - luminance(inks.front())) < 0.02f;
        });
        const InkFigures ink = measure_ink(frame, scene.paper, inks.front());
        if (scene.source.empty())
            std::printf("model:              %s\n", what.c_str());
        else
            std::printf("scene:              %s (%zu object%s)\n", what.c_str(), scene.objects.size(),
                        scene.objects.size() == 1 ? "" : "s");
        std::printf("device:             %s\n", context.device_name.c_str());
        std::printf("triangles:          %llu\n", (unsigned long long)stats.triangles);
        uint64_t depth_triangles = 0;
        for (size_t i = 0; i < renderer.object_count(); ++i) depth_triangles += renderer.read_depth_triangles(i);
        if (print)
            std::printf("depth pass:         per tile of the print\n");
        else if (renderer.depth_words())
            std::printf("depth pass:         by compute (--depth-raster %s)\n", depth_raster_name(request.depth_raster));
        else
            std::printf("depth pass:         %llu triangles (%.1f%%; --depth-cull %s)%s\n", (unsigned long long)depth_triangles,
                        stats.triangles ? 100.0 * double(depth_triangles) / double(stats.triangles) : 0.0,
                        depth_cull_name(request.depth_cull), fixed_depth_reason(request.depth_raster, context, scene).c_str());
        std::printf("candidate stipples: %llu\n", (unsigned long long)stats.candidate_stipples);
        // Counted by the density, hidden ones too (a tester read the count as the dots seen: --two-sided near a
        // surface counted 26,189 for an image of 1,761); vector output's plot line counts the visible ones.
        std::printf("drawn stipples:     %lld (by the density, before hidden-stipple removal%s)\n", (long long)stats.drawn_stipples,
                    vector ? "; the plot's dots are those visible" : "");
        // The plot's line under the scene's header with the rest (it came before the header until 2026-12-05).
        if (vector) std::printf("%s%s\n", plot::format_stats(last_plot).c_str(), sequence ? " (last frame)" : "");
        std::string paths;
        for (const SceneObject& o : scene.objects)
            if (paths.find(density_path_name(o.params.density_path)) == std::string::npos)
                paths += std::string(paths.empty() ? "" : ", ") + density_path_name(o.params.density_path);
        std::printf("density path:       %s%s\n", paths.c_str(), print ? " (a print is drawn by the splat)" : "");
        for (size_t i = 0; i < content.objects.size(); ++i) {
            const ObjectData& o = content.objects[i];
            if (!o.motion) continue;
            const size_t chosen = size_t(resolve_animation(o, scene.objects[i].animation));
            const anim::Animation& a = o.motion.model->animations[chosen];
            // The time into the animation the frame shows (looped or held), not the scene clock's.
            const std::string named = a.name.empty() ? "animation " + std::to_string(chosen) : quoted_excerpt(a.name, 120);  // as info names it
            std::printf("animation:          object %zu: %s (%.3f s) at %.3f s%s\n", i, named.c_str(), a.duration,
                        anim::animation_time(a, scene.objects[i].animation.time_at(clock.frame_time(cameras.size() - 1)),
                                             scene.objects[i].animation.loop),
                        sequence ? " (last frame)" : "");
        }
        for (const auto& [pass, ms] : stats.gpu_ms)
            std::printf("gpu %-16s%.3f ms%s\n", (pass + ":").c_str(), ms, in_tiles ? " (the last tile)" : "");
        if (paths.find("cpu") != std::string::npos)
            std::printf("cpu density:        %.3f ms\n", stats.cpu_density_ms);
        if (in_tiles) {
            std::printf("covered pixels:     not measured (drawn in tiles)\n");
        } else {
            std::printf("covered pixels:     %zu\n", ink.covered);
            if (!one_ink_luminance)
                std::printf("mean ink inside:    not measured (the objects' inks are of different luminances)\n");
            else if (!ink_readable(scene.paper, inks.front()))
                std::printf("mean ink inside:    not measured (the paper and the ink are of about the same luminance)\n");
            else
                std::printf("mean ink inside:    %.2f%% (of the way from the paper's luminance to the ink's over the covered "
                            "pixels, as tone measures: 1 - luminance for black on white)\n",
                            100.0 * ink.mean());
        }
        std::printf("load + generation:  %.3f s (generation %.3f s)\n", prepare_seconds, content.generation_seconds);
        std::printf("render + readback:  %.3f s%s\n", render_seconds, sequence ? " (last frame)" : "");
    }
    if (repeat > 0) {
        std::printf("frames timed:       %lld (after one warm-up frame)%s\n", repeat,
                    queued > 1 ? printf_string(", each the wall time of %lld queued back to back over %lld", queued, queued).c_str()
                               : "");
        std::printf("frame time:         median %.2f ms (%.1f fps), min %.2f, max %.2f\n", median(frame_ms),
                    1000.0 / median(frame_ms), *std::min_element(frame_ms.begin(), frame_ms.end()),
                    *std::max_element(frame_ms.begin(), frame_ms.end()));
        // The least too: on a shared machine the median moves with the load, the least much less.
        for (auto& [pass, values] : pass_ms)
            std::printf("gpu %-16s median %.3f ms, min %.3f\n", (pass + ":").c_str(), median(values),
                        *std::min_element(values.begin(), values.end()));
    }
    // What each file holds: a print's page, a vector page, or the image's pixels.
    std::string holds = printf_string("%lldx%lld", width, height);
    if (print) {
        const VkExtent2D page = app::print_layout(*print).page_px;
        holds = printf_string("%ux%u, %s%s at %g dpi, %s", page.width, page.height, args.get("--page", "").c_str(),
                              print_turned ? " landscape" : "", print->dpi,
                              print_fitted ? "the drawing fitted to it"
                              : print->fit == plot::Fit::Drawing ? "the frame's view: nothing is drawn to fit"
                                                                 : "the frame's view");
    } else if (vector) {
        // A CSV holds the dots alone (one row each); the lines go to an SVG or a PDF.
        const std::string lines = plot::is_csv_path(output) ? (last_plot.polylines ? printf_string(" (its %zu polylines are not written to CSV: use .svg or .pdf)", last_plot.polylines) : std::string())
                                                            : printf_string(", %zu polylines", last_plot.polylines);
        holds = plot::format_number(last_plot.page.width_mm, 6) + "x" + plot::format_number(last_plot.page.height_mm, 6) +  // 100.9 as given (it said 101)
                printf_string(" mm page: %zu dots%s%s; %s at %lldx%lld", last_plot.dots, lines.c_str(), sequence ? " in the last frame" : "",
                              last_plot.fit == plot::Fit::Drawing ? "the drawing fitted to it, from the frame's view" : "the frame's view",
                              width, height);
    }
    if (sequence)
        std::printf("wrote %zu frames %s .. %s (%s)\n", cameras.size(), frame_path(output, 0).c_str(),
                    frame_path(output, cameras.size() - 1).c_str(), holds.c_str());
    else
        std::printf("wrote %s (%s)\n", output_path(output, 0, false).c_str(), holds.c_str());
    if (args.has("--mask")) {  // its own line: the frame's coverage, beside any output
        const std::string mask = args.get("--mask", "");
        if (sequence)
            std::printf("wrote %zu masks %s .. %s\n", cameras.size(), frame_path(mask, 0).c_str(),
                        frame_path(mask, cameras.size() - 1).c_str());
        else
            std::printf("wrote %s (the coverage mask, %lldx%lld)\n", output_path(mask, 0, false).c_str(), width, height);
    }

    if (uint32_t messages = context.validation_message_count()) {
        std::fprintf(stderr, "stipple: %u Vulkan validation message(s): the render is not trustworthy\n", messages);
        return 2;
    }
    return 0;
}

}  // namespace stipple::cli
