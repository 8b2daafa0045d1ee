// stipple params: the per-object parameters, from the one table (src/params/param_table.hpp).
#include <cstdio>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "core/error.hpp"
#include "params/param_docs.hpp"

namespace stipple::cli {

CommandOptions params_command_options() { return {{"--markdown"}, {}}; }

int run_params(const std::vector<std::string>& argv) {
    const CommandOptions accepted = params_command_options();
    Args args(argv, accepted.flags, accepted.options);
    if (!args.positionals().empty()) fail("params takes no MODEL (it lists the per-object parameters)");
    std::fputs((args.flag("--markdown") ? param_markdown_table() : param_help_text()).c_str(), stdout);
    return 0;
}

}  // namespace stipple::cli
