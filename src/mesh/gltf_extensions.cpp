#include "mesh/gltf_extensions.hpp"

#include <algorithm>
#include <cctype>
#include <iterator>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "mesh/loader_util.hpp"

namespace stipple {

namespace {

using json = nlohmann::json;

// Khronos' ratified and widely used vendor extensions: enough to recognise a misspelling of the
// ones files actually carry.
constexpr std::string_view kKnown[] = {
    "KHR_animation_pointer", "KHR_draco_mesh_compression", "KHR_lights_punctual", "KHR_materials_anisotropy",
    "KHR_materials_clearcoat", "KHR_materials_diffuse_transmission", "KHR_materials_dispersion",
    "KHR_materials_emissive_strength", "KHR_materials_ior", "KHR_materials_iridescence",
    "KHR_materials_pbrSpecularGlossiness", "KHR_materials_sheen", "KHR_materials_specular",
    "KHR_materials_transmission", "KHR_materials_unlit", "KHR_materials_variants", "KHR_materials_volume",
    "KHR_mesh_quantization", "KHR_texture_basisu", "KHR_texture_transform", "KHR_xmp_json_ld", "KHR_xmp",
    "KHR_techniques_webgl", "EXT_lights_image_based", "EXT_mesh_gpu_instancing", "EXT_meshopt_compression",
    "EXT_texture_webp", "EXT_texture_avif", "EXT_mesh_features", "EXT_structural_metadata",
    "EXT_instance_features", "MSFT_lod", "MSFT_texture_dds", "MSFT_packing_normalRoughnessMetallic",
    "MSFT_packing_occlusionRoughnessMetallic", "CESIUM_primitive_outline", "ADOBE_materials_thin_transparency",
    "AGI_articulations"};

// Extensions that only concern what stipple does not draw (materials, textures, lights, metadata):
// a file may require them and still load right without them.
bool ignorable(std::string_view ext) {
    for (std::string_view prefix : {"KHR_materials_", "KHR_texture_", "EXT_texture_", "MSFT_texture_", "MSFT_packing_"})
        if (ext.substr(0, prefix.size()) == prefix) return true;
    for (std::string_view e : {"KHR_lights_punctual", "EXT_lights_image_based", "KHR_xmp_json_ld", "KHR_xmp",
                               "KHR_techniques_webgl", "ADOBE_materials_thin_transparency", "CESIUM_primitive_outline",
                               "EXT_structural_metadata", "EXT_mesh_features", "EXT_instance_features"})
        if (ext == e) return true;
    return false;
}

// A name as the glTF naming convention has it: an upper-case vendor prefix, '_', then the name.
bool well_formed(std::string_view ext) {
    const size_t underscore = ext.find('_');
    if (underscore == 0 || underscore == std::string_view::npos || underscore + 1 == ext.size()) return false;
    for (size_t i = 0; i < underscore; ++i)
        if (!std::isupper(static_cast<unsigned char>(ext[i])) && !std::isdigit(static_cast<unsigned char>(ext[i])))
            return false;
    return std::all_of(ext.begin(), ext.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

// Levenshtein distance, case-insensitive, given up beyond `limit` (names are short).
size_t distance(std::string_view a, std::string_view b, size_t limit) {
    if (a.size() > b.size() + limit || b.size() > a.size() + limit) return limit + 1;
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) == std::tolower(static_cast<unsigned char>(b[j - 1]));
            const size_t next = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
            diagonal = row[j];
            row[j] = next;
        }
    }
    return row[b.size()];
}

// The known or used name a misspelt entry most likely meant, or "" when none is close.
std::string likely_meant(std::string_view ext, const std::set<std::string>& used) {
    std::string best;
    size_t best_distance = 3;  // at most two edits
    auto consider = [&](std::string_view candidate) {
        const size_t d = distance(ext, candidate, 2);
        if (candidate != ext && d < best_distance) best = std::string(candidate), best_distance = d;
    };
    for (const std::string& u : used) consider(u);
    for (std::string_view k : kKnown) consider(k);
    return best;
}

std::string a_type(const json& v) {
    const std::string type = v.type_name();
    return (type == "array" || type == "object" ? "an " : "a ") + type;
}

std::string shown(const std::string& text) { return quoted_excerpt(text, 64); }

// The entries of extensionsUsed or extensionsRequired, each checked to be a well-formed name.
std::vector<std::string> names(const std::string& file, const json& doc, const char* key) {
    std::vector<std::string> out;
    const auto it = doc.find(key);
    if (it == doc.end()) return out;
    if (!it->is_array()) fail_file(file, std::string(key) + ": expected an array of extension names, got " + a_type(*it));
    for (size_t i = 0; i < it->size(); ++i) {
        const json& entry = (*it)[i];
        const std::string where = std::string(key) + "[" + std::to_string(i) + "]";
        if (!entry.is_string()) fail_file(file, where + ": expected an extension name (a string), got " + a_type(entry));
        const std::string& ext = entry.get_ref<const std::string&>();
        if (!well_formed(ext)) {
            const std::string meant = likely_meant(ext, {});
            fail_file(file, where + ": " + shown(ext) + " is not an extension name (PREFIX_name, e.g. KHR_materials_unlit)" +
                                (meant.empty() ? "" : "; did you mean '" + meant + "'?"));
        }
        out.push_back(ext);
    }
    return out;
}

// Extensions that change how geometry is stored and that loading decodes: KHR_mesh_quantization (the
// accessors' integer types, AccessorReader), EXT_meshopt_compression (gltf_meshopt.hpp),
// KHR_draco_mesh_compression (gltf_draco.hpp) and EXT_mesh_gpu_instancing (gltf_instancing.hpp).
bool supported(std::string_view ext) {
    return ext == "KHR_mesh_quantization" || ext == "EXT_meshopt_compression" || ext == "KHR_draco_mesh_compression" ||
           ext == "EXT_mesh_gpu_instancing";
}

bool known(std::string_view ext) { return std::find(std::begin(kKnown), std::end(kKnown), ext) != std::end(kKnown); }

}  // namespace

void check_gltf_extensions(const std::string& file, const json& doc, const std::set<std::string>& used) {
    const std::vector<std::string> declared = names(file, doc, "extensionsUsed");
    const std::vector<std::string> required = names(file, doc, "extensionsRequired");
    for (size_t i = 0; i < declared.size(); ++i) {
        const std::string& ext = declared[i];
        if (used.count(ext) || known(ext)) continue;
        // Unknown and unused: a vendor's own extension is allowed, a near miss of a real name is not.
        const std::string meant = likely_meant(ext, used);
        if (!meant.empty())
            fail_file(file, "extensionsUsed[" + std::to_string(i) + "]: unknown extension " + shown(ext) +
                                "; did you mean '" + meant + "'?");
    }
    for (size_t i = 0; i < required.size(); ++i) {
        const std::string& ext = required[i];
        const std::string where = "extensionsRequired[" + std::to_string(i) + "]: ";
        if (std::find(declared.begin(), declared.end(), ext) == declared.end())
            fail_file(file, where + shown(ext) + " is required but not listed in extensionsUsed");
        if (ignorable(ext) || supported(ext)) continue;
        const std::string meant = known(ext) ? std::string() : likely_meant(ext, used);
        fail_file(file, where + "the file requires extension " + shown(ext) + ", which stipple does not support" +
                            (meant.empty() ? "" : " (did you mean '" + meant + "'?)"));
    }
}

}  // namespace stipple
