// The parameter table (src/params/param_table.hpp) walked through every entry point: each parameter
// round-trips command line -> scene file -> loaded scene -> saved scene; each out-of-range value is
// rejected on the command line and in a scene file with the same range in the message; --help, the
// README and `stipple params` list the table's text, not a retyped copy.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/object_options.hpp"
#include "core/error.hpp"
#include "io/png_io.hpp"
#include "params/param_docs.hpp"
#include "params/param_table.hpp"
#include "scene/scene_json.hpp"
#include "support/run_command.hpp"
#include "support/test_paths.hpp"

namespace stipple {
namespace {

// A value of `spec` inside its range that differs from the default.
double other_value(const ParamSpec& spec) {
    const double current = spec.get(ObjectParams{});
    switch (spec.type) {
        case ParamType::Bool: return current != 0.0 ? 0.0 : 1.0;
        case ParamType::Choice: return std::fmod(current + 1.0, double(spec.choices.size()));
        case ParamType::Int: return current != spec.min ? spec.min : spec.max;
        case ParamType::Float: break;
    }
    const double lowest = param_lowest_value(spec);
    return double(float(lowest + 0.37 * (spec.max - lowest)));
}

// The command-line words that set `spec` to `value`.
std::vector<std::string> cli_words(const ParamSpec& spec, double value) {
    const std::string name = "--" + std::string(spec.cli);
    if (spec.type == ParamType::Bool) return {value != 0.0 ? name : "--no-" + std::string(spec.cli)};
    return {name, format_param_value(spec, value)};
}

ObjectParams read_cli(const std::vector<std::string>& words) {
    cli::Args args(words, cli::object_flags(), cli::object_options());
    return cli::read_object_params(args);
}

Scene scene_with(const ObjectParams& params) {
    Scene scene;
    scene.objects.push_back({"model.obj", {}, params});
    return scene;
}

std::string error_of(auto&& action) {
    try {
        action();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(ParamTable, EveryParameterRoundTripsThroughCommandLineAndSceneFile) {
    const auto dir = test::temp_dir("param-table-round-trip");
    size_t walked = 0;
    for (const ParamSpec& spec : param_table()) {
        if (spec.alias) continue;
        SCOPED_TRACE(spec.key);
        const double value = other_value(spec);
        ASSERT_FALSE(param_value_problem(spec, value)) << "the test picked an invalid value";
        ASSERT_NE(value, spec.get(ObjectParams{})) << "the test picked the default";

        const ObjectParams from_cli = read_cli(cli_words(spec, value));
        EXPECT_EQ(spec.get(from_cli), value) << "the command line did not set it";
        // Only this parameter changed.
        for (const ParamSpec& other : param_table()) {
            if (&other != &spec && !other.alias) {
                EXPECT_EQ(other.get(from_cli), other.get(ObjectParams{})) << other.key;
            }
        }

        const std::string saved = scene_to_json(scene_with(from_cli), dir);
        const Scene loaded = parse_scene(saved, "saved.json", dir);
        EXPECT_EQ(spec.get(loaded.objects.at(0).params), value) << "lost in the scene file:\n" << saved;
        EXPECT_EQ(scene_to_json(loaded, dir), saved) << "saving the loaded scene changed it";
        EXPECT_EQ(needs_regeneration(ObjectParams{}, from_cli), spec.effect == ParamEffect::Regenerate);
        ++walked;
    }
    EXPECT_GE(walked, 17u);
}

TEST(ParamTable, OutOfRangeValuesAreRejectedAlikeOnTheCommandLineAndInSceneFiles) {
    const auto dir = test::temp_dir("param-table-ranges");
    size_t checked = 0;
    for (const ParamSpec& spec : param_table()) {
        if (spec.type != ParamType::Int && spec.type != ParamType::Float) continue;
        std::vector<double> bad = {spec.min_open ? spec.min : spec.min - 1.0, spec.max + 1.0, spec.max * 2.0 + 1.0};
        if (spec.type == ParamType::Int) bad.push_back(spec.min + 0.5);
        for (double value : bad) {
            SCOPED_TRACE(std::string(spec.key) + " = " + std::to_string(value));
            const std::string problem = param_value_problem(spec, value).value_or("");
            ASSERT_FALSE(problem.empty());
            std::ostringstream text;
            text.precision(17);
            text << value;
            const std::string cli_error =
                error_of([&] { read_cli({"--" + std::string(spec.cli), text.str()}); });
            EXPECT_EQ(cli_error, "--" + std::string(spec.cli) + " = " + problem);
            const std::string json =
                R"({"objects": [{"model": "m.obj", "params": {")" + std::string(spec.key) + "\": " + text.str() + "}}]}";
            const std::string scene_error = error_of([&] { parse_scene(json, "bad.json", dir); });
            EXPECT_EQ(scene_error, "bad.json: objects[0].params." + std::string(spec.key) + ": " + problem);
            if (std::isfinite(value) && value != std::floor(value) && spec.type == ParamType::Int) continue;
            EXPECT_NE(problem.find("it must be " + param_range_text(spec)), std::string::npos) << problem;
            ++checked;
        }
    }
    EXPECT_GE(checked, 30u);
}

TEST(ParamTable, TheOldSilhouetteSwitchSetsTheIndependentLineKinds) {
    const ObjectParams both = read_cli({"--silhouette", "both"});
    EXPECT_TRUE(both.silhouette_lines);
    EXPECT_TRUE(both.toon);
    const ObjectParams lines = read_cli({"--silhouette", "lines"});
    EXPECT_TRUE(lines.silhouette_lines);
    EXPECT_FALSE(lines.toon);
    const ObjectParams separate = read_cli({"--toon"});
    EXPECT_FALSE(separate.silhouette_lines);
    EXPECT_TRUE(separate.toon);
    EXPECT_NE(error_of([] { read_cli({"--toon", "--no-toon"}); }), "");
    const auto dir = test::temp_dir("param-table-alias");
    const Scene scene =
        parse_scene(R"({"objects": [{"model": "m.obj", "params": {"silhouette": "lines"}}]})", "old.json", dir);
    EXPECT_TRUE(scene.objects.at(0).params.silhouette_lines);
    const std::string saved = scene_to_json(scene, dir);
    EXPECT_EQ(saved.find("\"silhouette\""), std::string::npos) << "an alias is read but never written";
    EXPECT_NE(saved.find("\"silhouette_lines\": true"), std::string::npos);
}

TEST(ParamTable, HelpReadmeAndParamsCommandListTheTablesText) {
    const test::CommandResult help = test::run_stipple({"--help"});
    EXPECT_NE(help.out.find(param_help_text()), std::string::npos) << "--help does not hold the table's option list";
    const test::CommandResult markdown = test::run_stipple({"params", "--markdown"});
    EXPECT_EQ(markdown.exit_code, 0);
    EXPECT_EQ(markdown.out, param_markdown_table());
    std::ifstream readme(test::source_path("README.md"));
    std::stringstream text;
    text << readme.rdbuf();
    EXPECT_NE(text.str().find(param_markdown_table()), std::string::npos)
        << "README.md's parameter table is not the table's: paste `stipple params --markdown` into it";
}

// A D_max the stipple budget caps is said: a larger one changes nothing (a review found --dmax 4 and 16 drawing
// the same image without a word).
TEST(CliParams, ADmaxTheBudgetCapsIsSaid) {
    const std::string blobby = test::source_path("assets/blobby.glb");
    const test::CommandResult info = test::run_stipple({"info", blobby, "--dmax", "2", "--max-stipples", "100000"});
    ASSERT_EQ(info.exit_code, 0) << info.err;
    const size_t at = info.out.find("D_max:");
    ASSERT_NE(at, std::string::npos) << info.out;
    const double in_effect = std::stod(info.out.substr(at + 6));
    EXPECT_GT(in_effect, 0.0);
    EXPECT_LT(in_effect, 2.0);
    const test::CommandResult render = test::run_stipple({"render", blobby, "--dmax", "2", "--max-stipples", "100000", "-o",
                                                          (test::temp_dir("cli-dmax-capped") / "capped.png").string(),
                                                          "--width", "160", "--height", "128"});
    ASSERT_EQ(render.exit_code, 0) << render.err;
    EXPECT_NE(render.err.find("D_max 2 is capped at"), std::string::npos) << render.err;
    const test::CommandResult uncapped = test::run_stipple({"info", blobby, "--dmax", "0.1"});
    EXPECT_EQ(uncapped.out.find("D_max:"), std::string::npos) << uncapped.out;
}

// A value after an option that takes none (`--shading yes`) is named with the option, not taken for a second
// model ("render takes at most one MODEL or SCENE.json" did not say which word was wrong).
TEST(CliParams, AValueAfterAFlagIsNamed) {
    for (const std::vector<std::string>& args : {std::vector<std::string>{"render", "--shading", "yes"},
                                                 std::vector<std::string>{"tone", "--regimes", "true"},
                                                 std::vector<std::string>{"info", "model.obj", "--json", "1"}}) {
        const test::CommandResult r = test::run_stipple(args);
        EXPECT_EQ(r.exit_code, 1) << args[0];
        const size_t flag = args[0] == "info" ? 2 : 1;
        EXPECT_NE(r.err.find("option " + args[flag] + " takes no value (got '" + args[flag + 1] + "' after it"), std::string::npos)
            << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
    // Another word there, beside the model: named too, rather than "at most one MODEL".
    const test::CommandResult r = test::run_stipple({"render", "model.obj", "--shading", "softly"});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("'softly' after --shading, which takes no value"), std::string::npos) << r.err;
}

// --help anywhere after the command prints the usage (it was "unknown option --help" unless it came first).
TEST(ParamTable, HelpAnywhereAfterTheCommandPrintsTheUsage) {
    for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
             {"info", "model.obj", "--json", "--help"}, {"params", "--markdown", "--help"}, {"render", "-h"}}) {
        const test::CommandResult r = test::run_stipple(args);
        EXPECT_EQ(r.exit_code, 0) << args.back() << ": " << r.err;
        EXPECT_NE(r.out.find("Usage:"), std::string::npos) << r.out;
    }
    const test::CommandResult version = test::run_stipple({"--version"});
    EXPECT_EQ(version.exit_code, 0) << version.err;
    EXPECT_TRUE(std::regex_match(version.out, std::regex("stipple [0-9]+\\.[0-9]+\\.[0-9]+\n"))) << version.out;
}

// Whether `help` names `option` as a word of its own (not "--frames" inside "--benchmark-frames").
bool names_option(const std::string& help, const std::string& option) {
    const auto word_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_'; };
    for (size_t at = help.find(option); at != std::string::npos; at = help.find(option, at + 1)) {
        const bool starts = at == 0 || !word_char(help[at - 1]);
        const bool ends = at + option.size() == help.size() || !word_char(help[at + option.size()]);
        if (starts && ends) return true;
    }
    return false;
}

// `stipple COMMAND --help` prints what that command takes, every option its reader accepts and no other
// command's sections (`view --help` printed all 280 lines, bench's and tone's included); `stipple --help`
// prints every command's options.
TEST(ParamTable, EachCommandsHelpListsEveryOptionItTakes) {
    using cli::CommandOptions;
    const std::vector<std::pair<std::string, CommandOptions>> commands = {
        {"render", cli::render_command_options()}, {"view", cli::view_command_options()},
        {"info", cli::info_command_options()},     {"bench", cli::bench_command_options()},
        {"tone", cli::tone_command_options()},     {"parity", cli::parity_command_options()},
        {"params", cli::params_command_options()}, {"cache", cli::cache_command_options()}};
    const test::CommandResult all = test::run_stipple({"--help"});
    ASSERT_EQ(all.exit_code, 0) << all.err;
    const auto lines = [](const std::string& text) { return std::count(text.begin(), text.end(), '\n'); };
    for (const auto& [command, accepted] : commands) {
        const test::CommandResult help = test::run_stipple({command, "--help"});
        ASSERT_EQ(help.exit_code, 0) << command << ": " << help.err;
        EXPECT_NE(help.out.find("stipple " + command), std::string::npos) << help.out;
        std::set<std::string> every = accepted.flags;
        every.insert(accepted.options.begin(), accepted.options.end());
        for (const std::string& option : every) {
            EXPECT_TRUE(names_option(help.out, option)) << "stipple " << command << " --help does not list " << option;
            EXPECT_TRUE(names_option(all.out, option)) << "stipple --help does not list " << command << "'s " << option;
        }
        EXPECT_LT(lines(help.out), lines(all.out) * 3 / 4) << command << " --help prints nearly everything";
        std::printf("stipple %-6s --help: %3zu options, %3ld lines (stipple --help: %ld)\n", command.c_str(), every.size(),
                    long(lines(help.out)), long(lines(all.out)));
    }
    // No other command's sections: view's help has no bench options, bench's no stipple options.
    EXPECT_EQ(test::run_stipple({"view", "--help"}).out.find("Bench options"), std::string::npos);
    EXPECT_EQ(test::run_stipple({"bench", "--help"}).out.find("Stipple options"), std::string::npos);
    EXPECT_NE(test::run_stipple({"render", "--help"}).out.find("Vector and print output"), std::string::npos);
    const std::string tone = test::run_stipple({"tone", "--help"}).out;
    for (const std::vector<std::string>& asked : {std::vector<std::string>{"help", "tone"}, {"--help", "tone"}, {"-h", "tone"},
                                                  {"help", "tone", "--views"}})
        EXPECT_EQ(test::run_stipple(asked).out, tone) << asked[0];
    EXPECT_EQ(test::run_stipple({"help", "help"}).out, all.out);
    const test::CommandResult two = test::run_stipple({"help", "render", "view"});
    EXPECT_EQ(two.exit_code, 2);
    EXPECT_EQ(two.err, "stipple: help takes one command, got 'render' and 'view' (try: stipple help render)\n");
    EXPECT_EQ(test::run_stipple({"help", "render", "--width", "400"}).exit_code, 0) << "an option with its value";
    const test::CommandResult unknown = test::run_stipple({"draw", "--help"});
    EXPECT_EQ(unknown.exit_code, 2);
    EXPECT_EQ(unknown.err, "stipple: unknown command 'draw' (try: stipple --help)\n");
}

TEST(ParamTable, TheExecutableRejectsAnOutOfRangeValueInOneLine) {
    const test::CommandResult r = test::run_stipple({"render", "--dmax", "20", "-o", "/nonexistent/x.png"});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "stipple: --dmax = 20 is out of range: it must be >= 0 and <= 16\n");
}

