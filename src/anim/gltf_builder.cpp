#include "anim/gltf_builder.hpp"

#include <algorithm>
#include <fstream>
#include <limits>

#include "core/error.hpp"
#include "mesh/glb_container.hpp"

namespace stipple::anim {

namespace {

size_t components_of(const std::string& type) {
    if (type == "SCALAR") return 1;
    if (type == "VEC2") return 2;
    if (type == "VEC3") return 3;
    if (type == "VEC4" || type == "MAT2") return 4;
    if (type == "MAT3") return 9;
    if (type == "MAT4") return 16;
    fail("GltfBuilder: unknown accessor type '" + type + "'");
}

}  // namespace

GltfBuilder::GltfBuilder() {
    doc = {{"asset", {{"version", "2.0"}, {"generator", "stipple"}}}};
}

int GltfBuilder::add(const std::string& array, nlohmann::json value) {
    if (!doc.contains(array)) doc[array] = nlohmann::json::array();
    doc[array].push_back(std::move(value));
    return static_cast<int>(doc[array].size() - 1);
}

int GltfBuilder::add_accessor(const void* bytes, size_t byte_count, int component_type, const std::string& type,
                              size_t count, bool normalized) {
    while (bin_.size() % 4) bin_ += '\0';
    const size_t offset = bin_.size();
    bin_.append(static_cast<const char*>(bytes), byte_count);
    const int view = add("bufferViews", {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", byte_count}});
    nlohmann::json accessor = {{"bufferView", view}, {"componentType", component_type}, {"count", count}, {"type", type}};
    if (normalized) accessor["normalized"] = true;
    return add("accessors", std::move(accessor));
}

int GltfBuilder::add_floats(const std::vector<float>& data, const std::string& type) {
    const size_t n = components_of(type);
    const int index = add_accessor(data.data(), data.size() * sizeof(float), 5126, type, data.size() / n, false);
    if (!data.empty()) {
        std::vector<float> lo(n, std::numeric_limits<float>::max()), hi(n, std::numeric_limits<float>::lowest());
        for (size_t i = 0; i < data.size(); ++i) lo[i % n] = std::min(lo[i % n], data[i]), hi[i % n] = std::max(hi[i % n], data[i]);
        doc["accessors"][index]["min"] = lo;
        doc["accessors"][index]["max"] = hi;
    }
    return index;
}

int GltfBuilder::add_uint16(const std::vector<uint16_t>& data, const std::string& type) {
    return add_accessor(data.data(), data.size() * 2, 5123, type, data.size() / components_of(type), false);
}

int GltfBuilder::add_int16(const std::vector<int16_t>& data, const std::string& type, bool normalized) {
    return add_accessor(data.data(), data.size() * 2, 5122, type, data.size() / components_of(type), normalized);
}

int GltfBuilder::add_uint8(const std::vector<uint8_t>& data, const std::string& type, bool normalized) {
    return add_accessor(data.data(), data.size(), 5121, type, data.size() / components_of(type), normalized);
}

int GltfBuilder::add_uint32(const std::vector<uint32_t>& data, const std::string& type) {
    return add_accessor(data.data(), data.size() * 4, 5125, type, data.size() / components_of(type), false);
}

std::string GltfBuilder::glb() const {
    nlohmann::json d = doc;
    std::string bin = bin_;
    while (bin.size() % 4) bin += '\0';
    if (!bin.empty()) d["buffers"] = nlohmann::json::array({{{"byteLength", bin.size()}}});
    return join_glb(d.dump(), bin);
}

void GltfBuilder::write(const std::string& path) const {
    const std::string bytes = glb();
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) fail_file(path, "cannot write the file");
}

}  // namespace stipple::anim
