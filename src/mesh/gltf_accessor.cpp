#include "mesh/gltf_accessor.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>

#include "core/error.hpp"
#include "core/memory.hpp"

namespace stipple {

const char* component_type_name(int component_type) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
        case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
        default: return "an unknown component type";
    }
}

const char* accessor_type_name(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return "SCALAR";
        case TINYGLTF_TYPE_VEC2: return "VEC2";
        case TINYGLTF_TYPE_VEC3: return "VEC3";
        case TINYGLTF_TYPE_VEC4: return "VEC4";
        case TINYGLTF_TYPE_MAT2: return "MAT2";
        case TINYGLTF_TYPE_MAT3: return "MAT3";
        case TINYGLTF_TYPE_MAT4: return "MAT4";
        default: return "an unknown type";
    }
}

namespace {

template <class T>
double load_as_double(const unsigned char* p) {
    T v;
    std::memcpy(&v, p, sizeof v);
    return static_cast<double>(v);
}

double component(const unsigned char* p, int component_type) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: return load_as_double<int8_t>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return load_as_double<uint8_t>(p);
        case TINYGLTF_COMPONENT_TYPE_SHORT: return load_as_double<int16_t>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return load_as_double<uint16_t>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return load_as_double<uint32_t>(p);
        default: return load_as_double<float>(p);
    }
}

// glTF's mapping of normalized integers to floats.
double normalize(double v, int component_type) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: return std::max(v / 127.0, -1.0);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return v / 255.0;
        case TINYGLTF_COMPONENT_TYPE_SHORT: return std::max(v / 32767.0, -1.0);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return v / 65535.0;
        default: return v;
    }
}

// Elements of component type T to floats, normalized integers mapped as glTF says. The component type
// is dispatched once per accessor, not per number.
template <class T>
void convert(const unsigned char* base, size_t stride, size_t count, size_t n, bool normalized, int type, float* out) {
    if (std::is_same_v<T, float> && stride == n * sizeof(float)) {
        std::memcpy(out, base, count * stride);
        return;
    }
    for (size_t i = 0; i < count; ++i)
        for (size_t c = 0; c < n; ++c) {
            T v;
            std::memcpy(&v, base + i * stride + c * sizeof(T), sizeof v);
            out[i * n + c] = static_cast<float>(normalized ? normalize(static_cast<double>(v), type) : static_cast<double>(v));
        }
}

void convert_any(const unsigned char* base, size_t stride, size_t count, size_t n, bool normalized, int type, float* out) {
    if (count == 0) return;  // `out` may then be null, which memcpy may not be given even for no bytes
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: return convert<int8_t>(base, stride, count, n, normalized, type, out);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return convert<uint8_t>(base, stride, count, n, normalized, type, out);
        case TINYGLTF_COMPONENT_TYPE_SHORT: return convert<int16_t>(base, stride, count, n, normalized, type, out);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return convert<uint16_t>(base, stride, count, n, normalized, type, out);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return convert<uint32_t>(base, stride, count, n, normalized, type, out);
        default: return convert<float>(base, stride, count, n, false, type, out);
    }
}

}  // namespace

void AccessorReader::fail(const std::string& field, const std::string& problem) const {
    fail_file(path_, field + ": " + problem);
}

const tinygltf::Accessor& AccessorReader::get(int index, const std::string& field) const {
    if (index < 0 || static_cast<size_t>(index) >= model_.accessors.size())
        fail(field, "accessor " + std::to_string(index) + " does not exist");
    return model_.accessors[index];
}

