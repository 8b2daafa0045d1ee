// Derives the benchmark's model set (one model per row of the paper's Table 1, polygon count within
// ±2%) from the scans in ../shared/models into the model cache, and prints each model's name,
// triangle count, the row's count and the source. Models already in the cache and current are kept.
// Usage: make_model_set [--out DIR] [--models-dir DIR] [--only NAME,NAME]
//   --out DIR          the cache folder (default: $STIPPLE_CACHE_DIR/bench-models or <build>/bench-models)
//   --models-dir DIR   where the scans are (default: $STIPPLE_SHARED_MODELS or <source>/../shared/models)
#include <cstdio>
#include <cstring>
#include <string>

#include "bench/model_set.hpp"
#include "bench/table1.hpp"
#include "core/error.hpp"

namespace {

std::vector<std::string> split_commas(const std::string& list) {
    std::vector<std::string> items;
    size_t start = 0;
    while (start <= list.size()) {
        size_t end = list.find(',', start);
        if (end == std::string::npos) end = list.size();
        if (end > start) items.push_back(list.substr(start, end - start));
        start = end + 1;
    }
    return items;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace stipple;
    bench::ModelSetOptions options;
    options.log = [](const std::string& line) { std::printf("%s\n", line.c_str()); std::fflush(stdout); };
    try {
        for (int i = 1; i < argc; ++i) {
            std::string arg = argv[i];
            if (arg == "--help" || arg == "-h") {
                std::printf("usage: make_model_set [--out DIR] [--models-dir DIR] [--only NAME,NAME]\n");
                return 0;
            }
            if ((arg == "--out" || arg == "--models-dir" || arg == "--only") && i + 1 < argc) {
                std::string value = argv[++i];
                if (arg == "--out") options.cache_dir = value;
                else if (arg == "--models-dir") options.models_dir = value;
                else options.only = split_commas(value);
                continue;
            }
            fail("unknown or incomplete argument '" + arg + "' (usage: make_model_set [--out DIR] [--models-dir DIR] [--only NAME,NAME])");
        }
        if (!bench::scans_available(options.models_dir))
            fail("the scans are not in " + options.models_dir.string() +
                 " (need horse.ply, igea.ply, stanford-bunny.obj, ogre.obj); nothing to derive");
        std::printf("model cache: %s\n", options.cache_dir.string().c_str());
        std::vector<bench::ModelEntry> entries = bench::prepare_model_set(options);
        std::printf("%-16s %10s %10s %8s  %s\n", "model", "triangles", "row", "off", "source");
        for (const bench::ModelEntry& e : entries)
            std::printf("%-16s %10zu %10zu %+7.2f%%  %s (%s)\n", e.name.c_str(), e.triangles, e.target,
                        100.0 * (double(e.triangles) - double(e.target)) / double(e.target), e.source.c_str(),
                        e.path.string().c_str());
        return 0;
    } catch (const Error& e) {
        std::fprintf(stderr, "make_model_set: %s\n", e.what());
        return 1;
    }
}
