#include "support/test_paths.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace stipple::test {

std::string shared_model(const std::string& name) {
    const char* env = std::getenv("STIPPLE_SHARED_MODELS");
    std::filesystem::path dir = env ? env : STIPPLE_SHARED_MODELS_DIR;
    std::filesystem::path path = dir / name;
    return std::filesystem::is_regular_file(path) ? path.string() : std::string();
}

std::string source_path(const std::string& relative) { return std::string(STIPPLE_SOURCE_DIR) + "/" + relative; }

std::string slurp(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::filesystem::path output_path(const std::string& name) {
    std::filesystem::path dir = STIPPLE_TEST_OUTPUT_DIR;
    std::filesystem::create_directories(dir);
    return dir / name;
}

std::filesystem::path temp_dir(const std::string& test_name) {
    // Inside the build tree, not in /tmp under a fixed name: two build trees tested at once (a fresh clone
    // beside a working one) would empty each other's folders mid-test.
    std::filesystem::path dir = std::filesystem::path(STIPPLE_TEST_OUTPUT_DIR) / "tmp" / test_name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace stipple::test
