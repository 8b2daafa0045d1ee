#include "anim/gltf_probe.hpp"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "mesh/load_mesh.hpp"
#include "mesh/loader_util.hpp"

namespace stipple::anim {

namespace {

constexpr uint32_t kGlbMagic = 0x46546C67;      // "glTF"
constexpr uint32_t kGlbJsonChunk = 0x4E4F534A;  // "JSON"

// The file's JSON, or a discarded value when it cannot be read or parsed. What is no model file to read is
// refused first, as the loader would: a FIFO given as a model waited here for a writer forever, and a link to
// /dev/zero was read until memory ran out (found by testing, 2026-12-06).
nlohmann::json read_json(const std::string& path) {
    check_model_file(path);
    std::ifstream in(path, std::ios::binary);
    if (!in) return nlohmann::json(nlohmann::json::value_t::discarded);
    std::string json;
    uint32_t header[5] = {};  // magic, version, length; the first chunk's length and type
    if (in.read(reinterpret_cast<char*>(header), sizeof header) && header[0] == kGlbMagic) {
        // Against the file's real size, not only its header's: a 22-byte file claiming a 4 GiB chunk was
        // given 4 GiB (found by review, 2026-12-04).
        std::error_code ec;
        const uintmax_t file_size = std::filesystem::file_size(path, ec);
        if (ec || header[4] != kGlbJsonChunk || header[3] > header[2] || uintmax_t(header[3]) + sizeof header > file_size)
            return nlohmann::json(nlohmann::json::value_t::discarded);
        json.resize(header[3]);
        if (!in.read(json.data(), std::streamsize(json.size()))) return nlohmann::json(nlohmann::json::value_t::discarded);
    } else {
        // In one allocation of the file's size, as the loader reads it: a stream's growing copies held a large
        // file about three times over.
        in.close();
        json = read_file(path);
    }
    return nlohmann::json::parse(json, nullptr, /*allow_exceptions=*/false);
}

bool non_empty_array(const nlohmann::json& doc, const char* key) {
    const auto it = doc.find(key);
    return it != doc.end() && (!it->is_array() || !it->empty());
}

// Whether any element of doc[key] has a "weights" array with a number other than 0 (or not a number:
// the loader will say what is wrong).
bool any_weight_set(const nlohmann::json& doc, const char* key) {
    const auto list = doc.find(key);
    if (list == doc.end() || !list->is_array()) return false;
    for (const nlohmann::json& item : *list) {
        if (!item.is_object()) continue;
        const auto weights = item.find("weights");
        if (weights == item.end()) continue;
        if (!weights->is_array()) return true;
        for (const nlohmann::json& w : *weights)
            if (!w.is_number() || w.get<double>() != 0.0) return true;
    }
    return false;
}

}  // namespace

bool gltf_declares_animations(const std::string& path) {
    const nlohmann::json doc = read_json(path);
    if (doc.is_discarded() || !doc.is_object()) return true;
    return non_empty_array(doc, "animations");
}

bool gltf_declares_deformation(const std::string& path) {
    const nlohmann::json doc = read_json(path);
    if (doc.is_discarded() || !doc.is_object()) return true;
    return non_empty_array(doc, "animations") || non_empty_array(doc, "skins") || any_weight_set(doc, "meshes") ||
           any_weight_set(doc, "nodes");
}

}  // namespace stipple::anim
