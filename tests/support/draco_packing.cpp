#include "support/draco_packing.hpp"

#include <cstring>
#include <stdexcept>
#include <vector>

#include <nlohmann/json.hpp>

#include "mesh/draco_codec.h"
#include "mesh/glb_container.hpp"
#include "support/model_files.hpp"

namespace stipple::test {

namespace {

using nlohmann::json;

// draco::DataType's value for a glTF component type, and its size.
int data_type(int component_type) {
    switch (component_type) {
        case 5120: return 1;
        case 5121: return 2;
        case 5122: return 3;
        case 5123: return 4;
        case 5125: return 6;
        case 5126: return 9;
        default: throw std::runtime_error("draco_pack_glb: unknown component type");
    }
}
size_t size_of(int component_type) { return component_type == 5120 || component_type == 5121 ? 1 : component_type == 5122 || component_type == 5123 ? 2 : 4; }

int components_of(const std::string& type) {
    return type == "SCALAR" ? 1 : type == "VEC2" ? 2 : type == "VEC3" ? 3 : type == "VEC4" ? 4 : 0;
}

int kind_of(const std::string& name) {  // StippleDracoInput::kind
    if (name == "POSITION") return 0;
    if (name == "NORMAL") return 1;
    if (name.rfind("COLOR", 0) == 0) return 2;
    if (name.rfind("TEXCOORD", 0) == 0) return 3;
    return 4;
}

// The accessor's elements, tightly packed.
std::string elements(const json& doc, std::string_view bin, int accessor) {
    const json& a = doc["accessors"][accessor];
    const json& v = doc["bufferViews"][a["bufferView"].get<int>()];
    const size_t size = size_of(a["componentType"]) * components_of(a["type"]);
    const size_t stride = v.value("byteStride", size), count = a["count"];
    const size_t base = v.value("byteOffset", size_t(0)) + a.value("byteOffset", size_t(0));
    std::string out;
    for (size_t i = 0; i < count; ++i) out += bin.substr(base + i * stride, size);
    return out;
}

}  // namespace

std::string draco_pack_glb(const std::string& glb, int position_bits) {
    const GlbChunks chunks = split_glb("pack.glb", glb);
    json doc = json::parse(chunks.json);
    std::string bin(chunks.bin);
    for (json& mesh : doc["meshes"])
        for (json& prim : mesh["primitives"]) {
            std::vector<uint32_t> indices;
            const size_t points = doc["accessors"][prim["attributes"]["POSITION"].get<int>()]["count"];
            if (prim.contains("indices")) {
                const json& a = doc["accessors"][prim["indices"].get<int>()];
                const std::string raw = elements(doc, bin, prim["indices"]);
                const size_t size = size_of(a["componentType"]);
                for (size_t i = 0; i < a["count"].get<size_t>(); ++i) {
                    uint32_t v = 0;
                    std::memcpy(&v, raw.data() + i * size, size);
                    indices.push_back(v);
                }
            } else {
                for (uint32_t i = 0; i < points; ++i) indices.push_back(i);
                doc["accessors"].push_back({{"componentType", 5125}, {"count", points}, {"type", "SCALAR"}});
                prim["indices"] = doc["accessors"].size() - 1;
            }
            std::vector<std::string> names, raws;
            std::vector<StippleDracoInput> inputs;
            for (auto it = prim["attributes"].begin(); it != prim["attributes"].end(); ++it) {
                const json& a = doc["accessors"][it.value().get<int>()];
                names.push_back(it.key());
                raws.push_back(elements(doc, bin, it.value().get<int>()));
                StippleDracoInput input{};
                input.attribute.data_type = data_type(a["componentType"]);
                input.attribute.components = components_of(a["type"]);
                input.attribute.component_size = int(size_of(a["componentType"]));
                input.kind = kind_of(it.key());
                input.normalized = a.value("normalized", false);
                inputs.push_back(input);
            }
            for (size_t i = 0; i < inputs.size(); ++i) inputs[i].attribute.values = reinterpret_cast<const unsigned char*>(raws[i].data());
            unsigned char* bytes = nullptr;
            size_t size = 0;
            if (stipple_draco_encode(uint32_t(points), indices.data(), uint32_t(indices.size() / 3), inputs.data(),
                                     uint32_t(inputs.size()), position_bits, &bytes, &size) != 0)
                throw std::runtime_error("draco_pack_glb: encoding failed");
            const std::string encoded(reinterpret_cast<const char*>(bytes), size);
            stipple_draco_free_bytes(bytes);
            json ids = json::object();
            for (size_t i = 0; i < inputs.size(); ++i) ids[names[i]] = inputs[i].attribute.unique_id;
            // The decoded counts, which the accessors must declare.
            StippleDracoMesh out;
            if (stipple_draco_decode(reinterpret_cast<const unsigned char*>(encoded.data()), encoded.size(), &out) != 0)
                throw std::runtime_error("draco_pack_glb: the encoded mesh does not decode");
            const uint32_t decoded_points = out.points, decoded_faces = out.faces;
            stipple_draco_free(&out);
            while (bin.size() % 4) bin.push_back('\0');
            doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", encoded.size()}});
            bin += encoded;
            for (auto it = prim["attributes"].begin(); it != prim["attributes"].end(); ++it) {
                json& a = doc["accessors"][it.value().get<int>()];
                a.erase("bufferView"), a.erase("byteOffset");
                a["count"] = decoded_points;
            }
            json& a = doc["accessors"][prim["indices"].get<int>()];
            a.erase("bufferView"), a.erase("byteOffset");
            a["count"] = 3 * decoded_faces;
            prim["extensions"]["KHR_draco_mesh_compression"] = {{"bufferView", doc["bufferViews"].size() - 1}, {"attributes", ids}};
        }
    while (bin.size() % 4) bin.push_back('\0');
    doc["buffers"][0]["byteLength"] = bin.size();
    doc["extensionsUsed"].push_back("KHR_draco_mesh_compression");
    doc["extensionsRequired"].push_back("KHR_draco_mesh_compression");
    return make_glb(doc.dump(), bin);
}

}  // namespace stipple::test
