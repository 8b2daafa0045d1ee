#include "cli/cache_options.hpp"

#include <filesystem>

#include "core/error.hpp"

#include "stipple/stipple_cache.hpp"

namespace stipple::cli {

std::set<std::string> cache_options() { return {"--cache-dir", "--cache-size"}; }

void apply_cache_options(const Args& args) {
    StippleCacheSettings& settings = stipple_cache_settings();
    if (args.has("--cache-dir")) {
        settings.dir = args.get("--cache-dir", "");
        std::error_code ec;
        if (settings.dir.empty()) fail("--cache-dir needs a folder");
        if (std::filesystem::exists(settings.dir, ec) && !std::filesystem::is_directory(settings.dir, ec))
            fail("--cache-dir " + settings.dir.string() + " is not a folder");
    }
    if (args.has("--cache-size")) settings.max_bytes = parse_byte_size("--cache-size", args.get("--cache-size", ""));
}

}  // namespace stipple::cli
