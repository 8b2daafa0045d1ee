#pragma once
// Writes small glTF files from code (tests, generated benchmark models): one binary buffer, accessors
// appended to it, the JSON document open for editing (tests break fields on purpose), saved as .glb.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace stipple::anim {

class GltfBuilder {
public:
    GltfBuilder();

    nlohmann::json doc;  // the glTF document; "buffers" is filled in by glb()

    // Appends `data` (4-byte aligned) as a new buffer view and accessor of `count` elements of `type`
    // ("SCALAR", "VEC3", "MAT4", ...); returns the accessor's index. Float accessors get min and max.
    int add_floats(const std::vector<float>& data, const std::string& type);
    int add_uint16(const std::vector<uint16_t>& data, const std::string& type);
    int add_int16(const std::vector<int16_t>& data, const std::string& type, bool normalized = false);
    int add_uint8(const std::vector<uint8_t>& data, const std::string& type, bool normalized = false);
    int add_uint32(const std::vector<uint32_t>& data, const std::string& type);

    // Appends `value` to the top-level array `array` ("nodes", "meshes", ...) and returns its index.
    int add(const std::string& array, nlohmann::json value);

    std::string glb() const;                    // the file's bytes
    void write(const std::string& path) const;  // saves glb(); throws stipple::Error naming the path

private:
    int add_accessor(const void* bytes, size_t byte_count, int component_type, const std::string& type, size_t count,
                     bool normalized);
    std::string bin_;
};

}  // namespace stipple::anim