void AccessorReader::check_type(int index, int type, const std::vector<int>& plain, const std::vector<int>& normalized,
                                const std::string& field, bool allow_float) const {
    const tinygltf::Accessor& a = get(index, field);
    auto listed = [&](const std::vector<int>& types) {
        return std::find(types.begin(), types.end(), a.componentType) != types.end();
    };
    const bool component_ok = a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT
                                  ? allow_float
                                  : (a.normalized ? listed(normalized) : listed(plain));
    if (a.type == type && component_ok) return;
    auto names = [](const std::vector<int>& types) {
        std::string out;
        for (size_t i = 0; i < types.size(); ++i) out += (i ? ", " : "") + std::string(component_type_name(types[i]));
        return out;
    };
    std::string expected = std::string(accessor_type_name(type)) + " of ";
    if (allow_float) expected += "FLOAT";
    if (!plain.empty()) expected += (allow_float ? ", " : "") + names(plain);
    if (!normalized.empty() && normalized != plain) expected += " or normalized " + names(normalized);
    fail(field, "accessor " + std::to_string(index) + " is " + accessor_type_name(a.type) + " of " +
                    (a.normalized ? "normalized " : "") + component_type_name(a.componentType) + ", expected " +
                    expected);
}

const unsigned char* AccessorReader::view_bytes(int view_index, size_t offset, size_t element, size_t stride,
                                                size_t count, const std::string& where) const {
    if (view_index < 0 || static_cast<size_t>(view_index) >= model_.bufferViews.size())
        fail_file(path_, where + ": buffer view " + std::to_string(view_index) + " does not exist");
    const tinygltf::BufferView& view = model_.bufferViews[view_index];
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model_.buffers.size())
        fail_file(path_, where + ": buffer view " + std::to_string(view_index) + " refers to a missing buffer");
    const size_t buffer_size = model_.buffers[view.buffer].data.size();
    if (view.byteOffset > buffer_size || view.byteLength > buffer_size - view.byteOffset)
        fail_file(path_, where + ": buffer view " + std::to_string(view_index) + " reaches past the end of its buffer");
    if (stride < element) fail_file(path_, where + ": byteStride is smaller than one element");
    // Overflow-safe form of: offset + (count - 1) * stride + element <= byteLength.
    if (count > 0 && (offset > view.byteLength || element > view.byteLength - offset ||
                      (count - 1) > (view.byteLength - offset - element) / stride))
        fail_file(path_, where + ": " + std::to_string(count) + " elements do not fit in buffer view " +
                             std::to_string(view_index));
    return model_.buffers[view.buffer].data.data() + view.byteOffset + offset;
}

AccessorReader::Layout AccessorReader::layout(int index, const std::string& where) const {
    const tinygltf::Accessor& a = model_.accessors[index];
    const int component_size = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType));
    const int components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
    if (component_size <= 0 || components <= 0) fail_file(path_, where + " has an invalid type");
    if (a.count > options_.max_elements)
        fail_file(path_, where + " claims " + std::to_string(a.count) + " elements, more than the limit of " +
                             std::to_string(options_.max_elements));
    Layout out;
    out.components = static_cast<size_t>(components);
    out.element = out.components * static_cast<size_t>(component_size);
    out.stride = out.element;
    if (a.bufferView >= 0) {
        const size_t view_stride = model_.bufferViews.size() > static_cast<size_t>(a.bufferView)
                                       ? model_.bufferViews[a.bufferView].byteStride
                                       : 0;
        out.stride = view_stride ? view_stride : out.element;
        out.base = view_bytes(a.bufferView, a.byteOffset, out.element, out.stride, a.count, where);
    }
    return out;
}

