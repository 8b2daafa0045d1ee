#include "mesh/gltf_instancing.hpp"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "core/error.hpp"
#include "mesh/loader_util.hpp"

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
    // Every attribute, the application's own (_ID, ...) too, has one element per instance. The counts are
    // checked, against each other and against what the copies would hold, before anything is read: a
    // file of a few hundred bytes can declare an accessor of 150M elements without data (zeros).
    size_t count = 0;
    std::string counted;
    for (const std::string& name : attributes.Keys()) {
        const int index = accessor(name.c_str());
        if (index < 0 || size_t(index) >= model.accessors.size()) continue;  // gltf_validate refused these
        const size_t n = model.accessors[size_t(index)].count;
        const std::string where = field + ".attributes." + name;
        if (n == 0) fail_file(path, where + ": 0 instances (an accessor holds at least one element)");
        if (!counted.empty() && n != count)
            fail_file(path, where + ": " + std::to_string(n) + " instances, but " + counted + " has " + std::to_string(count));
        count = n;
        counted = name;
    }
    if (counted.empty()) fail_file(path, field + ".attributes: empty (no instance is defined)");
    // The node's mesh, copied once per instance: its vertices in all (the loaders refuse more; checked
    // here before the instances' transforms are read and the copies made).
    uint64_t mesh_vertices = 0;
    if (node.mesh >= 0 && size_t(node.mesh) < model.meshes.size())
        for (const tinygltf::Primitive& prim : model.meshes[size_t(node.mesh)].primitives)
            if (const auto position = prim.attributes.find("POSITION");
                position != prim.attributes.end() && position->second >= 0 && size_t(position->second) < model.accessors.size())
                mesh_vertices = std::min<uint64_t>(mesh_vertices + std::min<uint64_t>(model.accessors[size_t(position->second)].count,
                                                                                        options.max_elements + 1),
                                                   options.max_elements + 1);  // no overflow from absurd counts
    if (count > options.max_elements || (mesh_vertices > 0 && count > options.max_elements / mesh_vertices))
        fail_file(path, field + ": " + std::to_string(count) + " instances of a mesh of " + std::to_string(mesh_vertices) +
                            " vertices, more than the limit of " + std::to_string(options.max_elements) + " vertices");
    // Each instance's transform (a dmat4) and its copy of the mesh's vertices (its triangles are counted
    // when the copies are made), before any of it is read.
    check_load_fits_memory(path, field, uint64_t(count) * mesh_vertices, 0, uint64_t(count) * sizeof(glm::dmat4));
    for (Attribute& a : read) {
        const int index = accessor(a.name);
        if (index < 0) continue;
        a.values = reader.numbers(index, a.type, a.plain, a.normalized, field + ".attributes." + a.name);
    }
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
