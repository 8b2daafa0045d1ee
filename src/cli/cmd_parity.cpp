// stipple parity: do two Vulkan devices (lavapipe and a real GPU) draw the same stipples? (issue 17)
#include <algorithm>
#include <cstdio>
#include <set>

#include "cli/args.hpp"
#include "cli/cache_options.hpp"
#include "cli/commands.hpp"
#include "cli/object_options.hpp"
#include "core/decimal.hpp"
#include "core/error.hpp"
#include "gpu/context.hpp"
#include "render/device_parity.hpp"
#include "stipple/object_data.hpp"

namespace stipple::cli {

namespace {

std::vector<int> parse_devices(const std::string& text, size_t available) {
    std::vector<int> devices;
    const std::vector<std::string> parts = split_list("--devices", text);
    // The count first: "0,1,2" on a machine of one device was refused for its '1'.
    if (parts.size() != 2) fail("--devices needs two device indices, as 0,1 (got " + text + ")");
    for (const std::string& part : parts) {
        const std::optional<int64_t> parsed = parse_decimal_integer(part);
        const int64_t index = parsed.value_or(-1);
        if (index < 0 || uint64_t(index) >= available)
            fail("--devices: '" + part + "' is not a device index (this machine's are 0 to " +
                 std::to_string(available - 1) + "; stipple render --list-devices shows them)");
        devices.push_back(int(index));
    }
    if (devices.size() != 2) fail("--devices needs two device indices, as 0,1");
    return devices;
}

std::vector<DensityPath> parse_paths(const std::string& text) {
    std::vector<DensityPath> paths;
    for (const std::string& part : split_list("--paths", text)) {
        const auto path = parse_density_path(part);
        if (!path) fail("--paths: unknown density path '" + part + "' (vertex, cpu, indirect, splat, cpu-splat)");
        if (std::find(paths.begin(), paths.end(), *path) != paths.end()) fail("--paths: '" + part + "' is named twice");
        paths.push_back(*path);
    }
    return paths;
}

}  // namespace

CommandOptions parity_command_options() {
    CommandOptions accepted{object_flags(), object_options()};
    accepted.options.insert({"--devices", "--paths", "--yaws", "--width", "--height"});
    accepted.options.merge(cache_options());  // it makes (and keeps) stipples as render does
    return accepted;
}

int run_parity(const std::vector<std::string>& argv) {
    const CommandOptions accepted = parity_command_options();
    Args args(argv, accepted.flags, accepted.options);
    if (args.has("--density-path")) fail("parity draws each path of --paths (default splat,vertex); --density-path does not apply");
    args.expect_at_most_positionals(1, "parity takes at most one MODEL");
    apply_cache_options(args);
    const std::string path = args.positionals().empty() ? default_model_path() : args.positionals()[0];
    // The options first: a mistyped one is said as such, not hidden behind the count of devices.
    const std::vector<DensityPath> paths = parse_paths(args.get("--paths", "splat,vertex"));
    const long long yaws = args.integer("--yaws", 8);
    if (yaws < 1 || yaws > 64) fail("--yaws = " + std::to_string(yaws) + " must be in 1..64");
    const long long width = args.integer("--width", 1280), height = args.integer("--height", 1024);
    if (width < 16 || width > 16384 || height < 16 || height > 16384)
        fail("--width/--height must be between 16 and 16384 (got " + std::to_string(width) + "x" +
             std::to_string(height) + ")");
    const ObjectParams params = read_object_params(args);
    const std::vector<std::string> names = gpu::Context::list_devices();
    if (names.empty()) fail("parity: this machine has no Vulkan device");
    const std::vector<int> devices = args.has("--devices")
                                         ? parse_devices(args.get("--devices", ""), names.size())
                                         : std::vector<int>{0, 1};
    if (!args.has("--devices") && names.size() < 2)
        fail("parity compares two Vulkan devices and this machine has " + std::to_string(names.size()) +
             " (--devices 0,0 compares one with itself)");
    const ObjectData object = load_object_data(path, params.generation);
    require_candidates(path, object.stipples->size(), params.generation.dmax, "compare");
    const std::vector<ParityView> views = parity_views(int(yaws), paths);
    const VkExtent2D extent{uint32_t(width), uint32_t(height)};

    DeviceRun runs[2];
    for (int d = 0; d < 2; ++d) {
        gpu::ContextOptions context_options;
        context_options.device_index = devices[size_t(d)];
        gpu::Context context(context_options);
        // An animated model as render draws it by default (its first animation at 0 s): without its
        // motion, the candidates generated for stretch were all drawn as rest density (too dark).
        runs[d] = run_parity_views(context, *object.mesh, *object.stipples, object.bounds, params, extent, views,
                                   object.motion);
    }
    const ParityReport report = compare_parity(runs[0], runs[1], views);

    std::printf("%s: %zu triangles, %zu candidate stipples, %ux%u\nA: device %d, %s\nB: device %d, %s\n\n", path.c_str(),
                object.mesh->triangle_count(), object.stipples->size(), extent.width, extent.height, devices[0],
                runs[0].device.c_str(), devices[1], runs[1].device.c_str());
    std::printf("| path | yaw:pitch | drawn A | drawn B | count diff | drawn by one only | mean ink A | mean ink B | ink diff |\n");
    std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const ParityRow& r : report.rows)
        std::printf("| %s | %g:%g | %lld | %lld | %.4f%% | %.4f%% | %.4f | %.4f | %.3f%% |\n", density_path_name(r.view.path),
                    r.view.yaw_deg, r.view.pitch_deg, (long long)r.drawn_a, (long long)r.drawn_b,
                    100.0 * r.count_difference, 100.0 * r.set_difference, r.ink_a, r.ink_b, 100.0 * r.ink_difference);
    std::printf("\nworst: drawn counts %.4f%% apart (limit %.1f%%), drawn sets %.4f%%, mean ink %.3f%% (limit %.0f%%): %s\n",
                100.0 * report.worst_count, 100.0 * kParityCountLimit, 100.0 * report.worst_set, 100.0 * report.worst_ink,
                100.0 * kParityInkLimit, report.holds() ? "parity holds" : "PARITY FAILS");
    return report.holds() ? 0 : 1;
}

}  // namespace stipple::cli
