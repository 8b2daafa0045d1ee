#pragma once
// Reads glTF accessors for the animation loader: any component type its use allows (normalized
// integers included), sparse accessors and accessors without a buffer view (zeros), every byte range
// checked. A wrong type for the use is an error naming the field, e.g.
// "animations[0].samplers[1].output: accessor 7 is VEC3 of FLOAT, expected VEC4 of FLOAT or normalized ...".
#include <cstdint>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "mesh/load_mesh.hpp"

namespace stipple::anim {

class AccessorReader {
public:
    AccessorReader(const std::string& path, const tinygltf::Model& model, const LoadOptions& options)
        : path_(path), model_(model), options_(options) {}

    // count * components numbers. FLOAT is always accepted; the integer component types listed in
    // `normalized` are accepted when the accessor is marked normalized, and mapped to [0, 1] / [-1, 1].
    std::vector<float> floats(int index, int type, const std::vector<int>& normalized, const std::string& field) const;

    // count * components unsigned integers of one of `component_types` (not normalized; at most 16 bits).
    std::vector<uint32_t> uints(int index, int type, const std::vector<int>& component_types,
                                const std::string& field) const;

    // The accessor, after checking that it exists (no type check).
    const tinygltf::Accessor& get(int index, const std::string& field) const;

    [[noreturn]] void fail(const std::string& field, const std::string& problem) const;

private:
    // Every element's numbers as floats (integers normalized when asked), sparse entries applied.
    std::vector<float> read(int index, bool normalized, const std::string& field) const;
    void check_type(int index, int type, const std::vector<int>& components, bool want_normalized,
                    const std::string& field) const;
    const unsigned char* view_bytes(int view, size_t offset, size_t element, size_t stride, size_t count,
                                    const std::string& where) const;

    const std::string& path_;
    const tinygltf::Model& model_;
    const LoadOptions& options_;
};

const char* component_type_name(int component_type);
const char* accessor_type_name(int type);

}  // namespace stipple::anim
