#include "mesh/gltf_draco.hpp"

#include <cstring>

#include "core/error.hpp"
#include "mesh/draco_codec.h"
#include "mesh/gltf_accessor.hpp"
#include "mesh/loader_util.hpp"

namespace stipple {

namespace {

// The glTF component type that a Draco data type (draco::DataType's values) is stored as, or 0.
int component_type_of(int draco_type) {
    switch (draco_type) {
        case 1: return TINYGLTF_COMPONENT_TYPE_BYTE;
        case 2: return TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
        case 3: return TINYGLTF_COMPONENT_TYPE_SHORT;
        case 4: return TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
        case 6: return TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        case 9: return TINYGLTF_COMPONENT_TYPE_FLOAT;
        default: return 0;
    }
}

// A decoded mesh, freed with its owner.
struct DecodedMesh {
    StippleDracoMesh mesh;
    ~DecodedMesh() { stipple_draco_free(&mesh); }
};

class PrimitiveDecoder {
public:
    PrimitiveDecoder(const std::string& file, tinygltf::Model& model, std::string field)
        : file_(file), model_(model), field_(std::move(field)) {}

    void run(tinygltf::Primitive& prim, const tinygltf::Value& extension) {
        if (prim.mode >= 0 && prim.mode != TINYGLTF_MODE_TRIANGLES)
            fail("the primitive's mode must be TRIANGLES (4), not " + std::to_string(prim.mode));
        const int view_index = extension.Get("bufferView").GetNumberAsInt();
        if (view_index < 0 || static_cast<size_t>(view_index) >= model_.bufferViews.size())
            fail("bufferView " + std::to_string(view_index) + " does not exist");
        const tinygltf::BufferView& view = model_.bufferViews[static_cast<size_t>(view_index)];
        const std::vector<unsigned char>& data = model_.buffers.at(static_cast<size_t>(view.buffer)).data;
        if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
            fail("buffer view " + std::to_string(view_index) + " reaches past the end of its buffer");

        if (stipple_draco_decode(data.data() + view.byteOffset, view.byteLength, &decoded_.mesh) != 0)
            fail("the Draco bitstream does not decode: " + one_line(decoded_.mesh.error));

        // Appended after the decoding: `view` and `data` above may move when buffers grow.
        const size_t buffer = model_.buffers.size();
        model_.buffers.emplace_back();
        buffer_ = buffer;
        const tinygltf::Value& attributes = extension.Get("attributes");
        for (const std::string& name : attributes.Keys()) {
            const auto accessor = prim.attributes.find(name);
            if (accessor == prim.attributes.end())
                fail("attributes." + name + ": the primitive has no " + name + " attribute");
            attribute(name, attributes.Get(name).GetNumberAsInt(), accessor->second);
        }
        if (prim.indices >= 0) indices(prim.indices);
    }

private:
    [[noreturn]] void fail(const std::string& problem) const { fail_file(file_, field_ + ": " + problem); }

    tinygltf::Accessor& accessor(int index, const std::string& what) {
        if (index < 0 || static_cast<size_t>(index) >= model_.accessors.size())
            fail(what + ": accessor " + std::to_string(index) + " does not exist");
        return model_.accessors[static_cast<size_t>(index)];
    }

    // Points the accessor at `bytes`, appended to the decoded buffer as a view of its own.
    void store(tinygltf::Accessor& a, const std::vector<unsigned char>& bytes) {
        std::vector<unsigned char>& out = model_.buffers[buffer_].data;
        while (out.size() % 4) out.push_back(0);
        tinygltf::BufferView view;
        view.buffer = static_cast<int>(buffer_);
        view.byteOffset = out.size();
        view.byteLength = bytes.size();
        out.insert(out.end(), bytes.begin(), bytes.end());
        model_.bufferViews.push_back(view);
        a.bufferView = static_cast<int>(model_.bufferViews.size() - 1);
        a.byteOffset = 0;
        a.sparse.isSparse = false;  // the decoded values are the whole accessor
    }

