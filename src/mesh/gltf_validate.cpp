#include "mesh/gltf_validate.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>
#include <set>
#include <system_error>
#include <utility>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/printf_string.hpp"
#include "mesh/glb_container.hpp"
#include "mesh/gltf_extensions.hpp"
#include "mesh/gltf_meshopt.hpp"
#include "mesh/loader_util.hpp"

namespace stipple {

namespace {

using json = nlohmann::json;

// tinygltf copies "extras" and "extensions" values recursively: nesting is bounded so that no file
// can exhaust its stack. Real files nest a handful of levels.
constexpr size_t kMaxDepth = 64;

// The offending value, short: numbers as written (a float keeps a decimal point, so "3.0" is not
// mistaken for an integer), other types by name.
std::string got(const json& v) {
    switch (v.type()) {
        case json::value_t::number_integer: return std::to_string(v.get<int64_t>());
        case json::value_t::number_unsigned: return std::to_string(v.get<uint64_t>());
        case json::value_t::number_float: {
            const double d = v.get<double>();
            if (!std::isfinite(d)) return "a number beyond double range";
            char text[40];
            std::snprintf(text, sizeof text, "%.17g", d);
            std::string s = text;
            if (s.find_first_of(".e") == std::string::npos) s += ".0";
            return s;
        }
        case json::value_t::string: return "a string";
        case json::value_t::boolean: return v.get<bool>() ? "true" : "false";
        case json::value_t::null: return "null";
        case json::value_t::array: return "an array";
        case json::value_t::object: return "an object";
        default: return "a binary value";
    }
}

struct Collection {
    const char* key;
    const char* singular;
};
constexpr Collection kCollections[] = {
    {"accessors", "accessor"}, {"animations", "animation"}, {"buffers", "buffer"}, {"bufferViews", "buffer view"},
    {"cameras", "camera"},     {"images", "image"},         {"materials", "material"}, {"meshes", "mesh"},
    {"nodes", "node"},         {"samplers", "sampler"},     {"scenes", "scene"},       {"skins", "skin"},
    {"textures", "texture"}};

std::string percent_decoded(const std::string& uri) {
    std::string out;
    for (size_t i = 0; i < uri.size(); ++i) {
        const auto hex = [&](size_t at) { return at < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[at])); };
        if (uri[i] == '%' && hex(i + 1) && hex(i + 2)) {
            out += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

std::string shown(const std::string& text) { return quoted_excerpt(text, 64); }

class Checker {
public:
    Checker(const std::string& file, const json& doc, const GlbChunks* glb, const std::filesystem::path* base_dir)
        : file_(file), doc_(doc), glb_(glb), base_dir_(base_dir) {}

    void run() {
        check_version();
        check_depth_and_extensions();
        for (const Collection& c : kCollections) {
            const json* array = find(doc_, c.key);
            if (!array) continue;
            if (!array->is_array()) bad(c.key, "expected an array, got " + got(*array));
            for (size_t i = 0; i < array->size(); ++i) object((*array)[i], at(c.key, i));
        }
        each("buffers", [&](const json& b, const std::string& where, size_t i) { buffer(b, where, i); });
        each("bufferViews", [&](const json& v, const std::string& where, size_t) { buffer_view(v, where); });
        each("accessors", [&](const json& a, const std::string& where, size_t) { accessor(a, where); });
        each("meshes", [&](const json& m, const std::string& where, size_t) { mesh(m, where); });
        each("nodes", [&](const json& n, const std::string& where, size_t) { node(n, where); });
        each("scenes", [&](const json& s, const std::string& where, size_t) {
            name(s, where);
            if (const json* nodes = find(s, "nodes")) indices(*nodes, at(where, "nodes"), "nodes", false);
        });
        if (const json* scene = find(doc_, "scene")) index(*scene, "scene", "scenes");
        each("skins", [&](const json& s, const std::string& where, size_t) { skin(s, where); });
        each("animations", [&](const json& a, const std::string& where, size_t) { animation(a, where); });
    }

private:
    [[noreturn]] void bad(const std::string& where, const std::string& problem) const {
        fail_file(file_, where + ": " + problem);
    }
    static const json* find(const json& object, const char* key) {
        const auto it = object.find(key);
        return it == object.end() ? nullptr : &*it;
    }
    static std::string at(const std::string& where, const char* key) { return where.empty() ? key : where + "." + key; }
    static std::string at(const std::string& where, size_t i) { return where + "[" + std::to_string(i) + "]"; }

    template <class F>
    void each(const char* key, F&& check) {
        if (const json* array = find(doc_, key))
            for (size_t i = 0; i < array->size(); ++i) check((*array)[i], at(key, i), i);
    }

    const json& object(const json& v, const std::string& where) const {
        if (!v.is_object()) bad(where, "expected an object, got " + got(v));
        return v;
    }
    const json& required(const json& object, const std::string& where, const char* key) const {
        const json* v = find(object, key);
        if (!v) bad(at(where, key), "missing (it is required)");
        return *v;
    }
    const json& array(const json& v, const std::string& where, bool non_empty) const {
        if (!v.is_array() || (non_empty && v.empty()))
            bad(where, std::string("expected ") + (non_empty ? "a non-empty array" : "an array") + ", got " +
                           (v.is_array() ? "an empty one" : got(v)));
        return v;
    }
    const std::string& string(const json& v, const std::string& where) const {
        if (!v.is_string()) bad(where, "expected a string, got " + got(v));
        return v.get_ref<const std::string&>();
    }
    void name(const json& object, const std::string& where) const {
        if (const json* n = find(object, "name")) string(*n, at(where, "name"));
    }
    void one_of(const json& v, const std::string& where, std::initializer_list<const char*> allowed) const {
        const std::string& s = string(v, where);
        std::string list;
        for (const char* a : allowed) {
            if (s == a) return;
            list += (list.empty() ? "" : ", ") + std::string(a);
        }
        bad(where, "expected one of " + list + ", got " + shown(s));
    }
    // A JSON integer (not 3.0) within [min, max]; `expected` words the expectation.
    uint64_t integer(const json& v, const std::string& where, uint64_t min, uint64_t max, const std::string& expected) const {
        const bool integral = v.is_number_unsigned() || (v.is_number_integer() && v.get<int64_t>() >= 0);
        const uint64_t value = !integral ? 0 : v.is_number_unsigned() ? v.get<uint64_t>() : static_cast<uint64_t>(v.get<int64_t>());
        if (!integral || value < min || value > max) bad(where, "expected " + expected + ", got " + got(v));
        return value;
    }
    uint64_t count(const json& v, const std::string& where) const {
        return integer(v, where, 0, UINT64_MAX, "a non-negative integer");
    }
    uint64_t optional_count(const json& object, const std::string& where, const char* key) const {
        const json* v = find(object, key);
        return v ? count(*v, at(where, key)) : 0;
    }
    size_t size_of(const char* collection) const {
        const json* array = find(doc_, collection);
        return array ? array->size() : 0;
    }
    // An index into a top-level collection, which must exist.
    size_t index(const json& v, const std::string& where, const char* collection) const {
        const char* singular = collection;
        for (const Collection& c : kCollections)
            if (std::string_view(c.key) == collection) singular = c.singular;
        const bool vowel = std::string_view("aeiou").find(singular[0]) != std::string_view::npos;
        const uint64_t i = integer(v, where, 0, UINT64_MAX, std::string("the index of ") + (vowel ? "an " : "a ") + singular);
        const size_t n = size_of(collection);
        if (i >= n)
            bad(where, std::string(singular) + " " + std::to_string(i) + " does not exist (the file has " +
                           (n ? std::to_string(n) + " of them" : std::string("none")) + ")");
        return static_cast<size_t>(i);
    }
    void optional_index(const json& object, const std::string& where, const char* key, const char* collection) const {
        if (const json* v = find(object, key)) index(*v, at(where, key), collection);
    }
    void indices(const json& v, const std::string& where, const char* collection, bool non_empty) const {
        array(v, where, non_empty);
        for (size_t i = 0; i < v.size(); ++i) index(v[i], at(where, i), collection);
    }
    // An array of finite numbers, of exactly `size` (0: any number of them).
    void numbers(const json& v, const std::string& where, size_t size) const {
        array(v, where, false);
        if (size && v.size() != size)
            bad(where, "expected " + std::to_string(size) + " numbers, got " + std::to_string(v.size()));
        for (size_t i = 0; i < v.size(); ++i)
            if (!v[i].is_number() || !std::isfinite(v[i].get<double>()))
                bad(at(where, i), "expected a finite number, got " + got(v[i]));
    }
    void optional_numbers(const json& object, const std::string& where, const char* key, size_t size) const {
        if (const json* v = find(object, key)) numbers(*v, at(where, key), size);
    }

    void check_version() {
        const json* asset = find(doc_, "asset");
        const json* version = asset && asset->is_object() ? find(*asset, "version") : nullptr;
        bool v1 = false;
        if (version && version->is_string()) v1 = version->get_ref<const std::string&>().rfind("1.", 0) == 0;
        else if (version && version->is_number()) v1 = version->get<double>() == 1.0;
        // glTF 1.0 kept its objects in dictionaries, and its binary form was an extension.
        if (!version)
            for (const Collection& c : kCollections)
                if (const json* v = find(doc_, c.key); v && v->is_object()) v1 = true;
        if (const json* used = find(doc_, "extensionsUsed"); used && used->is_array())
            for (const json& e : *used) v1 = v1 || (e.is_string() && e.get_ref<const std::string&>() == "KHR_binary_glTF");
        if (v1) fail_file(file_, "glTF 1.0 is not supported (convert to glTF 2.0)");

        if (!asset) bad("asset", "missing (every glTF 2.0 file has one)");
        object(*asset, "asset");
        const std::string& text = string(required(*asset, "asset", "version"), "asset.version");
        if (text.rfind("2.", 0) != 0) bad("asset.version", "glTF " + shown(text) + " is not supported (only 2.x)");
        if (const json* min = find(*asset, "minVersion"); min && string(*min, "asset.minVersion") != "2.0")
            bad("asset.minVersion", "the file needs glTF " + shown(min->get<std::string>()) + "; only 2.0 is supported");
    }

    // One walk over the whole document, without recursion: nesting depth, and the extensions in use.
    void check_depth_and_extensions() {
        std::set<std::string> used;
        std::vector<std::pair<const json*, size_t>> stack{{&doc_, 1}};
        while (!stack.empty()) {
            const auto [v, depth] = stack.back();
            stack.pop_back();
            if (depth > kMaxDepth) fail_file(file_, "JSON nested more than " + std::to_string(kMaxDepth) + " levels deep");
            if (v->is_object()) {
                for (auto it = v->begin(); it != v->end(); ++it) {
                    if (it.key() == "extensions" && it->is_object())
                        for (auto e = it->begin(); e != it->end(); ++e) used.insert(e.key());
                    stack.emplace_back(&*it, depth + 1);
                }
            } else if (v->is_array()) {
                for (const json& e : *v) stack.emplace_back(&e, depth + 1);
            }
        }
        check_gltf_extensions(file_, doc_, used);
    }

    // What a buffer's data can hold at most: the BIN chunk, the decoded data: URI, the external file.
    // nullopt for a placeholder buffer, which has none.
    std::optional<uint64_t> available(const json& b, const std::string& where, size_t i, std::string& holder) const {
        const json* uri = find(b, "uri");
        if (is_placeholder_buffer(b, i, glb_ != nullptr)) {
            // No data of its own: only EXT_meshopt_compression's views, decoded into it, may use it.
            if (!uses_meshopt())
                bad(at(where, "uri"), "missing (only the first buffer of a .glb, or a placeholder of EXT_meshopt_compression, "
                                      "may leave it out)");
            return std::nullopt;
        }
        if (!uri) {
            if (!glb_->has_bin) bad(where, "refers to the BIN chunk, but the file has none");
            holder = "the BIN chunk";
            return glb_->bin.size();
        }
        const std::string& u = string(*uri, at(where, "uri"));
        if (u.rfind("data:", 0) == 0) {
            const size_t comma = u.find(',');
            if (comma == std::string::npos) bad(at(where, "uri"), "a data: URI without ','");
            // The types glTF gives a buffer, in base64, are all tinygltf decodes (it takes any other for a file name).
            const std::string type = u.substr(0, comma);
            if (type != "data:application/octet-stream;base64" && type != "data:application/gltf-buffer;base64")
                bad(at(where, "uri"), "a buffer's data: URI must be application/octet-stream or application/gltf-buffer in "
                                      "base64, got " + shown(type));
            holder = "its data: URI";
            // tinygltf's own message for another character quotes the whole URI, and a length check before it
            // read as a short buffer.
            // Trailing whitespace is let through, as tinygltf decodes up to it.
            const size_t data_end = u.find_last_not_of(" \t\r\n") + 1;
            size_t bad_char = u.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/=", comma + 1);
            if (bad_char >= data_end) bad_char = std::string::npos;
            if (bad_char != std::string::npos)
                bad(at(where, "uri"), "its data: URI is not base64 (" + shown(u.substr(bad_char, 1)) + " at character " +
                                          std::to_string(bad_char - comma) + " of the data)");
            const uint64_t payload = u.size() - comma - 1;
            return payload / 4 * 3 + (payload % 4 ? 3 : 0);
        }
        if (!base_dir_) bad(at(where, "uri"), "external file " + shown(u) + " cannot be read: the model was not loaded from a file");
        const std::filesystem::path path = external_buffer_path(*base_dir_, u);
        std::error_code ec;
        const auto status = std::filesystem::status(path, ec);
        if (!std::filesystem::exists(status)) bad(at(where, "uri"), shown(u) + " not found (looked for " + shown(path.string()) + ")");
        if (!std::filesystem::is_regular_file(status)) bad(at(where, "uri"), shown(u) + " is not a regular file");
        holder = shown(u);
        return std::filesystem::file_size(path, ec);
    }

    void buffer(const json& b, const std::string& where, size_t i) {
        name(b, where);
        // glTF's minimum, and tinygltf's: it refuses an empty external file or data: URI.
        const uint64_t length = integer(required(b, where, "byteLength"), at(where, "byteLength"), 1, UINT64_MAX, "a positive integer");
        std::string holder;
        if (const std::optional<uint64_t> bytes = available(b, where, i, holder); bytes && length > *bytes)
            bad(at(where, "byteLength"), std::to_string(length) + " bytes, but " + holder + " holds only " + std::to_string(*bytes));
        buffer_lengths_.push_back(length);
        if (is_placeholder_buffer(b, i, glb_ != nullptr)) placeholders_.insert(i);
    }

    void buffer_view(const json& v, const std::string& where) {
        name(v, where);
        const size_t b = index(required(v, where, "buffer"), at(where, "buffer"), "buffers");
        const uint64_t offset = optional_count(v, where, "byteOffset");
        const uint64_t length = integer(required(v, where, "byteLength"), at(where, "byteLength"), 1, UINT64_MAX, "a positive integer");
        uint64_t stride = 0;
        if (const json* s = find(v, "byteStride")) stride = integer(*s, at(where, "byteStride"), 4, 252, "an integer from 4 to 252");
        if (const json* t = find(v, "target")) count(*t, at(where, "target"));
        if (offset > buffer_lengths_[b] || length > buffer_lengths_[b] - offset)
            bad(where, "byteOffset " + std::to_string(offset) + " + byteLength " + std::to_string(length) +
                           " reaches past the end of buffer " + std::to_string(b) + " (" + std::to_string(buffer_lengths_[b]) + " bytes)");
        const json* extensions = find(v, "extensions");
        const json* meshopt = extensions && extensions->is_object() ? find(*extensions, "EXT_meshopt_compression") : nullptr;
        if (meshopt) compressed_view(*meshopt, at(at(where, "extensions"), "EXT_meshopt_compression"), length, stride);
        else if (placeholders_.count(b))
            bad(at(where, "buffer"), "buffer " + std::to_string(b) + " holds no data (a placeholder of EXT_meshopt_compression), "
                                     "but this view is not compressed");
        views_.push_back({length, stride});
    }

    // EXT_meshopt_compression on a buffer view of `length` bytes (`view_stride`: its byteStride, 0 if none):
    // where the compressed bytes are, and what they decode to, count elements of byteStride bytes that fill
    // the view exactly. The strides, modes and filters are those the extension allows.
    void compressed_view(const json& e, const std::string& where, uint64_t length, uint64_t view_stride) const {
        object(e, where);
        const size_t b = index(required(e, where, "buffer"), at(where, "buffer"), "buffers");
        if (placeholders_.count(b)) bad(at(where, "buffer"), "buffer " + std::to_string(b) + " holds no data (it has no uri)");
        const uint64_t offset = optional_count(e, where, "byteOffset");
        const uint64_t source = integer(required(e, where, "byteLength"), at(where, "byteLength"), 1, UINT64_MAX, "a positive integer");
        if (offset > buffer_lengths_[b] || source > buffer_lengths_[b] - offset)
            bad(where, "byteOffset " + std::to_string(offset) + " + byteLength " + std::to_string(source) +
                           " reaches past the end of buffer " + std::to_string(b) + " (" + std::to_string(buffer_lengths_[b]) + " bytes)");
        one_of(required(e, where, "mode"), at(where, "mode"), {"ATTRIBUTES", "TRIANGLES", "INDICES"});
        const std::string& mode = e["mode"].get_ref<const std::string&>();
        std::string filter = "NONE";
        if (const json* f = find(e, "filter")) {
            one_of(*f, at(where, "filter"), {"NONE", "OCTAHEDRAL", "QUATERNION", "EXPONENTIAL"});
            filter = f->get<std::string>();
        }
        const uint64_t stride = integer(required(e, where, "byteStride"), at(where, "byteStride"), 1, 256, "an integer from 1 to 256");
        if (mode == "ATTRIBUTES" && stride % 4 != 0) bad(at(where, "byteStride"), "expected a multiple of 4 for ATTRIBUTES, got " + std::to_string(stride));
        if (mode != "ATTRIBUTES" && stride != 2 && stride != 4)
            bad(at(where, "byteStride"), "expected 2 or 4 for " + mode + ", got " + std::to_string(stride));
        if (mode != "ATTRIBUTES" && filter != "NONE") bad(at(where, "filter"), filter + " applies to ATTRIBUTES only, not " + mode);
        if ((filter == "OCTAHEDRAL" && stride != 4 && stride != 8) || (filter == "QUATERNION" && stride != 8))
            bad(at(where, "filter"), filter + " does not decode elements of " + std::to_string(stride) + " bytes");
        const uint64_t n = integer(required(e, where, "count"), at(where, "count"), 1, UINT64_MAX, "a positive integer");
        if (mode == "TRIANGLES" && n % 3 != 0) bad(at(where, "count"), "expected a multiple of 3 for TRIANGLES, got " + std::to_string(n));
        if (view_stride && view_stride != stride)
            bad(at(where, "byteStride"), std::to_string(stride) + ", but the buffer view's byteStride is " + std::to_string(view_stride));
        if (n > length / stride || n * stride != length)
            bad(at(where, "count"), std::to_string(n) + " elements of " + std::to_string(stride) + " bytes do not fill the buffer view's " +
                                        std::to_string(length) + " bytes");
    }
    bool uses(const char* extension) const {
        const json* used = find(doc_, "extensionsUsed");
        if (!used || !used->is_array()) return false;
        for (const json& e : *used)
            if (e.is_string() && e.get_ref<const std::string&>() == extension) return true;
        return false;
    }
    bool uses_meshopt() const { return uses("EXT_meshopt_compression"); }

    // `count` elements of `element` bytes, `stride` apart from `offset`, must lie in the buffer view.
    void fits(const std::string& where, size_t view, uint64_t offset, uint64_t n, uint64_t element, uint64_t stride) const {
        const uint64_t length = views_[view].length;
        if (n == 0) return;
        if (offset > length || element > length - offset || (n - 1) > (length - offset - element) / stride)
            bad(where, std::to_string(n) + " elements of " + std::to_string(element) + " bytes (" + std::to_string(stride) +
                           " apart) from byteOffset " + std::to_string(offset) + " do not fit in buffer view " +
                           std::to_string(view) + " (" + std::to_string(length) + " bytes)");
    }

    static uint64_t component_size(uint64_t type) { return type == 5126 || type == 5125 ? 4 : type == 5122 || type == 5123 ? 2 : 1; }
    uint64_t component_type(const json& v, const std::string& where, bool index_types) const {
        const uint64_t t = integer(v, where, 0, UINT64_MAX, "a component type");
        const bool ok = index_types ? (t == 5121 || t == 5123 || t == 5125) : (t >= 5120 && t <= 5126 && t != 5124);
        if (!ok) bad(where, std::string("expected a component type (") + (index_types ? "5121, 5123 or 5125" : "5120, 5121, 5122, 5123, 5125 or 5126") + "), got " + got(v));
        return t;
    }

    void accessor(const json& a, const std::string& where) {
        name(a, where);
        const uint64_t type_size = component_size(component_type(required(a, where, "componentType"), at(where, "componentType"), false));
        const uint64_t n = count(required(a, where, "count"), at(where, "count"));
        one_of(required(a, where, "type"), at(where, "type"), {"SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4"});
        const std::string& type = a["type"].get_ref<const std::string&>();
        const uint64_t components = type == "SCALAR" ? 1 : type[0] == 'V' ? type[3] - '0' : (type[3] - '0') * (type[3] - '0');
        const uint64_t offset = optional_count(a, where, "byteOffset");
        // glTF asks it (and a view's stride) in whole components: data read from elsewhere is garbage.
        if (offset % type_size != 0)
            bad(at(where, "byteOffset"), std::to_string(offset) + " is not a multiple of its component's " + std::to_string(type_size) + " bytes");
        if (const json* normalized = find(a, "normalized"); normalized && !normalized->is_boolean())
            bad(at(where, "normalized"), "expected true or false, got " + got(*normalized));
        optional_numbers(a, where, "min", 0);
        optional_numbers(a, where, "max", 0);
        if (const json* view = find(a, "bufferView")) {
            const size_t v = index(*view, at(where, "bufferView"), "bufferViews");
            const uint64_t element = type_size * components;
            fits(at(where, "count"), v, offset, n, element, views_[v].stride ? views_[v].stride : element);
        }
        if (const json* sparse = find(a, "sparse")) {
            const std::string s = at(where, "sparse");
            object(*sparse, s);
            const uint64_t k = integer(required(*sparse, s, "count"), at(s, "count"), 1, UINT64_MAX, "a positive integer");
            const std::string si = at(s, "indices"), sv = at(s, "values");
            const json& ind = object(required(*sparse, s, "indices"), si);
            const json& val = object(required(*sparse, s, "values"), sv);
            const size_t iv = index(required(ind, si, "bufferView"), at(si, "bufferView"), "bufferViews");
            const uint64_t index_size = component_size(component_type(required(ind, si, "componentType"), at(si, "componentType"), true));
            fits(at(s, "count"), iv, optional_count(ind, si, "byteOffset"), k, index_size, index_size);
            const size_t vv = index(required(val, sv, "bufferView"), at(sv, "bufferView"), "bufferViews");
            fits(at(s, "count"), vv, optional_count(val, sv, "byteOffset"), k, type_size * components, type_size * components);
        }
    }

    // attribute name -> accessor index (primitive attributes and morph targets).
    void attributes(const json& v, const std::string& where) const {
        object(v, where);
        for (auto it = v.begin(); it != v.end(); ++it) index(*it, where + "." + one_line(it.key()), "accessors");
    }

    void mesh(const json& m, const std::string& where) {
        name(m, where);
        const std::string p = at(where, "primitives");
        const json& primitives = array(required(m, where, "primitives"), p, true);
        for (size_t i = 0; i < primitives.size(); ++i) {
            const std::string w = at(p, i);
            const json& prim = object(primitives[i], w);
            attributes(required(prim, w, "attributes"), at(w, "attributes"));
            optional_index(prim, w, "indices", "accessors");
            optional_index(prim, w, "material", "materials");
            if (const json* mode = find(prim, "mode")) integer(*mode, at(w, "mode"), 0, 6, "a primitive mode from 0 to 6");
            if (const json* extensions = find(prim, "extensions"); extensions && extensions->is_object())
                if (const json* draco = find(*extensions, "KHR_draco_mesh_compression"))
                    draco_primitive(*draco, at(at(w, "extensions"), "KHR_draco_mesh_compression"));
            if (const json* targets = find(prim, "targets")) {
                array(*targets, at(w, "targets"), false);
                for (size_t t = 0; t < targets->size(); ++t) attributes((*targets)[t], at(at(w, "targets"), t));
            }
        }
        optional_numbers(m, where, "weights", 0);
    }

    // KHR_draco_mesh_compression on a primitive: the buffer view of its bitstream, and the bitstream's
    // attribute id for each attribute it holds (gltf_draco.hpp decodes it).
    void draco_primitive(const json& e, const std::string& where) const {
        object(e, where);
        index(required(e, where, "bufferView"), at(where, "bufferView"), "bufferViews");
        const std::string aw = at(where, "attributes");
        const json& attributes = object(required(e, where, "attributes"), aw);
        for (auto it = attributes.begin(); it != attributes.end(); ++it)
            integer(*it, aw + "." + one_line(it.key()), 0, UINT32_MAX, "a Draco attribute id");
    }

    void node(const json& n, const std::string& where) {
        name(n, where);
        optional_index(n, where, "camera", "cameras");
        optional_index(n, where, "mesh", "meshes");
        optional_index(n, where, "skin", "skins");
        if (const json* children = find(n, "children")) indices(*children, at(where, "children"), "nodes", false);
        optional_numbers(n, where, "matrix", 16);
        optional_numbers(n, where, "translation", 3);
        optional_numbers(n, where, "rotation", 4);
        optional_numbers(n, where, "scale", 3);
        optional_numbers(n, where, "weights", 0);
        node_transform(n, where);
        if (const json* extensions = find(n, "extensions"); extensions && extensions->is_object())
            if (const json* instancing = find(*extensions, "EXT_mesh_gpu_instancing"))
                gpu_instancing(*instancing, at(at(where, "extensions"), "EXT_mesh_gpu_instancing"), n);
    }

    // What glTF requires of a node's transform, refused here as the same faults are elsewhere (an inverse bind
    // matrix's fourth row, a rotation key of no length); each was drawn without a word: a fourth row other than
    // (0, 0, 0, 1) was ignored, a matrix beside translation, rotation or scale won over them, and a rotation
    // of no length was taken for no rotation. Checked loosely, as exporters round.
    void node_transform(const json& n, const std::string& where) const {
        const json* matrix = find(n, "matrix");
        std::string trs;
        for (const char* key : {"translation", "rotation", "scale"})
            if (find(n, key)) trs += (trs.empty() ? "" : ", ") + std::string(key);
        if (matrix && !trs.empty())
            bad(where, "has both a matrix and " + trs + "; glTF allows a matrix or translation, rotation and scale, not both");
        if (matrix) affine_matrix(*matrix, at(where, "matrix"));
        if (const json* rotation = find(n, "rotation")) unit_quaternion(*rotation, at(where, "rotation"));
    }
    // Column-major: the fourth row is elements 3, 7, 11 and 15.
    void affine_matrix(const json& m, const std::string& where) const {
        const auto off = [&](size_t i, double want) { return !(std::abs(m[i].get<double>() - want) <= 1e-3); };
        if (off(3, 0.0) || off(7, 0.0) || off(11, 0.0) || off(15, 1.0))
            bad(where, "its fourth row (elements 3, 7, 11, 15) is (" + got(m[3]) + ", " + got(m[7]) + ", " + got(m[11]) + ", " +
                           got(m[15]) + "); glTF requires (0, 0, 0, 1)");
    }
    void unit_quaternion(const json& q, const std::string& where) const {
        double squares = 0.0;
        for (const json& c : q) squares += c.get<double>() * c.get<double>();
        const double length = std::sqrt(squares);
        if (!(std::abs(length - 1.0) <= 1e-2))
            bad(where, "(" + got(q[0]) + ", " + got(q[1]) + ", " + got(q[2]) + ", " + got(q[3]) + ") has length " +
                           printf_string("%g", length) + "; glTF requires a unit quaternion");
    }

    // EXT_mesh_gpu_instancing on a node: its attributes name accessors (gltf_instancing.cpp reads them),
    // and it instances the node's mesh, so the node needs one.
    void gpu_instancing(const json& e, const std::string& where, const json& node) const {
        object(e, where);
        attributes(required(e, where, "attributes"), at(where, "attributes"));
        if (!find(node, "mesh")) bad(where, "the node has no mesh to instance");
    }

    void skin(const json& s, const std::string& where) {
        name(s, where);
        indices(required(s, where, "joints"), at(where, "joints"), "nodes", true);
        optional_index(s, where, "skeleton", "nodes");
        optional_index(s, where, "inverseBindMatrices", "accessors");
    }

    void animation(const json& a, const std::string& where) {
        name(a, where);
        const std::string sw = at(where, "samplers"), cw = at(where, "channels");
        const json& samplers = array(required(a, where, "samplers"), sw, true);
        for (size_t i = 0; i < samplers.size(); ++i) {
            const std::string w = at(sw, i);
            const json& s = object(samplers[i], w);
            index(required(s, w, "input"), at(w, "input"), "accessors");
            index(required(s, w, "output"), at(w, "output"), "accessors");
            if (const json* interpolation = find(s, "interpolation"))
                one_of(*interpolation, at(w, "interpolation"), {"LINEAR", "STEP", "CUBICSPLINE"});
        }
        const json& channels = array(required(a, where, "channels"), cw, true);
        for (size_t i = 0; i < channels.size(); ++i) {
            const std::string w = at(cw, i);
            const json& c = object(channels[i], w);
            const uint64_t s = integer(required(c, w, "sampler"), at(w, "sampler"), 0, UINT64_MAX, "the index of a sampler");
            if (s >= samplers.size())
                bad(at(w, "sampler"), "sampler " + std::to_string(s) + " does not exist (the animation has " +
                                          std::to_string(samplers.size()) + ")");
            const std::string tw = at(w, "target");
            const json& target = object(required(c, w, "target"), tw);
            optional_index(target, tw, "node", "nodes");
            // "pointer" is KHR_animation_pointer's (a channel of properties, not of a node): such channels are
            // skipped, as the extension's other readers do when they do not require it (a file that requires
            // it is refused with the extensions).
            if (uses("KHR_animation_pointer"))
                one_of(required(target, tw, "path"), at(tw, "path"), {"translation", "rotation", "scale", "weights", "pointer"});
            else
                one_of(required(target, tw, "path"), at(tw, "path"), {"translation", "rotation", "scale", "weights"});
        }
    }

    struct View {
        uint64_t length;
        uint64_t stride;  // 0: tightly packed
    };

    const std::string& file_;
    const json& doc_;
    const GlbChunks* glb_;
    const std::filesystem::path* base_dir_;
    std::vector<uint64_t> buffer_lengths_;
    std::set<size_t> placeholders_;  // buffers with no data, for EXT_meshopt_compression's views
    std::vector<View> views_;
};

}  // namespace

std::filesystem::path external_buffer_path(const std::filesystem::path& base_dir, const std::string& uri) {
    return base_dir / percent_decoded(uri);
}

json validate_gltf(const std::string& name, std::string_view bytes, bool binary, const std::filesystem::path* base_dir) {
    GlbChunks glb;
    if (binary) glb = split_glb(name, bytes);
    const std::string_view text = binary ? glb.json : bytes;
    json doc;
    try {
        doc = json::parse(text.begin(), text.end());
    } catch (const json::exception& e) {
        std::string what = e.what();
        if (const size_t bracket = what.find("] "); what.rfind("[json.exception", 0) == 0 && bracket != std::string::npos)
            what.erase(0, bracket + 2);
        // What it last read can be a data: URI of megabytes: its first characters say where.
        if (const size_t read = what.find("; last read: "); read != std::string::npos)
            what = what.substr(0, read) + "; last read: " + excerpt(what.substr(read + 13), 60);
        fail_file(name, "not valid JSON: " + excerpt(one_line(what), 240));
    }
    if (!doc.is_object()) fail_file(name, "expected a JSON object at the top level, got " + got(doc));
    Checker(name, doc, binary ? &glb : nullptr, base_dir).run();
    return doc;
}

}  // namespace stipple
