// glTF 2.0 (.gltf with external or data: buffers, and .glb) through tinygltf, after gltf_validate has
// checked the JSON's fields. tinygltf parses the JSON and loads the buffers; what points into those
// buffers (accessors, buffer views, indices, node references) is checked again here as it is used.
#include <tiny_gltf.h>  // the implementation lives in Debian's libtinygltf, so no TINYGLTF_IMPLEMENTATION

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "core/error.hpp"
#include "mesh/load_mesh.hpp"
#include "mesh/gltf_validate.hpp"
#include "mesh/loader_util.hpp"

namespace stipple {

namespace {

// Images play no part in stippling: skip decoding them (and any failure to).
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
    return true;
}

const char* mode_name(int mode) {
    switch (mode) {
        case TINYGLTF_MODE_POINTS: return "POINTS";
        case TINYGLTF_MODE_LINE: return "LINES";
        case TINYGLTF_MODE_LINE_LOOP: return "LINE_LOOP";
        case TINYGLTF_MODE_LINE_STRIP: return "LINE_STRIP";
        default: return "unknown";
    }
}

// Elements of one accessor, every one of them inside its buffer.
struct Span {
    const unsigned char* data = nullptr;
    size_t stride = 0;
    size_t count = 0;
    const unsigned char* at(size_t i) const { return data + i * stride; }
};

class Loader {
public:
    Loader(const std::string& path, const tinygltf::Model& model, const LoadOptions& options)
        : path_(path), model_(model), options_(options) {}

    Mesh run() {
        mesh_.source = path_;
        if (model_.scenes.empty()) {
            // No scene to say what is shown: every mesh once, untransformed.
            for (size_t m = 0; m < model_.meshes.size(); ++m) add_mesh(static_cast<int>(m), glm::dmat4(1.0));
        } else {
            const int scene = model_.defaultScene >= 0 ? model_.defaultScene : 0;
            if (static_cast<size_t>(scene) >= model_.scenes.size())
                fail_file(path_, "default scene " + std::to_string(scene) + " does not exist");
            add_scene(model_.scenes[scene]);
        }
        // Points and lines are skipped with a warning; with nothing else, the one line is the error's.
        if (mesh_.indices.empty() && !skipped_.empty())
            fail_file(path_, "the model has no triangles, only " + skipped_.front() +
                                 (skipped_.size() > 1 ? " and " + std::to_string(skipped_.size() - 1) + " more like it" : "") +
                                 ": only triangles are drawn");
        for (const std::string& what : skipped_)
            std::fprintf(stderr, "%s: warning: skipping %s: only triangles are drawn\n", path_.c_str(), what.c_str());
        return std::move(mesh_);
    }

private:
    void add_scene(const tinygltf::Scene& scene) {
        // Iterative, so that a deep hierarchy cannot overflow the stack. glTF nodes form a forest,
        // so a node reached twice means a cycle or a shared child: refused, as it could loop.
        std::vector<char> seen(model_.nodes.size(), 0);
        std::vector<std::pair<int, glm::dmat4>> stack;
        for (auto it = scene.nodes.rbegin(); it != scene.nodes.rend(); ++it) stack.emplace_back(*it, glm::dmat4(1.0));
        while (!stack.empty()) {
            const auto [index, parent] = stack.back();
            stack.pop_back();
            if (index < 0 || static_cast<size_t>(index) >= model_.nodes.size())
                fail_file(path_, "node " + std::to_string(index) + " does not exist");
            if (seen[index]) fail_file(path_, "node " + std::to_string(index) + " is reached twice (the node hierarchy must be a tree)");
            seen[index] = 1;
            const tinygltf::Node& node = model_.nodes[index];
            const glm::dmat4 world = parent * local_transform(node, index);
            if (node.mesh >= 0) add_mesh(node.mesh, world);
            for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) stack.emplace_back(*it, world);
        }
    }