template <class Apply>
void AccessorReader::for_each_sparse(int index, const Layout& layout, const std::string& where, Apply&& apply) const {
    const tinygltf::Accessor& a = model_.accessors[index];
    if (!a.sparse.isSparse) return;
    const size_t count = a.sparse.count < 0 ? 0 : static_cast<size_t>(a.sparse.count);
    if (count > a.count)
        fail_file(path_, where + ": sparse count " + std::to_string(count) + " exceeds the accessor's count " +
                             std::to_string(a.count));
    const int index_type = a.sparse.indices.componentType;
    const int index_size = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(index_type));
    if (index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        fail_file(path_, where + ": sparse indices must be unsigned byte, short or int");
    const unsigned char* indices = view_bytes(a.sparse.indices.bufferView, size_t(std::max(a.sparse.indices.byteOffset, 0)),
                                              index_size, index_size, count, where + " sparse indices");
    const unsigned char* values = view_bytes(a.sparse.values.bufferView, size_t(std::max(a.sparse.values.byteOffset, 0)),
                                             layout.element, layout.element, count, where + " sparse values");
    for (size_t j = 0; j < count; ++j) {
        const double target = component(indices + j * index_size, index_type);
        if (target >= static_cast<double>(a.count))
            fail_file(path_, where + ": sparse index " + std::to_string(static_cast<uint64_t>(target)) +
                                 " is beyond the accessor's " + std::to_string(a.count) + " elements");
        apply(values + j * layout.element, static_cast<size_t>(target));
    }
}

// An accessor without a buffer view is zeros, as many as it says: a few bytes of file may ask gigabytes.
void AccessorReader::check_zeros_fit(const tinygltf::Accessor& a, const Layout& l, const std::string& where,
                                     size_t value_bytes) const {
    if (l.base != nullptr) return;  // its data is in the file, which fits (check_model_size)
    const uint64_t memory = physical_memory_bytes(), bytes = uint64_t(a.count) * l.components * value_bytes;
    if (memory > 0 && bytes > memory / 4)
        fail_file(path_, where + ": " + std::to_string(a.count) + " elements without a buffer view (zeros) would take " +
                             byte_size(bytes) + ", more than this machine's " + byte_size(memory) + " of memory allows");
}

std::vector<float> AccessorReader::read(int index, bool normalized, const std::string& field) const {
    const tinygltf::Accessor& a = get(index, field);
    const std::string where = field + " (accessor " + std::to_string(index) + ")";
    const Layout l = layout(index, where);
    const size_t n = l.components;
    check_zeros_fit(a, l, where, sizeof(float));
    std::vector<float> out(a.count * n, 0.0f);  // no buffer view: zeros (sparse entries may follow)
    if (l.base) convert_any(l.base, l.stride, a.count, n, normalized, a.componentType, out.data());
    for_each_sparse(index, l, where, [&](const unsigned char* value, size_t i) {
        convert_any(value, l.element, 1, n, normalized, a.componentType, &out[i * n]);
    });
    return out;
}

std::vector<float> AccessorReader::numbers(int index, int type, const std::vector<int>& plain,
                                           const std::vector<int>& normalized, const std::string& field,
                                           bool allow_non_finite) const {
    check_type(index, type, plain, normalized, field, true);
    const tinygltf::Accessor& a = model_.accessors[index];
    std::vector<float> out = read(index, a.normalized && a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT, field);
    for (size_t i = 0; i < out.size() && !allow_non_finite; ++i)
        if (!std::isfinite(out[i]))
            fail(field, "element " + std::to_string(i / tinygltf::GetNumComponentsInType(a.type)) + " is not finite");
    return out;
}

std::vector<uint32_t> AccessorReader::uints(int index, int type, const std::vector<int>& component_types,
                                            const std::string& field) const {
    // The normalized flag means nothing to an index: accepted either way, read as the integers stored.
    check_type(index, type, component_types, component_types, field, false);
    const tinygltf::Accessor& a = model_.accessors[index];
    const std::string where = field + " (accessor " + std::to_string(index) + ")";
    const Layout l = layout(index, where);
    const size_t n = l.components, size = l.element / n;
    check_zeros_fit(a, l, where, sizeof(uint32_t));
    std::vector<uint32_t> out(a.count * n, 0u);
    auto put = [&](const unsigned char* element, size_t i) {
        for (size_t c = 0; c < n; ++c) out[i * n + c] = static_cast<uint32_t>(component(element + c * size, a.componentType));
    };
    if (l.base)
        for (size_t i = 0; i < a.count; ++i) put(l.base + i * l.stride, i);
    for_each_sparse(index, l, where, put);
    return out;
}

}  // namespace stipple
