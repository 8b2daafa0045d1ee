#include "support/meshopt_packing.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <vector>

#include <meshoptimizer.h>
#include <nlohmann/json.hpp>

#include "mesh/glb_container.hpp"
#include "support/model_files.hpp"

namespace stipple::test {

namespace {

std::vector<uint32_t> indices_of(const std::string& bytes, uint32_t stride) {
    std::vector<uint32_t> out(bytes.size() / stride);
    for (size_t i = 0; i < out.size(); ++i) {
        uint32_t v = 0;
        std::memcpy(&v, bytes.data() + i * stride, stride);  // little-endian, as every machine this runs on
        out[i] = v;
    }
    return out;
}

std::string encode(const std::string& raw, const ViewCoding& coding) {
    const size_t count = raw.size() / coding.stride;
    std::vector<unsigned char> out;
    size_t size = 0;
    if (coding.mode == "ATTRIBUTES") {
        out.resize(meshopt_encodeVertexBufferBound(count, coding.stride));
        size = meshopt_encodeVertexBuffer(out.data(), out.size(), raw.data(), count, coding.stride);
    } else {
        const std::vector<uint32_t> indices = indices_of(raw, coding.stride);
        uint32_t vertices = 0;
        for (uint32_t i : indices) vertices = std::max(vertices, i + 1);
        if (coding.mode == "TRIANGLES") {
            out.resize(meshopt_encodeIndexBufferBound(count, vertices));
            size = meshopt_encodeIndexBuffer(out.data(), out.size(), indices.data(), count);
        } else {
            out.resize(meshopt_encodeIndexSequenceBound(count, vertices));
            size = meshopt_encodeIndexSequence(out.data(), out.size(), indices.data(), count);
        }
    }
    if (size == 0) throw std::runtime_error("meshopt_pack_glb: encoding failed");
    return std::string(reinterpret_cast<const char*>(out.data()), size);
}

}  // namespace

std::string meshopt_pack_glb(const std::string& glb, const std::map<size_t, ViewCoding>& codings) {
    const GlbChunks chunks = split_glb("pack.glb", glb);
    nlohmann::json doc = nlohmann::json::parse(chunks.json);
    std::string bin;
    uint64_t placeholder_length = 0;
    auto align = [](std::string& s) { while (s.size() % 4) s.push_back('\0'); };
    nlohmann::json& views = doc["bufferViews"];
    bool fallback_flag = true;
    for (size_t i = 0; i < views.size(); ++i) {
        nlohmann::json& v = views[i];
        const size_t offset = v.value("byteOffset", size_t(0)), length = v["byteLength"].get<size_t>();
        const std::string raw(chunks.bin.substr(offset, length));
        ViewCoding coding;
        const auto listed = codings.find(i);
        const bool compress = codings.empty() ? length % 4 == 0 : listed != codings.end();
        if (listed != codings.end()) coding = listed->second, fallback_flag = coding.fallback_flag;
        else if (v.contains("byteStride")) coding.stride = v["byteStride"].get<uint32_t>();  // must match the view's
        align(bin);
        if (!compress) {
            v["byteOffset"] = bin.size();
            bin += raw;
            continue;
        }
        const std::string packed = encode(raw, coding);
        nlohmann::json e = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", packed.size()},
                            {"byteStride", coding.stride}, {"count", length / coding.stride}, {"mode", coding.mode}};
        if (coding.filter != "NONE") e["filter"] = coding.filter;
        bin += packed;
        while (placeholder_length % 16) ++placeholder_length;
        v["buffer"] = 1;
        v["byteOffset"] = placeholder_length;
        placeholder_length += length;
        v["extensions"]["EXT_meshopt_compression"] = e;
    }
    align(bin);
    doc["buffers"] = nlohmann::json::array({{{"byteLength", bin.size()}}, {{"byteLength", std::max<uint64_t>(placeholder_length, 1)}}});
    if (fallback_flag) doc["buffers"][1]["extensions"]["EXT_meshopt_compression"] = {{"fallback", true}};
    doc["extensionsUsed"].push_back("EXT_meshopt_compression");
    doc["extensionsRequired"].push_back("EXT_meshopt_compression");
    return make_glb(doc.dump(), bin);
}

}  // namespace stipple::test