    glm::dmat4 local_transform(const tinygltf::Node& node, int index) const {
        const std::string where = "node " + std::to_string(index) + ": ";
        if (!node.matrix.empty()) {
            if (node.matrix.size() != 16) fail_file(path_, where + "matrix must have 16 numbers");
            return glm::make_mat4(node.matrix.data());  // both glTF and glm are column-major
        }
        glm::dmat4 m(1.0);
        if (!node.translation.empty()) {
            if (node.translation.size() != 3) fail_file(path_, where + "translation must have 3 numbers");
            m[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
        }
        if (!node.rotation.empty()) {
            if (node.rotation.size() != 4) fail_file(path_, where + "rotation must have 4 numbers");
            const auto& r = node.rotation;  // glTF stores x, y, z, w
            m = m * glm::mat4_cast(glm::normalize(glm::dquat(r[3], r[0], r[1], r[2])));
        }
        if (!node.scale.empty()) {
            if (node.scale.size() != 3) fail_file(path_, where + "scale must have 3 numbers");
            m = m * glm::scale(glm::dmat4(1.0), glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
        }
        return m;
    }

    void add_mesh(int index, const glm::dmat4& world) {
        if (index < 0 || static_cast<size_t>(index) >= model_.meshes.size())
            fail_file(path_, "mesh " + std::to_string(index) + " does not exist");
        const tinygltf::Mesh& m = model_.meshes[index];
        const std::string name = m.name.empty() ? "mesh " + std::to_string(index) : "mesh '" + one_line(m.name) + "'";
        for (size_t p = 0; p < m.primitives.size(); ++p)
            add_primitive(m.primitives[p], name + " primitive " + std::to_string(p), world);
    }

    Span accessor(int index, int component_type, int type, const std::string& what) const {
        if (index < 0 || static_cast<size_t>(index) >= model_.accessors.size())
            fail_file(path_, what + ": accessor " + std::to_string(index) + " does not exist");
        const tinygltf::Accessor& a = model_.accessors[index];
        const std::string where = what + ": accessor " + std::to_string(index);
        if (a.sparse.isSparse) fail_file(path_, where + " is sparse, which is not supported");
        if (a.type != type || (component_type >= 0 && a.componentType != component_type))
            fail_file(path_, where + " has the wrong type (" + (type == TINYGLTF_TYPE_VEC3 ? "expected float VEC3" : "expected SCALAR") + ")");
        if (a.bufferView < 0 || static_cast<size_t>(a.bufferView) >= model_.bufferViews.size())
            fail_file(path_, where + " has no buffer view");
        const tinygltf::BufferView& view = model_.bufferViews[a.bufferView];
        if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model_.buffers.size())
            fail_file(path_, where + ": its buffer view refers to a missing buffer");
        const size_t buffer_size = model_.buffers[view.buffer].data.size();
        if (view.byteOffset > buffer_size || view.byteLength > buffer_size - view.byteOffset)
            fail_file(path_, where + ": buffer view " + std::to_string(a.bufferView) + " reaches past the end of its buffer");
        const int32_t component_size = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType));
        if (component_size <= 0) fail_file(path_, where + " has an invalid component type");
        const size_t element = static_cast<size_t>(component_size) * static_cast<size_t>(tinygltf::GetNumComponentsInType(a.type));
        const size_t stride = view.byteStride ? view.byteStride : element;
        if (stride < element) fail_file(path_, where + ": byteStride is smaller than one element");
        if (a.count > options_.max_elements)
            fail_file(path_, where + " claims " + std::to_string(a.count) + " elements, more than the limit of " +
                                 std::to_string(options_.max_elements));
        // Overflow-safe form of: byteOffset + (count - 1) * stride + element <= byteLength.
        if (a.count > 0 && (a.byteOffset > view.byteLength || element > view.byteLength - a.byteOffset ||
                            (a.count - 1) > (view.byteLength - a.byteOffset - element) / stride))
            fail_file(path_, where + " claims " + std::to_string(a.count) + " elements, more than its buffer view holds");
        return Span{model_.buffers[view.buffer].data.data() + view.byteOffset + a.byteOffset, stride, a.count};
    }

    std::vector<uint32_t> corners(const tinygltf::Primitive& prim, size_t vertex_count, const std::string& what) const {
        std::vector<uint32_t> out;
        if (prim.indices < 0) {  // non-indexed: the vertices in order
            out.resize(vertex_count);
            for (size_t i = 0; i < vertex_count; ++i) out[i] = static_cast<uint32_t>(i);
            return out;
        }
        const Span s = accessor(prim.indices, -1, TINYGLTF_TYPE_SCALAR, what + " indices");
        const int type = model_.accessors[prim.indices].componentType;
        out.resize(s.count);
        for (size_t i = 0; i < s.count; ++i) {
            uint32_t v = 0;
            if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) v = *s.at(i);
            else if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) v = load<uint16_t>(s.at(i));
            else if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) v = load<uint32_t>(s.at(i));
            else fail_file(path_, what + ": indices must be unsigned byte, short or int");
            if (v >= vertex_count)
                fail_file(path_, what + ": index " + std::to_string(i) + " refers to vertex " + std::to_string(v) +
                                     " but there are only " + std::to_string(vertex_count) + " vertices");
            out[i] = v;
        }
        return out;
    }

    template <class T>
    static T load(const unsigned char* p) {
        T v;
        std::memcpy(&v, p, sizeof v);
        return v;
    }

    // Strips and fans become triangles with the winding the glTF spec gives each of them;
    // strip/fan triangles with a repeated corner are only joins and are dropped.
    static std::vector<uint32_t> triangles(int mode, const std::vector<uint32_t>& c) {
        if (mode == TINYGLTF_MODE_TRIANGLES) return c;
        std::vector<uint32_t> out;
        for (size_t i = 0; i + 2 < c.size(); ++i) {
            uint32_t a, b, d;
            if (mode == TINYGLTF_MODE_TRIANGLE_FAN) a = c[i + 1], b = c[i + 2], d = c[0];
            else if (i % 2 == 0) a = c[i], b = c[i + 1], d = c[i + 2];
            else a = c[i], b = c[i + 2], d = c[i + 1];
            if (a != b && b != d && a != d) out.insert(out.end(), {a, b, d});
        }
        return out;
    }

    void add_primitive(const tinygltf::Primitive& prim, const std::string& what, const glm::dmat4& world) {
        const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
        if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
            skipped_.push_back(what + " (mode " + mode_name(mode) + ")");
            return;
        }
        const auto position = prim.attributes.find("POSITION");
        if (position == prim.attributes.end()) fail_file(path_, what + " has no POSITION attribute");
        const Span positions = accessor(position->second, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, what + " POSITION");
        const auto normal = prim.attributes.find("NORMAL");
        const Span normals = normal == prim.attributes.end()
                                 ? Span{}
                                 : accessor(normal->second, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, what + " NORMAL");
        if (normals.data && normals.count != positions.count)
            fail_file(path_, what + " has " + std::to_string(normals.count) + " normals for " +
                                 std::to_string(positions.count) + " positions");
        std::vector<uint32_t> indices = triangles(mode, corners(prim, positions.count, what));
        if (mode == TINYGLTF_MODE_TRIANGLES && indices.size() % 3 != 0)
            fail_file(path_, what + " has " + std::to_string(indices.size()) + " corners, not a multiple of 3");

        // Instancing can multiply a small file into a huge mesh: the limit applies to the result.
        if (mesh_.positions.size() + positions.count > std::min<uint64_t>(options_.max_elements, UINT32_MAX) ||
            (mesh_.indices.size() + indices.size()) / 3 > options_.max_elements)
            fail_file(path_, "the scene has more than " + std::to_string(options_.max_elements) + " vertices or triangles");

        Mesh part;
        part.positions.resize(positions.count);
        for (size_t i = 0; i < positions.count; ++i)
            part.positions[i] = glm::vec3(world * glm::dvec4(glm::dvec3(load<glm::vec3>(positions.at(i))), 1.0));
        const glm::dmat3 linear(world);
        if (glm::determinant(linear) < 0.0)  // a mirroring transform turns faces inside out: undo it
            for (size_t t = 0; t + 2 < indices.size(); t += 3) std::swap(indices[t + 1], indices[t + 2]);
        part.indices = std::move(indices);
        if (normals.data) {
            const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(linear));
            part.normals.resize(normals.count);
            for (size_t i = 0; i < normals.count; ++i) {
                const glm::dvec3 n = normal_matrix * glm::dvec3(load<glm::vec3>(normals.at(i)));
                const double length = glm::length(n);
                part.normals[i] = length > 0.0 ? glm::vec3(n / length) : glm::vec3(0.0f);
            }
        } else {
            compute_vertex_normals(part);  // per primitive, so every part has a full set
        }
        append_mesh(mesh_, part);
    }

    const std::string& path_;
    const tinygltf::Model& model_;
    const LoadOptions& options_;
    Mesh mesh_;
    std::vector<std::string> skipped_;  // primitives of points or lines, as "mesh M primitive P (mode X)"
};

