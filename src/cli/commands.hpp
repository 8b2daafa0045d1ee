#pragma once
#include <set>
#include <string>
#include <vector>

#include "cli/args.hpp"
#include "scene/scene.hpp"

namespace stipple::cli {

// Each returns the process exit code; errors are thrown as stipple::Error.
int run_render(const std::vector<std::string>& args);
int run_info(const std::vector<std::string>& args);
int run_view(const std::vector<std::string>& args);
int run_bench(const std::vector<std::string>& args);
int run_params(const std::vector<std::string>& args);
int run_cache(const std::vector<std::string>& args);
int run_tone(const std::vector<std::string>& args);
int run_parity(const std::vector<std::string>& args);

// The flags (no value) and options (one value) a command's Args accepts, and no others: its --help lists each.
struct CommandOptions {
    std::set<std::string> flags;
    std::set<std::string> options;
};
CommandOptions render_command_options();
CommandOptions info_command_options();
CommandOptions view_command_options();
CommandOptions bench_command_options();
CommandOptions params_command_options();
CommandOptions cache_command_options();
CommandOptions tone_command_options();
CommandOptions parity_command_options();

void print_usage();  // every command and all their options
// What `command` takes (its line of the command list and its options' sections); false for an unknown command.
bool print_command_usage(const std::string& command);
std::string default_model_path();  // the built-in default scene (assets/blobby.glb)

// The scene the positionals describe: none (the default scene), one SCENE.json, or MODEL files with the
// object options; then --yaw/--pitch/--distance/--light override its camera and light. `command`
// names the command in messages.
Scene scene_from_command_line(const Args& args, const std::string& command);

}  // namespace stipple::cli
