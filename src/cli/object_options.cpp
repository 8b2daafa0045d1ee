#include "cli/object_options.hpp"

#include "core/error.hpp"

namespace stipple::cli {

std::set<std::string> object_flags() {
    return {"--no-shading", "--no-extrinsic", "--no-intrinsic", "--no-thinning"};
}

std::set<std::string> object_options() {
    return {"--dmax",        "--max-stipples", "--seed", "--relax-iterations", "--shading-exponent",
            "--point-size",  "--pr",           "--de",   "--min-area",         "--density-path",
            "--silhouette",  "--silhouette-width", "--toon-sharpness"};
}

ObjectParams read_object_params(const Args& args) {
    ObjectParams params;
    params.generation.dmax = float(args.number("--dmax", params.generation.dmax));
    long long budget = args.integer("--max-stipples", (long long)params.generation.max_stipples);
    if (budget < 1) fail("--max-stipples = " + std::to_string(budget) + " is out of range: it must be >= 1");
    params.generation.max_stipples = uint64_t(budget);
    long long seed = args.integer("--seed", (long long)params.generation.seed);
    if (seed < 0) fail("--seed = " + std::to_string(seed) + " is out of range: it must be >= 0");
    params.generation.seed = uint64_t(seed);
    long long iterations = args.integer("--relax-iterations", params.generation.relax_iterations);
    if (iterations < 0 || iterations > 100)
        fail("--relax-iterations = " + std::to_string(iterations) + " is out of range: it must be >= 0 and <= 100");
    params.generation.relax_iterations = int(iterations);
    params.shading_exponent = float(args.number("--shading-exponent", params.shading_exponent));
    params.shading = !args.flag("--no-shading");
    params.point_size = float(args.number("--point-size", params.point_size));
    params.extrinsic = !args.flag("--no-extrinsic");
    params.pr = float(args.number("--pr", params.pr));
    params.min_area = float(args.number("--min-area", params.min_area));
    params.intrinsic = !args.flag("--no-intrinsic");
    params.de = float(args.number("--de", params.de));
    if (args.has("--density-path")) {
        std::string name = args.get("--density-path", "");
        auto path = parse_density_path(name);
        if (!path) fail("--density-path '" + name + "' is not one of vertex, cpu, indirect, splat, cpu-splat");
        params.density_path = *path;
    }
    if (args.has("--silhouette")) {
        std::string name = args.get("--silhouette", "");
        auto mode = parse_silhouette_mode(name);
        if (!mode) fail("--silhouette '" + name + "' is not one of none, lines, toon, both");
        params.silhouette = *mode;
    }
    params.silhouette_width = float(args.number("--silhouette-width", params.silhouette_width));
    params.silhouette_thinning = !args.flag("--no-thinning");
    params.toon_sharpness = float(args.number("--toon-sharpness", params.toon_sharpness));
    validate_params(params);
    return params;
}

}  // namespace stipple::cli
