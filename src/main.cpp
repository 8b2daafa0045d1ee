// stipple: interactive illustrative stipple drawing of polygonal models (Lu et al., VMV 2002).
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "cli/commands.hpp"
#include "core/error.hpp"

int main(int argc, char** argv) {
#if defined(__GLIBC__)
    // Blocks of 4 MiB and more straight from the system and back to it when freed. By default glibc
    // raises this threshold to the largest block freed so far (up to 32 MiB), after which stipple
    // generation's per-slab arrays (1-30 MiB, short-lived ones between long-lived ones) come from the
    // heap and stay resident as holes after they are freed: the 8M-stipple dragon peaked at 401 MB
    // instead of 354 MB (`STIPPLE_NO_CACHE=1 /usr/bin/time -v stipple info dragon.ply --dmax 4`).
    mallopt(M_MMAP_THRESHOLD, 4 << 20);
#endif
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
        stipple::cli::print_usage();
        return args.empty() ? 1 : 0;
    }
    const std::string command = args[0];
    args.erase(args.begin());
    try {
        if (command == "render") return stipple::cli::run_render(args);
        if (command == "info") return stipple::cli::run_info(args);
        if (command == "view") return stipple::cli::run_view(args);
        if (command == "bench") return stipple::cli::run_bench(args);
        if (command == "params") return stipple::cli::run_params(args);
        if (command == "cache") return stipple::cli::run_cache(args);
        if (command == "tone") return stipple::cli::run_tone(args);
        std::fprintf(stderr, "stipple: unknown command '%s' (try: stipple --help)\n", command.c_str());
        return 2;
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