// D_max 0 makes no stipples: the lines and the toon ramp are drawn alone (the paper's Figure 9 "without
// stipples", an outline for the plotter), on every path, and a page with neither says why it is blank.
TEST(ParamTable, DmaxZeroDrawsTheLinesAlone) {
    const auto dir = test::temp_dir("params-dmax-zero");
    auto dark_pixels = [](const std::string& path) {
        const Image image = read_png(path);
        size_t dark = 0;
        for (size_t i = 0; i < image.pixels.size(); i += size_t(image.channels)) dark += image.pixels[i] < 128;
        return dark;
    };
    for (const std::string path : {"splat", "vertex", "indirect", "cpu", "cpu-splat"}) {
        const std::string lines = (dir / ("lines_" + path + ".png")).string();
        const test::CommandResult r = test::run_stipple({"render", "--width", "320", "--height", "256", "--dmax", "0", "--contours",
                                                         "--density-path", path, "--stats", "-o", lines});
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_NE(r.out.find("candidate stipples: 0\n"), std::string::npos) << r.out;
        EXPECT_NE(r.out.find("drawn stipples:     0 ("), std::string::npos) << r.out;
        EXPECT_GT(dark_pixels(lines), 300u) << path << ": the outline is drawn";
    }
    const std::string bare = (dir / "bare.png").string();
    const test::CommandResult png = test::run_stipple({"render", "--width", "320", "--height", "256", "--dmax", "0", "-o", bare});
    ASSERT_EQ(png.exit_code, 0) << png.err;
    EXPECT_EQ(dark_pixels(bare), 0u);
    const test::CommandResult svg =
        test::run_stipple({"render", "--width", "320", "--height", "256", "--dmax", "0", "-o", (dir / "bare.svg").string()});
    ASSERT_EQ(svg.exit_code, 0) << svg.err;
    for (const test::CommandResult* r : {&png, &svg}) {
        EXPECT_NE(r->err.find("D_max is 0 (no stipples) and no line or toon is asked: nothing is drawn"), std::string::npos) << r->err;
        EXPECT_EQ(std::count(r->err.begin(), r->err.end(), '\n'), 1) << "said once: " << r->err;
    }
}

}  // namespace
}  // namespace stipple
