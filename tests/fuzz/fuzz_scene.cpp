// libFuzzer harness: the scene-file reader (parse_scene, its public API) on arbitrary text. A scene
// that reads must also survive being written and read back, as the viewer's "save" relies on.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_check.hpp"
#include "scene/scene_json.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string name = "fuzz.json";
    const std::filesystem::path base = "/nonexistent-fuzz-scene-dir";
    stipple::Scene scene;
    try {
        scene = stipple::parse_scene(std::string(reinterpret_cast<const char*>(data), size), name, base);
    } catch (const stipple::Error& e) {
        stipple::fuzz::check_message(e, name);
        return 0;
    }
    try {
        stipple::parse_scene(stipple::scene_to_json(scene, base), name, base);
    } catch (const stipple::Error& e) {
        stipple::fuzz::contract_broken(std::string("a scene that read does not read back after saving: ") + e.what());
    }
    return 0;
}
