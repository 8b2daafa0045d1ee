// stipple: interactive illustrative stipple drawing of polygonal models (Lu et al., VMV 2002).
#include <algorithm>
#include <csignal>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"
#include "gpu/context.hpp"

namespace {

int unknown_command(const std::string& command) {
    std::fprintf(stderr, "stipple: unknown command '%s' (try: stipple --help)\n", command.c_str());
    return 2;
}

int run_command(const std::string& command, const std::vector<std::string>& args) {
    if (command == "render") return stipple::cli::run_render(args);
    if (command == "info") return stipple::cli::run_info(args);
    if (command == "view") return stipple::cli::run_view(args);
    if (command == "bench") return stipple::cli::run_bench(args);
    if (command == "params") return stipple::cli::run_params(args);
    if (command == "cache") return stipple::cli::run_cache(args);
    if (command == "tone") return stipple::cli::run_tone(args);
    if (command == "parity") return stipple::cli::run_parity(args);
    return unknown_command(command);
}

}  // namespace

int main(int argc, char** argv) {
    // A write beyond the file-size limit (ulimit -f) fails with EFBIG, which every writer reports in one line,
    // instead of killing the process with no word and a partial file left behind.
    std::signal(SIGXFSZ, SIG_IGN);
    std::vector<std::string> args(argv + 1, argv + argc);
    const auto asks_help = [](const std::string& a) { return a == "--help" || a == "-h" || a == "help"; };
    if (!args.empty() && (args[0] == "--version" || args[0] == "version")) {
        std::printf("stipple %s\n", STIPPLE_VERSION);
        return 0;
    }
    if (args.empty() || asks_help(args[0])) {
        // `stipple help view` (or --help view, -h view), as `stipple view --help`; `help help` is everything.
        if (args.size() >= 2 && !asks_help(args[1])) {
            // `help render view` printed render's options and said nothing of "view" (options after the command
            // are fine, with their values: `help tone --views`, `help render --width 400`).
            if (args.size() >= 3 && !asks_help(args[2]) && !args[2].starts_with('-')) {
                std::fprintf(stderr, "stipple: help takes one command, got '%s' and '%s' (try: stipple help %s)\n",
                             args[1].c_str(), args[2].c_str(), args[1].c_str());
                return 2;
            }
            return stipple::cli::print_command_usage(args[1]) ? 0 : unknown_command(args[1]);
        }
        stipple::cli::print_usage();
        return args.empty() ? 1 : 0;
    }
    const std::string command = args[0];
    args.erase(args.begin());
    // `stipple render --help`, or `stipple info MODEL --json --help`: what that command takes.
    if (std::any_of(args.begin(), args.end(), [](const std::string& a) { return a == "--help" || a == "-h"; })) {
        return stipple::cli::print_command_usage(command) ? 0 : unknown_command(command);
    }
    try {
        stipple::worker_count();  // a bad STIPPLE_THREADS fails here, not in whatever thread first asks
        const int status = run_command(command, args);
        // Any validation message fails the command, whichever device printed it (render and the viewer
        // say so themselves; tone, parity and the viewer's probe device did not, and exited 0).
        const uint32_t messages = stipple::gpu::validation_messages_in_process();
        if (status == 0 && messages > 0) {
            std::fprintf(stderr, "stipple: %u Vulkan validation message(s): the result is not trustworthy\n", messages);
            return 2;
        }
        return status;
    } catch (const stipple::Error& e) {
        std::fprintf(stderr, "stipple: %s\n", e.what());
        return 1;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "stipple: out of memory\n");
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "stipple: internal error: %s\n", e.what());
        return 3;
    }
}