    void attribute(const std::string& name, int unique_id, int accessor_index) {
        const std::string what = "attributes." + name;
        tinygltf::Accessor& a = accessor(accessor_index, what);
        const StippleDracoMesh& mesh = decoded_.mesh;
        const StippleDracoAttribute* att = nullptr;
        for (uint32_t i = 0; i < mesh.attribute_count; ++i)
            if (unique_id >= 0 && mesh.attributes[i].unique_id == static_cast<uint32_t>(unique_id)) att = &mesh.attributes[i];
        if (!att) fail(what + ": the bitstream has no attribute " + std::to_string(unique_id));
        const int components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
        const int component_size = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType));
        if (components <= 0 || component_size <= 0) fail(what + ": accessor " + std::to_string(accessor_index) + " has an invalid type");
        if (component_type_of(att->data_type) != a.componentType || att->components != components)
            fail(what + ": the bitstream's attribute is " + std::to_string(att->components) + " values of " +
                 component_type_name(component_type_of(att->data_type)) + ", its accessor " + accessor_type_name(a.type) +
                 " of " + component_type_name(a.componentType));
        if (a.count != mesh.points)
            fail(what + ": accessor " + std::to_string(accessor_index) + " has " + std::to_string(a.count) +
                 " elements, the bitstream " + std::to_string(mesh.points) + " points");
        const size_t bytes = size_t(mesh.points) * size_t(components) * size_t(component_size);
        store(a, std::vector<unsigned char>(att->values, att->values + bytes));
    }

    void indices(int accessor_index) {
        tinygltf::Accessor& a = accessor(accessor_index, "indices");
        const StippleDracoMesh& mesh = decoded_.mesh;
        if (a.type != TINYGLTF_TYPE_SCALAR || a.count != 3 * size_t(mesh.faces))
            fail("indices: accessor " + std::to_string(accessor_index) + " has " + std::to_string(a.count) +
                 " elements, the bitstream " + std::to_string(mesh.faces) + " triangles");
        const int size = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType));
        if (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
            a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
            fail("indices: accessor " + std::to_string(accessor_index) + " is not of unsigned byte, short or int");
        const uint64_t largest = size == 1 ? 0xFF : size == 2 ? 0xFFFF : 0xFFFFFFFF;
        std::vector<unsigned char> bytes(3 * size_t(mesh.faces) * size_t(size));
        for (size_t i = 0; i < 3 * size_t(mesh.faces); ++i) {
            const uint32_t v = mesh.corners[i];  // below mesh.points (draco_codec.h)
            if (v > largest)
                fail("indices: triangle " + std::to_string(i / 3) + " refers to point " + std::to_string(v) +
                     ", beyond what accessor " + std::to_string(accessor_index) + "'s type holds");
            std::memcpy(bytes.data() + i * size_t(size), &v, size_t(size));  // little-endian
        }
        store(a, bytes);
    }

    const std::string& file_;
    tinygltf::Model& model_;
    std::string field_;
    DecodedMesh decoded_;
    size_t buffer_ = 0;
};

}  // namespace

bool prepare_draco(nlohmann::json& doc) {
    const auto meshes = doc.find("meshes");
    const auto accessors = doc.find("accessors");
    if (meshes == doc.end() || accessors == doc.end()) return false;
    int stand_in = -1;  // the view every such accessor points at
    for (nlohmann::json& mesh : *meshes) {
        const auto primitives = mesh.find("primitives");
        if (primitives == mesh.end()) continue;
        for (nlohmann::json& prim : *primitives) {
            const auto extensions = prim.find("extensions");
            if (extensions == prim.end() || !extensions->contains("KHR_draco_mesh_compression") || !prim.contains("indices"))
                continue;
            nlohmann::json& a = (*accessors)[prim["indices"].get<size_t>()];  // gltf_validate checked the index
            if (a.contains("bufferView")) continue;
            if (stand_in < 0) {
                doc["buffers"].push_back({{"uri", "data:application/octet-stream;base64,AAAAAA=="}, {"byteLength", 4}});
                doc["bufferViews"].push_back({{"buffer", doc["buffers"].size() - 1}, {"byteLength", 4}});
                stand_in = static_cast<int>(doc["bufferViews"].size() - 1);
            }
            a["bufferView"] = stand_in;
        }
    }
    return stand_in >= 0;
}

size_t decode_draco(const std::string& file, tinygltf::Model& model) {
    size_t decoded = 0;
    for (size_t m = 0; m < model.meshes.size(); ++m)
        for (size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            tinygltf::Primitive& prim = model.meshes[m].primitives[p];
            const auto extension = prim.extensions.find("KHR_draco_mesh_compression");
            if (extension == prim.extensions.end()) continue;
            const std::string field = "meshes[" + std::to_string(m) + "].primitives[" + std::to_string(p) +
                                      "].extensions.KHR_draco_mesh_compression";
            PrimitiveDecoder(file, model, field).run(prim, extension->second);
            ++decoded;
        }
    return decoded;
}

}  // namespace stipple
