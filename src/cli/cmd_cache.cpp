// stipple cache: what the stipple cache holds, and emptying it (src/stipple/stipple_cache.hpp).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <ctime>

#include "cli/args.hpp"
#include "cli/cache_options.hpp"
#include "cli/commands.hpp"
#include "core/error.hpp"
#include "stipple/stipple_cache.hpp"

namespace stipple::cli {

namespace {

// In the units --cache-size reads (500M is 500 MiB, 64K is 64 KiB): "1073.7 MB" for the default 1G read as
// another size; below a MiB in KiB or bytes (a limit of 1K listed as "0.0 MiB").
std::string cache_size_text(uint64_t bytes) {
    char text[32];
    if (bytes >= 1048576) std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / 1048576.0);
    else if (bytes >= 1024) std::snprintf(text, sizeof text, "%.1f KiB", double(bytes) / 1024.0);
    else std::snprintf(text, sizeof text, "%llu bytes", static_cast<unsigned long long>(bytes));
    return text;
}

std::string local_time(std::filesystem::file_time_type time) {
    const auto system = std::chrono::time_point_cast<std::chrono::system_clock::duration>(
        time - std::filesystem::file_time_type::clock::now() + std::chrono::system_clock::now());
    const std::time_t t = std::chrono::system_clock::to_time_t(system);
    std::tm tm{};
    localtime_r(&t, &tm);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M", &tm);
    return text;
}

}  // namespace

CommandOptions cache_command_options() { return {{"--list", "--clear"}, cache_options()}; }

int run_cache(const std::vector<std::string>& argv) {
    const CommandOptions accepted = cache_command_options();
    Args args(argv, accepted.flags, accepted.options);
    if (!args.positionals().empty()) fail("cache takes no MODEL (see stipple --help)");
    if (args.flag("--list") && args.flag("--clear")) fail("cache takes --list or --clear, not both");
    if (!args.flag("--list") && !args.flag("--clear")) fail("cache needs one of --list or --clear");
    apply_cache_options(args);
    const StippleCacheSettings& settings = stipple_cache_settings();
    std::error_code ec;
    if (args.has("--cache-dir") && !std::filesystem::is_directory(settings.dir, ec))
        fail("--cache-dir " + settings.dir.string() + ": no such folder");
    if (std::filesystem::exists(settings.dir, ec) && !std::filesystem::is_directory(settings.dir, ec))
        fail_file(settings.dir.string(), "the stipple cache folder is a file");
    if (args.flag("--clear")) {
        const uint64_t freed = clear_cache(settings.dir);
        std::printf("cleared %s: %s freed\n", settings.dir.c_str(), cache_size_text(freed).c_str());
        return 0;
    }
    uint64_t total = 0;
    const auto entries = list_cache_entries(settings.dir);
    // One entry per model and generation parameters (seed, D_max, budget, ...): the same model's entries are
    // told apart by their key, the entry's file name.
    std::printf("%s (limit %s; most recently used first; [key] tells one model's entries apart)\n", settings.dir.c_str(),
                cache_size_text(settings.max_bytes).c_str());
    for (const CacheEntryInfo& e : entries) {
        total += e.bytes;
        if (e.readable)
            std::printf("  %s  %9s  %10llu stipples  %9llu polygons  [%s]  %s\n", local_time(e.last_used).c_str(),
                        cache_size_text(e.bytes).c_str(), (unsigned long long)e.stipples, (unsigned long long)e.triangles,
                        e.path.stem().c_str(), e.model.c_str());
        else
            std::printf("  %s  %9s  (unreadable: %s)\n", local_time(e.last_used).c_str(), cache_size_text(e.bytes).c_str(),
                        e.path.filename().c_str());
    }
    std::printf("%zu %s, %s\n", entries.size(), entries.size() == 1 ? "entry" : "entries", cache_size_text(total).c_str());
    return 0;
}

}  // namespace stipple::cli
