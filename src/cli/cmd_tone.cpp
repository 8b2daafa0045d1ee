// stipple tone: does a model keep its tone as it moves away (§2.3, Figures 3-6)? Prints the mean ink
// inside the object's footprint at each distance, with the extrinsic enhancement on and off, and with
// --regimes where the stipples the tone asks for go (src/render/tone_survey.hpp).
#include <cmath>
#include <cstdio>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/unit_direction.hpp"
#include "cli/args.hpp"
#include "cli/cache_options.hpp"
#include "cli/commands.hpp"
#include "cli/object_options.hpp"
#include "core/decimal.hpp"
#include "core/error.hpp"
#include "core/printf_string.hpp"
#include "gpu/context.hpp"
#include "render/object_gpu.hpp"
#include "render/tone_survey.hpp"
#include "stipple/object_data.hpp"

namespace stipple::cli {

namespace {

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::stringstream stream(text);
    std::string part;
    while (std::getline(stream, part, separator)) parts.push_back(part);
    return parts;
}

double parse_number(const std::string& text, const std::string& option) {
    const std::optional<double> value = parse_decimal(text);
    if (!value) fail(option + ": '" + text + "' is not a finite number");
    return *value;
}

std::vector<float> parse_distances(const std::string& text) {
    std::vector<float> distances;
    for (const std::string& part : split_list("--distances", text)) {
        double d = parse_number(part, "--distances");
        if (!(d >= 1e-4) || d > 1e4) fail("--distances: " + part + " must be in [0.0001, 10000]");
        // Compared as the table and --images name them (%g): a repeat drew the same column twice.
        for (float earlier : distances)
            if (printf_string("%g", earlier) == printf_string("%g", float(d)))
                fail("--distances: '" + part + "' is the same distance as an earlier one, as the table names them");
        distances.push_back(float(d));
    }
    if (distances.empty() || distances.size() > 64) fail("--distances needs 1 to 64 comma-separated values");
    return distances;
}

// YAW:PITCH pairs, comma-separated: "30:10,120:-20".
std::vector<std::array<float, 2>> parse_views(const std::string& text) {
    std::vector<std::array<float, 2>> views;
    for (const std::string& part : split_list("--views", text)) {
        std::vector<std::string> angles = split(part, ':');
        if (angles.size() != 2) fail("--views: '" + part + "' is not YAW:PITCH (degrees)");
        double yaw = parse_number(angles[0], "--views"), pitch = parse_number(angles[1], "--views");
        if (std::abs(yaw) > 360.0 || std::abs(pitch) > 89.0)
            fail("--views: '" + part + "' needs a yaw in [-360, 360] and a pitch in [-89, 89]");
        // The table names a view to 0.1 degree and --images by %g: two views closer than that wrote one
        // set of files and two rows that read the same.
        const float y0 = float(yaw), p0 = float(pitch);  // compared as they are kept (30.05 rounds either way)
        for (const auto& [y, p] : views)
            if (std::round(10.0f * y) == std::round(10.0f * y0) && std::round(10.0f * p) == std::round(10.0f * p0))
                fail("--views: '" + part + "' is the same view as an earlier one to 0.1 degree (the table shows views to 0.1 degree)");
        views.push_back({float(yaw), float(pitch)});
    }
    if (views.empty() || views.size() > 16) fail("--views needs 1 to 16 YAW:PITCH pairs");
    return views;
}

// Seeds, comma-separated: "1,2,3".
std::vector<uint64_t> parse_seeds(const std::string& text) {
    std::vector<uint64_t> seeds;
    for (const std::string& part : split_list("--seeds", text)) {
        const double seed = parse_number(part, "--seeds");
        if (seed < 0.0 || seed > 4294967295.0 || seed != std::floor(seed))
            fail("--seeds: '" + part + "' is not a whole number in [0, 4294967295]");
        if (std::find(seeds.begin(), seeds.end(), uint64_t(seed)) != seeds.end())
            fail("--seeds: '" + part + "' is named twice (its table would be averaged in twice)");
        seeds.push_back(uint64_t(seed));
    }
    if (seeds.empty() || seeds.size() > 16) fail("--seeds needs 1 to 16 comma-separated seeds");
    return seeds;
}

// One row per view: the mean ink at each distance and its max/min. `label` names the seed, if several.
// A max/min cell: "-" where fewer than two distances covered a pixel.
void print_figure(double figure) {
    if (std::isnan(figure)) std::printf(" - |\n");
    else std::printf(" %.3f |\n", figure);
}

void print_table(const ToneSurvey& survey, const ToneSurveyOptions& options, const char* extrinsic,
                 const std::string& label = "") {
    for (size_t v = 0; v < options.views.size(); ++v) {
        std::printf("| %-3s | %6.1f:%-5.1f |", extrinsic, options.views[v][0], options.views[v][1]);
        if (!label.empty()) std::printf(" %s |", label.c_str());
        for (const ToneSample& s : survey.samples) {
            if (s.covered(v)) std::printf(" %.4f |", s.mean_ink[v]);
            else std::printf(" - |");  // nothing covered: no tone to read (and none counted in max/min)
        }
        print_figure(survey.max_over_min(v));
    }
}

// The surveys of several seeds as one: each distance's ink averaged over the seeds (the tone under the
// noise of which stipples and polygons one seed draws), and the mean of the seeds' own figures.
void print_seed_average(const std::vector<ToneSurvey>& surveys, const ToneSurveyOptions& options, const char* extrinsic) {
    print_table(mean_survey(surveys), options, extrinsic, "mean");
    for (size_t v = 0; v < options.views.size(); ++v) {
        double figures = 0.0;
        for (const ToneSurvey& s : surveys) figures += s.max_over_min(v);
        std::printf("| %-3s | %6.1f:%-5.1f | mean of the seeds' max/min |", extrinsic, options.views[v][0],
                    options.views[v][1]);
        for (size_t i = 0; i < surveys.front().samples.size(); ++i) std::printf(" |");
        print_figure(figures / double(surveys.size()));
    }
}

// How far sampling alone can move a figure: a view's mean ink at a distance rests on the dots drawn there
// (about its ink over a dot's point_size^2 pixels, summed over the view's frames), and a count of N varies
// by up to about 1/sqrt(N) from view to view, frame to frame and seed to seed (less where the dots are
// blue noise or polygons large enough to draw their exact count: the fox over 64 frames at 1/16, about
// 3,200 dots and 1.8% by this rule, moved by 0.9% from seed to seed). Said where that exceeds 2.5%:
// the 5% tone figure cannot be read there from one frame (at 1/16 of a 1280x1024 frame the
// default scene draws about 240 dots, the fox about 30).
void print_sampling_note(const ToneSurvey& survey, const ToneSurveyOptions& options, float point_size) {
    const double dot = std::max(1.0, double(point_size) * double(point_size));
    double fewest = -1.0;
    float at = 0.0f;
    for (const ToneSample& s : survey.samples)
        for (size_t v = 0; v < s.ink.size(); ++v)
            if (s.covered(v) && (fewest < 0.0 || s.ink[v].ink / dot < fewest)) fewest = s.ink[v].ink / dot, at = s.distance;
    if (fewest < 0.0) return;
    const double spread = 1.0 / std::sqrt(std::max(fewest, 1.0));
    if (spread <= 0.025) return;
    std::printf("\nSampling: at d=%g a view's figure rests on about %.0f dots (its ink over point_size^2, summed over "
                "its %d frame(s)), so sampling alone can move it by about +-%.1f%% (1/sqrt of the dots) between views, "
                "frames and seeds, and more where few polygons draw them (a polygon selected or not takes all its dots, "
                "and every frame keeps the seed's choice: only --seeds averages that). More frames (--frames, up to "
                "64, with --arc 360), seeds (--seeds) or pixels (--width, --height) steady it.\n",
                at, fewest, options.frames, 100.0 * spread);
}

void print_regimes(const ToneSurvey& survey, const ToneSurveyOptions& options, float point_size) {
    std::printf("\nWhere the tone goes (extrinsic on; stipples summed over the frames; owed: area x density x "
                "every term, allowed: the same from the integer candidates, expected: probability x drawn density; counts in "
                "stipples' ink, an enlarged dot counting as the stipples it stands for):\n");
    for (size_t v = 0; v < options.views.size(); ++v) {
        std::printf("\nview %.1f:%.1f\n", options.views[v][0], options.views[v][1]);
        std::printf("| distance | regime | polygons | owed | allowed | expected | drawn | drawn/owed |\n");
        std::printf("|---:|---|---:|---:|---:|---:|---:|---:|\n");
        for (const ToneSample& s : survey.samples) {
            const ToneTally& tally = s.tallies[v];
            for (size_t r = 0; r < kToneRegimeCount; ++r) {
                const RegimeTally& t = tally.regimes[r];
                if (t.polygons == 0) continue;
                std::printf("| %g | %s | %zu | %.1f | %.1f | %.1f | %.1f | %.3f |\n", s.distance,
                            tone_regime_name(ToneRegime(r)), t.polygons, t.owed, t.allowed, t.expected, t.drawn,
                            t.owed > 0.0 ? t.drawn / t.owed : 0.0);
            }
            const RegimeTally total = tally.total();
            std::printf("| %g | all | %zu | %.1f | %.1f | %.1f | %.1f | %.3f |\n", s.distance, total.polygons, total.owed,
                        total.allowed, total.expected, total.drawn, total.owed > 0.0 ? total.drawn / total.owed : 0.0);
        }
        // On the screen: ink per drawn stipple against an isolated dot's (point_size^2 pixels).
        std::printf("\n| distance | covered px | ink px | drawn stipples | unshared ink / (drawn x point_size^2) | "
                    "off the surface | hidden (whole dots) | ink / unshared ink | owed x point_size^2 / covered | mean ink |\n"
                    "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
        const double dot = double(point_size) * double(point_size);
        for (const ToneSample& s : survey.samples) {
            const InkFigures& ink = s.ink[v];
            const RegimeTally total = s.tallies[v].total();
            const double footprint = ink.unshared_ink + ink.off_surface_ink + ink.hidden_ink;
            std::printf("| %g | %zu | %.0f | %.0f | %.3f | %.3f | %.3f (%.3f) | %.3f | %.4f | %.4f |\n", s.distance, ink.covered,
                        ink.ink, total.drawn, total.drawn > 0.0 ? ink.unshared_ink / (total.drawn * dot) : 0.0,
                        footprint > 0.0 ? ink.off_surface_ink / footprint : 0.0,
                        footprint > 0.0 ? ink.hidden_ink / footprint : 0.0,
                        footprint > 0.0 ? ink.hidden_whole_ink / footprint : 0.0,
                        ink.unshared_ink > 0.0 ? ink.ink / ink.unshared_ink : 0.0,
                        ink.covered ? total.owed * dot / double(ink.covered) : 0.0, ink.mean());
        }
    }
}

}  // namespace

CommandOptions tone_command_options() {
    CommandOptions accepted{object_flags(), object_options()};
    accepted.flags.insert({"--regimes", "--orthographic"});
    accepted.options.insert({"--views", "--distances", "--width", "--height", "--frames", "--arc", "--light", "--device", "--fov",
                             "--images", "--seeds"});
    accepted.options.merge(cache_options());  // it makes (and keeps) stipples as render does
    return accepted;
}

int run_tone(const std::vector<std::string>& argv) {
    const CommandOptions accepted = tone_command_options();
    Args args(argv, accepted.flags, accepted.options);
    args.expect_at_most_positionals(1, "tone takes at most one MODEL");
    apply_cache_options(args);
    const std::string path = args.positionals().empty() ? default_model_path() : args.positionals()[0];
    if (args.flag("--extrinsic") || args.flag("--no-extrinsic"))
        fail("tone draws every table with the extrinsic enhancement on and off; drop --extrinsic/--no-extrinsic");

    ToneSurveyOptions options;
    long long width = args.integer("--width", 1280), height = args.integer("--height", 1024);
    if (width < 16 || width > 16384 || height < 16 || height > 16384)
        fail("--width/--height must be between 16 and 16384 (got " + std::to_string(width) + "x" +
             std::to_string(height) + ")");
    options.extent = {uint32_t(width), uint32_t(height)};
    if (args.has("--distances")) options.distances = parse_distances(args.get("--distances", ""));
    if (args.has("--views")) options.views = parse_views(args.get("--views", ""));
    long long frames = args.integer("--frames", 1);
    if (frames < 1 || frames > 64) fail("--frames = " + std::to_string(frames) + " must be in 1..64");
    options.frames = int(frames);
    if (args.has("--arc") && frames < 2) fail("--arc turns the object over the frames of a view: give --frames N (2..64)");
    double arc = args.number("--arc", frames > 1 ? 40.0 : 0.0);
    if (!(arc >= 0.0 && arc <= 360.0)) fail(printf_string("--arc = %g must be in [0, 360] degrees", arc));
    options.arc_deg = float(arc);
    double fov = args.number("--fov", options.fov_y_deg);
    if (!(fov >= 0.5 && fov <= 120.0)) fail(printf_string("--fov = %g must be in [0.5, 120] degrees", fov));
    options.fov_y_deg = float(fov);
    options.regimes = args.flag("--regimes");
    options.orthographic = args.flag("--orthographic");
    options.image_dir = args.get("--images", "");
    if (args.has("--images") && options.image_dir.empty()) fail("--images needs a folder");
    if (!options.image_dir.empty()) {
        // Made if missing, as -o's folders are; a file of that name is refused.
        std::error_code ec;
        if (std::filesystem::exists(options.image_dir, ec) && !std::filesystem::is_directory(options.image_dir, ec))
            fail("--images " + options.image_dir + " is not a folder");
        std::filesystem::create_directories(options.image_dir, ec);
        if (!std::filesystem::is_directory(options.image_dir))
            fail("--images " + options.image_dir + ": cannot make the folder" + (ec ? " (" + ec.message() + ")" : ""));
        // And its files can be written: an unwritable folder failed after the whole survey, its tables lost.
        const std::filesystem::path probe = std::filesystem::path(options.image_dir) / ".stipple-write-test";
        if (!std::ofstream(probe)) fail("--images " + options.image_dir + ": cannot write in the folder (the images would be lost after the survey)");
        std::filesystem::remove(probe, ec);
    }
    glm::vec3 light = FrameView{}.light_view;
    if (args.has("--light")) {
        const std::optional<glm::vec3> direction = unit_direction(args.vec3("--light", light));
        if (!direction) fail("--light must not be the zero vector");
        light = *direction;
    }
    ObjectParams params = read_object_params(args);
    std::vector<uint64_t> seeds{params.generation.seed};
    if (args.has("--seeds")) {
        if (args.has("--seed")) fail("give --seed or --seeds, not both");
        seeds = parse_seeds(args.get("--seeds", ""));
    }
    if (seeds.size() > 1 && !options.image_dir.empty()) fail("--images takes one seed (drop --seeds)");

    gpu::ContextOptions context_options;
    context_options.device_index = device_index(args);
    gpu::Context context(context_options);
    const bool several = seeds.size() > 1;
    std::vector<ToneSurvey> ons, offs;
    const ObjectData model = load_model_data(path);
    check_model_fits(context, model, params.generation);  // before generating
    for (size_t k = 0; k < seeds.size(); ++k) {
        params.generation.seed = seeds[k];
        ObjectData object = model;
        object.stipples = make_model_stipples(path, model, params.generation);
        require_candidates(path, object.stipples->size(), params.generation.dmax, "measure");
        StippleRenderer renderer(context, kColorFormat, context.depth_format);
        // An animated model as render draws it by default, its first animation at 0 s (without its motion
        // the candidates generated for stretch were drawn as rest density: 0.52 mean ink for the fox, 0.41).
        renderer.add_object(*object.mesh, *object.stipples, glm::mat4(1.0f), params, object.motion);
        if (k == 0)
            std::printf("%s: %zu triangles, %zu candidate stipples, %ux%u, %s %g deg, D_max %g, point size "
                        "%g, %d frame(s) per view over %g deg of yaw%s\n\n",
                        path.c_str(), object.mesh->triangle_count(), object.stipples->size(), options.extent.width,
                        options.extent.height, options.orthographic ? "orthographic, the span of a field of view of" : "field of view",
                        options.fov_y_deg, params.generation.dmax, params.point_size,
                        options.frames, options.arc_deg, several ? ", for each seed" : "");
        renderer.params(0).extrinsic = true;
        ons.push_back(survey_tone(context, renderer, 0, object.bounds, options, light,
                                  args.flag("--regimes") ? &object.stipples->positions : nullptr));
        renderer.params(0).extrinsic = false;
        ToneSurveyOptions off_options = options;
        off_options.regimes = false;
        offs.push_back(survey_tone(context, renderer, 0, object.bounds, off_options, light));
    }
    for (const ToneSample& sample : ons.front().samples)
        for (size_t v = 0; v < options.views.size(); ++v)
            if (!sample.covered(v))
                std::fprintf(stderr, "stipple tone: at d=%g the object covers no pixel or inks none in view %g:%g "
                                     "(beyond the frame, the camera inside it, thinner than a pixel there (between "
                                     "pixel centres), or only the back of a one-sided surface in view, which "
                                     "--two-sided draws): shown as -, left out of max/min\n",
                             sample.distance, options.views[v][0], options.views[v][1]);
    std::printf("Mean ink inside the coverage mask at each distance (multiples of the framing distance)%s:\n\n",
                several ? "; per seed, then each distance averaged over the seeds" : "");
    std::printf("| extrinsic | yaw:pitch |%s", several ? " seed |" : "");
    for (float d : options.distances) std::printf(" d=%g |", d);
    std::printf(" max/min |\n|---|---|%s", several ? "---|" : "");
    for (size_t i = 0; i < options.distances.size(); ++i) std::printf("---:|");
    std::printf("---:|\n");
    for (const auto* surveys : {&ons, &offs}) {
        const char* extrinsic = surveys == &ons ? "on" : "off";
        for (size_t k = 0; k < seeds.size(); ++k)
            print_table((*surveys)[k], options, extrinsic, several ? std::to_string(seeds[k]) : "");
        if (several) print_seed_average(*surveys, options, extrinsic);
    }
    if (args.flag("--regimes"))
        for (size_t k = 0; k < seeds.size(); ++k) {
            if (several) std::printf("\nseed %llu:\n", static_cast<unsigned long long>(seeds[k]));
            print_regimes(ons[k], options, params.point_size);
        }
    print_sampling_note(ons.front(), options, params.point_size);  // the last line, as --help says
    return 0;
}

}  // namespace stipple::cli
