#include "mesh/gltf_meshopt.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <vector>

#include <meshoptimizer.h>

#include "core/error.hpp"

namespace stipple {

namespace {

using json = nlohmann::json;

// The most bytes a compressed byte can become. meshoptimizer's attribute codec spends at least two bits per
// 16 bytes of a byte column (64:1), its index codecs at least a nibble per triangle or a byte per index: a
// placeholder buffer longer than this many times its views' compressed bytes is refused rather than
// allocated (a few bytes of JSON could otherwise ask for terabytes).
constexpr uint64_t kMaxExpansion = 256;
constexpr uint64_t kExpansionSlack = uint64_t(1) << 20;

// Three zero bytes: what tinygltf loads for a placeholder until decode_meshopt sizes it.
constexpr const char* kPlaceholderUri = "data:application/octet-stream;base64,AAAA";
constexpr uint64_t kPlaceholderBytes = 3;

std::string view_field(size_t view) {
    return "bufferViews[" + std::to_string(view) + "].extensions.EXT_meshopt_compression";
}

}  // namespace

bool is_placeholder_buffer(const json& buffer, size_t index, bool glb) {
    return buffer.is_object() && !buffer.contains("uri") && !(glb && index == 0);
}

MeshoptPlan prepare_meshopt(json& doc, bool glb) {
    MeshoptPlan plan;
    if (auto buffers = doc.find("buffers"); buffers != doc.end() && buffers->is_array())
        for (size_t i = 0; i < buffers->size(); ++i) {
            json& b = (*buffers)[i];
            if (!is_placeholder_buffer(b, i, glb)) continue;
            plan.placeholders.push_back(i);
            b["uri"] = kPlaceholderUri;
            b["byteLength"] = kPlaceholderBytes;
        }
    if (auto views = doc.find("bufferViews"); views != doc.end() && views->is_array())
        for (size_t i = 0; i < views->size(); ++i) {
            const json& v = (*views)[i];
            const auto extensions = v.find("extensions");
            if (extensions == v.end() || !extensions->is_object()) continue;
            const auto e = extensions->find("EXT_meshopt_compression");
            if (e == extensions->end()) continue;
            // gltf_validate has checked every field's presence, type and range.
            MeshoptView m;
            m.view = i;
            m.source_buffer = (*e)["buffer"].get<size_t>();
            m.source_offset = e->value("byteOffset", uint64_t(0));
            m.source_length = (*e)["byteLength"].get<uint64_t>();
            m.stride = (*e)["byteStride"].get<uint64_t>();
            m.count = (*e)["count"].get<uint64_t>();
            m.mode = (*e)["mode"].get<std::string>();
            m.filter = e->value("filter", std::string("NONE"));
            plan.views.push_back(std::move(m));
        }
    return plan;
}

void decode_meshopt(const std::string& file, const MeshoptPlan& plan, tinygltf::Model& model) {
    // Each placeholder as long as the furthest view into it, within what the views decode to (each view's
    // bytes, and up to 4 of alignment before it) and what their compressed bytes can fill, each byte of
    // those counted once: 100 views sharing one source range, or one tiny view placed far out, had a
    // 106 KB file reserve 1.6 GB (found by review, 2026-12-04).
    std::map<size_t, uint64_t> extent, decoded_bytes;
    std::map<size_t, std::vector<std::pair<uint64_t, uint64_t>>> sources;  // per placeholder: (start, end) by source
    for (const MeshoptView& m : plan.views) {
        const tinygltf::BufferView& v = model.bufferViews.at(m.view);
        const size_t b = static_cast<size_t>(v.buffer);
        extent[b] = std::max<uint64_t>(extent[b], uint64_t(v.byteOffset) + v.byteLength);
        decoded_bytes[b] += uint64_t(v.byteLength) + 4;
        // Source buffers apart: their ranges as one line, each buffer on its own stretch of it.
        const uint64_t origin = uint64_t(m.source_buffer) << 40;
        sources[b].push_back({origin + m.source_offset, origin + m.source_offset + m.source_length});
    }
    for (size_t b : plan.placeholders) {
        const uint64_t need = extent[b];
        std::vector<std::pair<uint64_t, uint64_t>>& ranges = sources[b];
        std::sort(ranges.begin(), ranges.end());
        uint64_t compressed = 0, covered_to = 0;
        for (const auto& [start, end] : ranges) {
            const uint64_t from = std::max(start, covered_to);
            if (end > from) compressed += end - from;
            covered_to = std::max(covered_to, end);
        }
        if (need > decoded_bytes[b] + kExpansionSlack)
            fail_file(file, "buffers[" + std::to_string(b) + "]: its compressed views reach byte " + std::to_string(need) +
                                ", beyond the " + std::to_string(decoded_bytes[b]) + " bytes they decode to");
        if (need > kMaxExpansion * compressed + kExpansionSlack)
            fail_file(file, "buffers[" + std::to_string(b) + "]: its compressed views reach byte " + std::to_string(need) +
                                ", more than their " + std::to_string(compressed) + " compressed bytes can decode to");
        model.buffers.at(b).data.assign(static_cast<size_t>(need), 0);
    }
    std::vector<unsigned char> decoded;
    for (const MeshoptView& m : plan.views) {
        const std::string where = view_field(m.view);
        const tinygltf::BufferView& v = model.bufferViews.at(m.view);
        const std::vector<unsigned char>& source = model.buffers.at(m.source_buffer).data;
        std::vector<unsigned char>& target = model.buffers.at(static_cast<size_t>(v.buffer)).data;
        const uint64_t bytes = m.count * m.stride;  // the view's byteLength (gltf_validate)
        if (m.source_offset > source.size() || m.source_length > source.size() - m.source_offset)
            fail_file(file, where + ": its bytes reach past the end of buffer " + std::to_string(m.source_buffer));
        if (v.byteOffset > target.size() || bytes > target.size() - v.byteOffset)
            fail_file(file, where + ": the decoded data reaches past the end of buffer " + std::to_string(v.buffer));
        // Decoded apart and copied: the filters read the elements as 16-bit and 32-bit numbers, which the
        // parent view need not align.
        decoded.assign(static_cast<size_t>(bytes), 0);
        const unsigned char* in = source.data() + m.source_offset;
        const size_t count = static_cast<size_t>(m.count), stride = static_cast<size_t>(m.stride);
        const size_t length = static_cast<size_t>(m.source_length);
        int status = 0;
        if (m.mode == "ATTRIBUTES") status = meshopt_decodeVertexBuffer(decoded.data(), count, stride, in, length);
        else if (m.mode == "TRIANGLES") status = meshopt_decodeIndexBuffer(decoded.data(), count, stride, in, length);
        else status = meshopt_decodeIndexSequence(decoded.data(), count, stride, in, length);
        if (status != 0)
            fail_file(file, where + ": its " + std::to_string(m.source_length) + " bytes do not decode as " + m.mode + " (" +
                                std::to_string(m.count) + " elements of " + std::to_string(m.stride) +
                                " bytes; meshoptimizer error " + std::to_string(status) + ")");
        if (m.filter == "OCTAHEDRAL") meshopt_decodeFilterOct(decoded.data(), count, stride);
        else if (m.filter == "QUATERNION") meshopt_decodeFilterQuat(decoded.data(), count, stride);
        else if (m.filter == "EXPONENTIAL") meshopt_decodeFilterExp(decoded.data(), count, stride);
        std::memcpy(target.data() + v.byteOffset, decoded.data(), decoded.size());
    }
}

}  // namespace stipple
