#include "cli/object_options.hpp"

#include "core/error.hpp"
#include "core/printf_string.hpp"
#include "params/param_table.hpp"

namespace stipple::cli {

std::set<std::string> object_flags() {
    std::set<std::string> flags;
    for (const ParamSpec& spec : param_table())
        if (spec.type == ParamType::Bool)
            for (const std::string& name : param_cli_names(spec)) flags.insert(name);
    return flags;
}

std::set<std::string> object_options() {
    std::set<std::string> options;
    for (const ParamSpec& spec : param_table())
        if (spec.type != ParamType::Bool) options.insert("--" + std::string(spec.cli));
    return options;
}

std::set<std::string> camera_flags() { return {"--orthographic", "--perspective"}; }
std::set<std::string> camera_options() { return {"--yaw", "--pitch", "--distance", "--light", "--ink", "--paper"}; }

namespace {

// Whether the command line gives the parameter of this scene key (as --x, --no-x or --x VALUE).
bool gives(const Args& args, const char* key) {
    const ParamSpec* spec = find_param(key);
    if (!spec) return false;
    const std::string name = "--" + std::string(spec->cli);
    return spec->type == ParamType::Bool ? args.flag(name) || args.flag("--no-" + std::string(spec->cli)) : args.has(name);
}

}  // namespace

ObjectParams read_object_params(const Args& args) {
    ObjectParams params;
    for (const ParamSpec& spec : param_table())
        for (const char* key : spec.alias_of)
            if (gives(args, spec.key) && gives(args, key))
                fail("--" + std::string(spec.cli) + " sets --" + find_param(key)->cli + " too: give one or the other, not both");
    for (const ParamSpec& spec : param_table()) {
        const std::string name = "--" + std::string(spec.cli);
        if (spec.type == ParamType::Bool) {
            const std::string off = "--no-" + std::string(spec.cli);
            if (args.flag(name) && args.flag(off)) fail(name + " and " + off + " contradict each other");
            if (args.flag(name)) spec.set(params, 1.0);
            if (args.flag(off)) spec.set(params, 0.0);
        } else if (args.has(name)) {
            spec.set(params, parse_param_text(spec, args.get(name, "")));
        }
    }
    validate_params(params);
    return params;
}

std::string first_object_option(const Args& args) {
    for (const std::string& name : object_flags())
        if (args.flag(name)) return name;
    for (const std::string& name : object_options())
        if (args.has(name)) return name;
    return "";
}

void require_candidates(const std::string& path, size_t candidates, double dmax, const std::string& nothing_to) {
    if (candidates == 0)
        fail_file(path, "has no stipple candidates at D_max " + printf_string("%g", dmax) + " (raise --dmax): nothing to " + nothing_to);
}

}  // namespace stipple::cli
