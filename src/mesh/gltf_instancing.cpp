#include "mesh/gltf_instancing.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "core/error.hpp"

namespace stipple {

std::vector<glm::dmat4> read_gpu_instances(const std::string& path, const tinygltf::Model& model, int node_index,
                                           const AccessorReader& reader, const LoadOptions& options) {
    const tinygltf::Node& node = model.nodes[node_index];
    const auto ext = node.extensions.find("EXT_mesh_gpu_instancing");
    if (ext == node.extensions.end()) return {};
    const std::string field = "nodes[" + std::to_string(node_index) + "].extensions.EXT_mesh_gpu_instancing";
    // gltf_validate checked the object, its attributes and their accessor indices.
    const tinygltf::Value& attributes = ext->second.Get("attributes");
    auto accessor = [&](const char* name) { return attributes.Has(name) ? attributes.Get(name).GetNumberAsInt() : -1; };
    // The types the extension allows (with KHR_mesh_quantization, integers for translation and scale too).
    const std::vector<int> kRotationTypes = {TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT};
    struct Attribute {
        const char* name;
        int type;
        std::vector<int> plain, normalized;
        std::vector<float> values;
    };
    Attribute read[] = {{"TRANSLATION", TINYGLTF_TYPE_VEC3, kGltfQuantizedTypes, kGltfQuantizedTypes, {}},
                        {"ROTATION", TINYGLTF_TYPE_VEC4, {}, kRotationTypes, {}},
                        {"SCALE", TINYGLTF_TYPE_VEC3, kGltfQuantizedTypes, kGltfQuantizedTypes, {}}};
    size_t count = 0;
    const char* counted = nullptr;
    for (Attribute& a : read) {
        const int index = accessor(a.name);
        if (index < 0) continue;
        const std::string where = field + ".attributes." + a.name;
        a.values = reader.numbers(index, a.type, a.plain, a.normalized, where);
        const size_t n = a.values.size() / (a.type == TINYGLTF_TYPE_VEC4 ? 4 : 3);
        if (counted && n != count)
            fail_file(path, where + ": " + std::to_string(n) + " instances, but " + counted + " has " + std::to_string(count));
        count = n;
        counted = a.name;
    }
    if (!counted) fail_file(path, field + ".attributes: none of TRANSLATION, ROTATION or SCALE");
    if (count > options.max_elements)
        fail_file(path, field + ": " + std::to_string(count) + " instances, more than the limit of " +
                            std::to_string(options.max_elements));
    std::vector<glm::dmat4> out(count, glm::dmat4(1.0));
    for (size_t i = 0; i < count; ++i) {
        glm::dmat4& m = out[i];
        if (const auto& t = read[0].values; !t.empty()) m[3] = glm::dvec4(t[3 * i], t[3 * i + 1], t[3 * i + 2], 1.0);
        if (const auto& r = read[1].values; !r.empty()) {
            const glm::dquat q(r[4 * i + 3], r[4 * i], r[4 * i + 1], r[4 * i + 2]);  // stored x, y, z, w
            const double length = glm::length(q);
            if (!(length > 0.0)) fail_file(path, field + ".attributes.ROTATION: instance " + std::to_string(i) + " is a zero quaternion");
            m = m * glm::mat4_cast(q / length);
        }
        if (const auto& s = read[2].values; !s.empty()) m = m * glm::scale(glm::dmat4(1.0), glm::dvec3(s[3 * i], s[3 * i + 1], s[3 * i + 2]));
    }
    return out;
}

}  // namespace stipple
