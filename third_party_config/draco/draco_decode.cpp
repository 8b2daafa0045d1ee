// The decoding half of src/mesh/draco_codec.h, linked with libdraco.a into one object whose other symbols
// are all made local (third_party_config/Draco.cmake). With draco_encode.cpp, the only files that include
// libdraco's headers.
#include "mesh/draco_codec.h"

#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <new>
#include <vector>

#include <draco/compression/decode.h>
#include <draco/mesh/mesh.h>

namespace {

struct Owned {
    std::vector<uint32_t> corners;
    std::vector<std::vector<unsigned char>> values;
    std::vector<StippleDracoAttribute> attributes;
};

int failed(StippleDracoMesh* out, const char* problem) {
    std::snprintf(out->error, sizeof out->error, "%s", problem);
    return 1;
}

}  // namespace

namespace {

int decode(const unsigned char* data, size_t size, StippleDracoMesh* out) {
    draco::DecoderBuffer bitstream;
    bitstream.Init(reinterpret_cast<const char*>(data), size);
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&bitstream);
    if (!decoded.ok()) return failed(out, decoded.status().error_msg_string().c_str());
    const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
    if (!mesh) return failed(out, "the bitstream holds no mesh");
    auto owned = std::make_unique<Owned>();
    const uint32_t points = mesh->num_points(), faces = mesh->num_faces();
    owned->corners.resize(3 * size_t(faces));
    for (uint32_t f = 0; f < faces; ++f) {
        const draco::Mesh::Face& face = mesh->face(draco::FaceIndex(f));
        for (int c = 0; c < 3; ++c) {
            if (face[c].value() >= points) return failed(out, "a triangle refers to a point the mesh does not have");
            owned->corners[3 * size_t(f) + size_t(c)] = face[c].value();
        }
    }
    // Every read below is checked against the attribute's own buffer: the decoder's tables are trusted no further.
    for (int32_t i = 0; i < mesh->num_attributes(); ++i) {
        const draco::PointAttribute* att = mesh->attribute(i);
        if (!att || !att->buffer()) return failed(out, "an attribute has no data");
        const int component_size = draco::DataTypeLength(att->data_type());
        const size_t element = size_t(att->num_components()) * size_t(component_size > 0 ? component_size : 0);
        if (element == 0 || size_t(att->byte_stride()) != element || (!att->is_mapping_identity() && att->indices_map_size() < points))
            return failed(out, "an attribute is inconsistent");
        std::vector<unsigned char> values(size_t(points) * element);
        const size_t stored = att->buffer()->data_size();
        for (uint32_t p = 0; p < points; ++p) {
            const uint64_t value = att->mapped_index(draco::PointIndex(p)).value();
            const uint64_t at = uint64_t(att->byte_offset()) + value * element;
            if (value >= att->size() || at + element > stored) return failed(out, "a point refers to a value the bitstream does not hold");
            std::memcpy(values.data() + size_t(p) * element, att->buffer()->data() + at, element);
        }
        owned->values.push_back(std::move(values));
        owned->attributes.push_back({att->unique_id(), int(att->data_type()), int(att->num_components()), component_size,
                                     nullptr});
    }
    for (size_t i = 0; i < owned->attributes.size(); ++i) owned->attributes[i].values = owned->values[i].data();
    out->points = points;
    out->faces = faces;
    out->corners = owned->corners.data();
    out->attribute_count = uint32_t(owned->attributes.size());
    out->attributes = owned->attributes.data();
    out->owner = owned.release();
    return 0;
}

}  // namespace

extern "C" int stipple_draco_decode(const unsigned char* data, size_t size, StippleDracoMesh* out) {
    *out = StippleDracoMesh{};
    // Nothing may leave through the C interface: a header that asks for more than memory holds is one more
    // way for a bitstream not to decode.
    try {
        return decode(data, size, out);
    } catch (const std::bad_alloc&) {
        return failed(out, "the bitstream asks for more memory than there is");
    } catch (const std::exception& e) {
        return failed(out, e.what());
    }
}

extern "C" void stipple_draco_free(StippleDracoMesh* mesh) {
    delete static_cast<Owned*>(mesh->owner);
    *mesh = StippleDracoMesh{};
}

