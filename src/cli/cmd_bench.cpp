// stipple bench: the paper's Table 1 on this machine (see src/bench/).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "bench/bench_compare.hpp"
#include "bench/bench_output.hpp"
#include "bench/bench_runner.hpp"
#include "bench/table1.hpp"
#include "cli/cmd_bench_plot.hpp"
#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "render/depth_triangles.hpp"
#include "core/error.hpp"
#include "gpu/context.hpp"

namespace stipple::cli {

namespace {

long long bounded(const Args& args, const std::string& name, long long fallback, long long lo, long long hi) {
    long long value = args.integer(name, fallback);
    if (value < lo || value > hi)
        fail(name + " = " + std::to_string(value) + " must be in " + std::to_string(lo) + ".." + std::to_string(hi));
    return value;
}

// A list option naming one entry twice would run it twice and write a results.json that --compare refuses.
void fail_on_repeats(const std::string& option, const std::vector<std::string>& names) {
    for (size_t i = 0; i < names.size(); ++i)
        for (size_t j = 0; j < i; ++j)
            if (names[i] == names[j]) fail(option + ": '" + names[i] + "' is named twice");
}

}  // namespace

CommandOptions bench_command_options() {
    return {{"--quick", "--list-devices", "--animated-only"},
            {"--out", "--frames", "--warmup", "--models", "--paths", "--width", "--height", "--device", "--models-dir", "--cache-dir",
             "--animated-triangles", "--compare", "--plot-dots", "--depth-cull", "--depth-raster", "--queued"}};
}

int run_bench(const std::vector<std::string>& argv) {
    const CommandOptions accepted = bench_command_options();
    Args args(argv, accepted.flags, accepted.options);
    if (args.flag("--list-devices")) {
        for (const std::string& line : gpu::Context::list_devices()) std::printf("%s\n", line.c_str());
        return 0;
    }
    if (!args.positionals().empty()) fail("bench takes no MODEL (it runs its own model set; see --models)");

    bench::BenchOptions options;
    options.quick = args.flag("--quick");
    options.object_lines = !options.quick;  // --quick keeps to the paper's columns
    // --quick: the two smallest rows, the paper's two paths with and without lines, 5 timed frames.
    options.frames = int(bounded(args, "--frames", options.quick ? 5 : 20, 1, 100000));
    options.warmup = int(bounded(args, "--warmup", 3, 0, 1000));
    options.queued = args.has("--queued") ? int(bounded(args, "--queued", 1, 1, 1000)) : 0;  // 0: by device
    options.width = uint32_t(bounded(args, "--width", 1280, 1, 16384));
    options.height = uint32_t(bounded(args, "--height", 1024, 1, 16384));
    options.device = device_index(args);
    // The animated row's skinned cylinder: >= 100k triangles (issue 16), fewer for --quick; 0 skips it, and
    // so does naming rows with --models unless the row is asked for.
    const bool rows_named = args.has("--models") && !args.has("--animated-triangles") && !args.flag("--animated-only");
    options.animated_triangles = uint32_t(
        bounded(args, "--animated-triangles", rows_named ? 0 : options.quick ? 20'000 : 100'000, 0, 10'000'000));
    options.animated_only = args.flag("--animated-only");
    if (options.animated_only && options.animated_triangles == 0) fail("--animated-only needs --animated-triangles > 0");
    if (options.animated_only && (args.has("--models") || args.has("--paths")))
        fail(std::string("--animated-only runs the animated row alone, on its own cylinder and path: it takes no ") +
             (args.has("--models") ? "--models" : "--paths"));
    if (args.has("--models")) {
        for (const std::string& name : split_list("--models", args.get("--models", ""))) {
            const bench::PaperRow* row = bench::find_paper_row(name);
            if (!row) fail("--models: unknown model '" + name + "' (the rows of Table 1 are: " + bench::paper_row_names() + ")");
            options.models.push_back(row->name);  // "low-res-dragon" as the row's own name
        }
        fail_on_repeats("--models", options.models);
    } else if (options.quick) {
        options.models = {bench::kPaperTable[0].name, bench::kPaperTable[1].name};
    }
    if (args.has("--paths")) {
        std::string list = args.get("--paths", "");
        if (list != "all")
            for (const std::string& name : split_list("--paths", list)) {
                auto path = parse_density_path(name);
                if (!path) {
                    std::string known;
                    for (DensityPath p : bench::all_density_paths()) known += std::string(known.empty() ? "" : ", ") + density_path_name(p);
                    fail("--paths: unknown density path '" + name + "' (one of: " + known + ", or all)");
                }
                options.paths.push_back(*path);
            }
        std::vector<std::string> names;
        for (DensityPath p : options.paths) names.push_back(density_path_name(p));
        fail_on_repeats("--paths", names);
    } else if (options.quick) {
        options.paths = {DensityPath::Vertex, DensityPath::Cpu, DensityPath::Splat};
    }
    const std::string depth_cull = args.get("--depth-cull", "auto");
    if (!parse_depth_cull(depth_cull)) fail("--depth-cull = " + depth_cull + " must be auto, on or off");
    options.depth_cull = *parse_depth_cull(depth_cull);
    const std::string depth_raster = args.get("--depth-raster", "auto");
    if (!parse_depth_raster(depth_raster)) fail("--depth-raster = " + depth_raster + " must be auto, compute or fixed");
    options.depth_raster = *parse_depth_raster(depth_raster);
    if (args.has("--models-dir")) options.models_dir = args.get("--models-dir", "");
    if (args.has("--cache-dir")) options.cache_dir = args.get("--cache-dir", "");
    if (args.has("--models-dir") && options.models_dir.empty()) fail("--models-dir needs a folder");
    // Without the option a missing folder means a machine without the scans (the bench says so and draws
    // spheres); a folder named that is not there, or a file named where it should be, is a mistake.
    if (args.has("--models-dir") && !std::filesystem::exists(options.models_dir))
        fail("--models-dir " + options.models_dir.string() + ": no such folder");
    if (args.has("--models-dir") && !std::filesystem::is_directory(options.models_dir))
        fail("--models-dir " + options.models_dir.string() + " is a file, not a folder");
    if (args.has("--cache-dir") && options.cache_dir.empty()) fail("--cache-dir needs a folder");
    const std::filesystem::path out = args.get("--out", "bench-results");
    if (out.empty()) fail("--out needs a folder");
    // Read before the run: a bad file fails at once, and --out may be the folder it is in.
    const std::string compare_path = args.get("--compare", "");
    if (args.has("--compare") && compare_path.empty()) fail("--compare needs the path of an earlier results.json");
    std::string old_results;
    if (!compare_path.empty()) old_results = bench::read_results_file(compare_path);
    // Made now: a run of many minutes must not end unable to write its results.
    {
        std::error_code ec;
        std::filesystem::create_directories(out, ec);
        if (ec || !std::filesystem::is_directory(out))
            fail_file(out.string(), "cannot make the results folder" + (ec ? ": " + ec.message() : std::string(" (a file is there)")));
        // And the files in it can be written (a folder results.md, or /proc, failed after every frame was timed).
        std::filesystem::create_directories(out / "images", ec);
        for (const std::filesystem::path& file : {out / "results.md", out / "results.json", out / "chart.svg", out / "images" / ".write-test"}) {
            const bool existed = std::filesystem::exists(file, ec);
            if (!std::ofstream(file, std::ios::app)) fail_file(file.string(), "cannot be written: the results would be lost after the run");
            if (!existed) std::filesystem::remove(file, ec);
        }
    }
    options.image_dir = out / "images";
    // The plot-order row: in a full run 150k dots and the bunny's view; --quick (in the test suite)
    // shrinks it to 15k dots without the bunny; a run of chosen --models, or --animated-only, leaves it out
    // unless asked.
    const bool plot_asked = args.has("--plot-dots");
    const size_t plot_dots = size_t(bounded(args, "--plot-dots", options.quick ? 15'000 : 150'000, 0, 10'000'000));
    const bool plot_row = plot_dots > 0 && (plot_asked || (!options.animated_only && !args.has("--models")));
    options.command = "stipple bench";
    // As a shell reads it back: a word with a space or a quote quoted (--models 'low-res dragon').
    for (const std::string& a : argv) {
        if (a.find_first_of(" \t'\"$\\`") == std::string::npos) {
            options.command += " " + a;
            continue;
        }
        std::string quoted = "'";
        for (char c : a) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
        options.command += " " + quoted + "'";
    }

    const auto log = [](const std::string& line) {
        std::printf("%s\n", line.c_str());
        std::fflush(stdout);
    };
    const auto start = std::chrono::steady_clock::now();
    bench::BenchResults results;
    try {
        results = bench::run_bench(options, log);
    } catch (const Error& e) {
        // The checks that refuse a model advise the options render takes; the bench draws every row at the
        // defaults and has none of them (it said "lower --dmax", which it refused as an unknown option).
        std::string message = e.what();
        const size_t advice = message.find(": lower --dmax or --max-stipples");
        if (advice == std::string::npos) throw;
        fail(message.substr(0, advice) + ": the bench draws every row at the default D_max (leave the row out with "
                                         "--models)");
    }
    if (plot_row) {
        results.plot_order = measure_plot_order_row(plot_dots, !options.quick, options.models_dir, options.width,
                                                    options.height, options.device, log);
        results.validation_messages += results.plot_order->validation_messages;
    }
    results.total_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    const std::string markdown = bench::markdown_report(results);
    bench::write_text_file((out / "results.md").string(), markdown);
    bench::write_text_file((out / "results.json").string(), bench::json_report(results));
    bench::write_text_file((out / "chart.svg").string(), bench::svg_chart(results));
    std::printf("\n%s", markdown.c_str());
    // This run's frames, not whatever an earlier run left in the folder.
    const bool images = std::any_of(results.models.begin(), results.models.end(),
                                    [](const bench::ModelResult& m) { return !m.image.empty(); });
    std::printf("wrote %s, %s, %s%s%s (%.0f s)\n", (out / "results.md").c_str(), (out / "results.json").c_str(),
                (out / "chart.svg").c_str(), images ? " and the standard frames in " : "",
                images ? (out / "images").c_str() : "", results.total_seconds);
    if (!compare_path.empty()) {
        const bench::Comparison comparison = bench::compare_runs(old_results, compare_path, bench::json_report(results));
        std::printf("\n%s", bench::comparison_text(comparison, compare_path).c_str());
    }
    if (results.validation_messages > 0) {
        std::fprintf(stderr, "stipple: %u Vulkan validation message(s) during the benchmark: its figures are not trustworthy\n",
                     results.validation_messages);
        return 2;
    }
    return 0;
}

}  // namespace stipple::cli
