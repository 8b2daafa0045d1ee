#pragma once
// EXT_meshopt_compression: glTF buffer views stored compressed with meshoptimizer's codecs (attributes,
// triangle lists, index sequences, and the octahedral, quaternion and exponential filters), as gltfpack
// writes them. The uncompressed layout is the parent view's; its buffer may be a placeholder with no data
// (no uri, and not the first buffer of a .glb, whose data is the BIN chunk).
//
// tinygltf knows nothing of the extension and needs data for every buffer, so loading goes in two steps
// around it (gltf_document.cpp): prepare_meshopt gives each placeholder a few bytes to load, and
// decode_meshopt then sizes it to what its views need and decodes every compressed view into its place.
// gltf_validate checks the extension's fields first (strides, modes, filters, counts, byte ranges).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

namespace stipple {

// Whether buffer `index` of a document holds no data of its own: no uri, and not the BIN chunk of a .glb.
bool is_placeholder_buffer(const nlohmann::json& buffer, size_t index, bool glb);

struct MeshoptView {
    size_t view = 0;              // the parent buffer view, which names where the data goes
    size_t source_buffer = 0;     // where the compressed bytes are
    uint64_t source_offset = 0, source_length = 0;
    uint64_t stride = 0, count = 0;
    std::string mode, filter;     // ATTRIBUTES, TRIANGLES or INDICES; NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL
};

struct MeshoptPlan {
    std::vector<MeshoptView> views;
    std::vector<size_t> placeholders;  // buffers with no data of their own
    bool empty() const { return views.empty() && placeholders.empty(); }
};

// Lists the compressed views of a validated document and gives each placeholder buffer three bytes of
// data: URI (byteLength 3), which decode_meshopt replaces.
MeshoptPlan prepare_meshopt(nlohmann::json& doc, bool glb);

// After tinygltf has loaded the prepared document: every placeholder buffer as long as the views into it
// need (zeros), and every compressed view decoded into its parent view's bytes. Throws stipple::Error
// "<file>: bufferViews[i].extensions.EXT_meshopt_compression: ..." for data that does not decode.
void decode_meshopt(const std::string& file, const MeshoptPlan& plan, tinygltf::Model& model);

}  // namespace stipple
