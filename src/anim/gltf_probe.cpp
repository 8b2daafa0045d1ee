#include "anim/gltf_probe.hpp"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

namespace stipple::anim {

namespace {

constexpr uint32_t kGlbMagic = 0x46546C67;      // "glTF"
constexpr uint32_t kGlbJsonChunk = 0x4E4F534A;  // "JSON"

}  // namespace

bool gltf_declares_animations(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return true;
    std::string json;
    uint32_t header[5] = {};  // magic, version, length; the first chunk's length and type
    if (in.read(reinterpret_cast<char*>(header), sizeof header) && header[0] == kGlbMagic) {
        if (header[4] != kGlbJsonChunk || header[3] > header[2]) return true;
        json.resize(header[3]);
        if (!in.read(json.data(), std::streamsize(json.size()))) return true;
    } else {
        in.clear();
        in.seekg(0);
        std::stringstream text;
        text << in.rdbuf();
        json = text.str();
    }
    const nlohmann::json doc = nlohmann::json::parse(json, nullptr, /*allow_exceptions=*/false);
    if (doc.is_discarded() || !doc.is_object()) return true;
    const auto animations = doc.find("animations");
    return animations != doc.end() && (!animations->is_array() || !animations->empty());
}

}  // namespace stipple::anim
