// The encoding half of src/mesh/draco_codec.h (for the tests, which write Draco files), linked with libdraco.a
// into one object whose other symbols are all made local (third_party_config/Draco.cmake).
#include "mesh/draco_codec.h"

#include <cstring>
#include <exception>

#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>

namespace {

int encode(uint32_t points, const uint32_t* corners, uint32_t faces, StippleDracoInput* attributes,
           uint32_t attribute_count, int position_bits, unsigned char** bytes, size_t* size) {
    draco::Mesh mesh;
    mesh.set_num_points(points);
    for (uint32_t f = 0; f < faces; ++f)
        mesh.AddFace({draco::PointIndex(corners[3 * f]), draco::PointIndex(corners[3 * f + 1]), draco::PointIndex(corners[3 * f + 2])});
    const draco::GeometryAttribute::Type kinds[] = {draco::GeometryAttribute::POSITION, draco::GeometryAttribute::NORMAL,
                                                    draco::GeometryAttribute::COLOR, draco::GeometryAttribute::TEX_COORD,
                                                    draco::GeometryAttribute::GENERIC};
    for (uint32_t i = 0; i < attribute_count; ++i) {
        StippleDracoAttribute& a = attributes[i].attribute;
        const auto type = static_cast<draco::DataType>(a.data_type);
        const int64_t element = int64_t(draco::DataTypeLength(type)) * a.components;
        draco::GeometryAttribute ga;
        ga.Init(kinds[attributes[i].kind], nullptr, uint8_t(a.components), type, attributes[i].normalized, element, 0);
        const int id = mesh.AddAttribute(ga, true, points);
        if (id < 0) return 1;
        for (uint32_t p = 0; p < points; ++p)
            mesh.attribute(id)->SetAttributeValue(draco::AttributeValueIndex(p), a.values + size_t(p) * size_t(element));
        a.unique_id = mesh.attribute(id)->unique_id();
    }
    draco::Encoder encoder;
    encoder.SetSpeedOptions(5, 5);
    if (position_bits > 0) encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, position_bits);
    draco::EncoderBuffer encoded;
    if (!encoder.EncodeMeshToBuffer(mesh, &encoded).ok()) return 1;
    *size = encoded.size();
    *bytes = new unsigned char[encoded.size()];
    std::memcpy(*bytes, encoded.data(), encoded.size());
    return 0;
}

}  // namespace

extern "C" int stipple_draco_encode(uint32_t points, const uint32_t* corners, uint32_t faces, StippleDracoInput* attributes,
                                    uint32_t attribute_count, int position_bits, unsigned char** bytes, size_t* size) {
    try {
        return encode(points, corners, faces, attributes, attribute_count, position_bits, bytes, size);
    } catch (...) {  // nothing leaves through the C interface
        return 1;
    }
}

extern "C" void stipple_draco_free_bytes(unsigned char* bytes) { delete[] bytes; }