// Bytes from memory have no folder: a reference to an external file is refused, not looked up in
// the current directory.
bool no_external_file(std::vector<unsigned char>*, std::string* err, const std::string& uri, void*) {
    if (err) *err = "external file '" + uri + "' cannot be read: the model was not loaded from a file";
    return false;
}
bool no_file_exists(const std::string&, void*) { return false; }
std::string unexpanded(const std::string& path, void*) { return path; }
bool no_file_written(std::string*, const std::string&, const std::vector<unsigned char>&, void*) { return false; }

}  // namespace

Mesh parse_gltf(const std::string& path, std::string_view bytes, const std::filesystem::path* base_dir,
                const LoadOptions& options) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const bool binary = ext == ".glb";
    if (bytes.size() > UINT32_MAX) fail_file(path, "a glTF file of 4 GiB or more is not supported");
    // tinygltf reads a field of the wrong type as absent, and trusts sizes: every field we (and the
    // animation reader) use is checked first, and named when it is wrong.
    validate_gltf(path, bytes, binary, base_dir);

    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&skip_image, nullptr);
    if (!base_dir) loader.SetFsCallbacks({&no_file_exists, &unexpanded, &no_external_file, &no_file_written, nullptr});
    const std::string dir = base_dir ? base_dir->string() : std::string();
    tinygltf::Model model;
    std::string err, warn;
    const auto size = static_cast<unsigned int>(bytes.size());
    const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()), size, dir)
                           : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), size, dir);
    if (!ok) fail_file(path, "cannot read glTF: " + one_line(err.empty() ? warn : err));
    if (!warn.empty()) std::fprintf(stderr, "%s: warning: %s\n", path.c_str(), one_line(warn).c_str());
    return Loader(path, model, options).run();
}

}  // namespace stipple
