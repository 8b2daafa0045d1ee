#pragma once
// Reads glTF accessors for the mesh and animation loaders: any component type its use allows (normalized
// integers, and the integer positions and normals of KHR_mesh_quantization), sparse accessors and accessors
// without a buffer view (zeros), every byte range checked. A wrong type for the use is an error naming the
// field, e.g.
// "animations[0].samplers[1].output: accessor 7 is VEC3 of FLOAT, expected VEC4 of FLOAT or normalized ...".
#include <cstdint>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "mesh/load_mesh.hpp"

namespace stipple {

// Component types by use beyond FLOAT: positions may be any of these (KHR_mesh_quantization), plain (the
// node's transform scales them) or normalized; normals, and a morph target's position deltas, signed ones.
inline const std::vector<int> kGltfQuantizedTypes = {TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                                     TINYGLTF_COMPONENT_TYPE_SHORT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};
inline const std::vector<int> kGltfSignedTypes = {TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT};

class AccessorReader {
public:
    AccessorReader(const std::string& path, const tinygltf::Model& model, const LoadOptions& options)
        : path_(path), model_(model), options_(options) {}

    // count * components numbers. FLOAT is always accepted; the integer component types listed in
    // `normalized` are accepted when the accessor is marked normalized, and mapped to [0, 1] / [-1, 1].
    std::vector<float> floats(int index, int type, const std::vector<int>& normalized, const std::string& field) const {
        return numbers(index, type, {}, normalized, field);
    }
    // The same, and the integer types listed in `plain` when the accessor is not normalized (their values
    // as they are: KHR_mesh_quantization's positions, which the node's transform scales). A number that is
    // not finite is an error unless `allow_non_finite` (a broken normal, which loading recomputes).
    std::vector<float> numbers(int index, int type, const std::vector<int>& plain, const std::vector<int>& normalized,
                               const std::string& field, bool allow_non_finite = false) const;

    // count * components unsigned integers of one of `component_types` (not normalized), exactly.
    std::vector<uint32_t> uints(int index, int type, const std::vector<int>& component_types,
                                const std::string& field) const;

    // The accessor, after checking that it exists (no type check).
    const tinygltf::Accessor& get(int index, const std::string& field) const;

    [[noreturn]] void fail(const std::string& field, const std::string& problem) const;

private:
    // Every element's numbers as floats (integers normalized when asked), sparse entries applied.
    std::vector<float> read(int index, bool normalized, const std::string& field) const;
    // Where the accessor's elements are (nullptr without a buffer view), its element size and stride.
    struct Layout {
        const unsigned char* base = nullptr;
        size_t components = 0, element = 0, stride = 0;
    };
    Layout layout(int index, const std::string& where) const;
    // Refuses, in one line, zeros (an accessor without a buffer view) of more than a quarter of the machine's memory.
    void check_zeros_fit(const tinygltf::Accessor& a, const Layout& l, const std::string& where, size_t value_bytes) const;
    // Calls apply(first byte of an element, i) for each entry of a sparse accessor (none otherwise).
    template <class Apply>
    void for_each_sparse(int index, const Layout& layout, const std::string& where, Apply&& apply) const;
    void check_type(int index, int type, const std::vector<int>& plain, const std::vector<int>& normalized,
                    const std::string& field, bool allow_float) const;
    const unsigned char* view_bytes(int view, size_t offset, size_t element, size_t stride, size_t count,
                                    const std::string& where) const;

    const std::string& path_;
    const tinygltf::Model& model_;
    const LoadOptions& options_;
};

const char* component_type_name(int component_type);
const char* accessor_type_name(int type);

}  // namespace stipple
