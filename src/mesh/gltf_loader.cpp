// The static mesh of a glTF 2.0 file (.gltf with external or data: buffers, and .glb), read by
// gltf_document (validated, loaded by tinygltf, compressed views decoded). What points into the buffers
// (accessors, buffer views, indices, node references) is checked again here as it is used.
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
#include "mesh/gltf_accessor.hpp"
#include "mesh/gltf_document.hpp"
#include "mesh/gltf_instancing.hpp"
#include "mesh/load_mesh.hpp"
#include "mesh/loader_util.hpp"

namespace stipple {

namespace {

const char* mode_name(int mode) {
    switch (mode) {
        case TINYGLTF_MODE_POINTS: return "POINTS";
        case TINYGLTF_MODE_LINE: return "LINES";
        case TINYGLTF_MODE_LINE_LOOP: return "LINE_LOOP";
        case TINYGLTF_MODE_LINE_STRIP: return "LINE_STRIP";
        default: return "unknown";
    }
}

const std::vector<int> kIndexTypes = {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                      TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT};

// A document without skins, morph targets or animations: its mesh is drawn as loaded.
bool nothing_deforms(const tinygltf::Model& model) {
    if (!model.skins.empty() || !model.animations.empty()) return false;
    for (const tinygltf::Mesh& mesh : model.meshes)
        for (const tinygltf::Primitive& prim : mesh.primitives)
            if (!prim.targets.empty()) return false;
    return true;
}

class Loader {
public:
    Loader(const std::string& path, const tinygltf::Model& model, const LoadOptions& options)
        : path_(path), model_(model), options_(options), reader_(path, model, options), keep_exact_(nothing_deforms(model)) {}

    // What `stipple info` says was expanded, e.g. "EXT_mesh_gpu_instancing (125 instances of 1 node)";
    // "" for none.
    std::string instancing() const {
        if (instanced_nodes_ == 0) return "";
        return "EXT_mesh_gpu_instancing (" + std::to_string(instances_) + (instances_ == 1 ? " instance" : " instances") +
               " of " + std::to_string(instanced_nodes_) + (instanced_nodes_ == 1 ? " node)" : " nodes)");
    }

    Mesh run() {
        mesh_.source = path_;
        if (model_.scenes.empty()) {
            // No scene to say what is shown: every mesh once, untransformed.
            for (size_t m = 0; m < model_.meshes.size(); ++m) add_mesh(static_cast<int>(m), {glm::dmat4(1.0)});
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
        // Placed far from the file's origin by its nodes, the model is stored about its own centre (Mesh::origin,
        // as the OBJ and PLY readers do): a unit sphere under a node translated 90,000 units was rounded to 1/128
        // of a unit (its area 12.62 for 12.56, its shading in bands).
        if (keep_exact_) store_about_far_origin(mesh_, exact_);
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
            if (node.mesh >= 0) {
                std::vector<glm::dmat4> worlds = read_gpu_instances(path_, model_, index, reader_, options_);
                if (worlds.empty()) {
                    worlds.push_back(glm::dmat4(1.0));  // no instancing: the node's own
                } else {
                    ++instanced_nodes_;
                    instances_ += worlds.size();
                }
                for (glm::dmat4& instance : worlds) instance = world * instance;
                add_mesh(node.mesh, worlds);
            }
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

    // The mesh once at each of `worlds` (a node's, or its EXT_mesh_gpu_instancing instances').
    void add_mesh(int index, const std::vector<glm::dmat4>& worlds) {
        if (index < 0 || static_cast<size_t>(index) >= model_.meshes.size())
            fail_file(path_, "mesh " + std::to_string(index) + " does not exist");
        const tinygltf::Mesh& m = model_.meshes[index];
        const std::string name = m.name.empty() ? "mesh " + std::to_string(index) : "mesh '" + one_line(m.name) + "'";
        for (size_t p = 0; p < m.primitives.size(); ++p)
            add_primitive(m.primitives[p], name + " primitive " + std::to_string(p), worlds);
    }

    std::vector<uint32_t> corners(const tinygltf::Primitive& prim, size_t vertex_count, const std::string& what) const {
        std::vector<uint32_t> out;
        if (prim.indices < 0) {  // non-indexed: the vertices in order
            out.resize(vertex_count);
            for (size_t i = 0; i < vertex_count; ++i) out[i] = static_cast<uint32_t>(i);
            return out;
        }
        out = reader_.uints(prim.indices, TINYGLTF_TYPE_SCALAR, kIndexTypes, what + " indices");
        for (size_t i = 0; i < out.size(); ++i)
            if (out[i] >= vertex_count)
                fail_file(path_, what + ": index " + std::to_string(i) + " refers to vertex " + std::to_string(out[i]) +
                                     " but there are only " + std::to_string(vertex_count) + " vertices");
        return out;
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

    void add_primitive(const tinygltf::Primitive& prim, const std::string& what, const std::vector<glm::dmat4>& worlds) {
        const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
        if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
            skipped_.push_back(what + " (mode " + mode_name(mode) + ")");
            return;
        }
        const auto position = prim.attributes.find("POSITION");
        if (position == prim.attributes.end()) fail_file(path_, what + " has no POSITION attribute");
        const std::vector<float> positions =
            reader_.numbers(position->second, TINYGLTF_TYPE_VEC3, kGltfQuantizedTypes, kGltfQuantizedTypes, what + " POSITION");
        const size_t vertex_count = positions.size() / 3;
        const auto normal = prim.attributes.find("NORMAL");
        const std::vector<float> normals =
            normal == prim.attributes.end()
                ? std::vector<float>()
                : reader_.numbers(normal->second, TINYGLTF_TYPE_VEC3, {}, kGltfSignedTypes, what + " NORMAL", true);
        if (!normals.empty() && normals.size() != positions.size())
            fail_file(path_, what + " has " + std::to_string(normals.size() / 3) + " normals for " +
                                 std::to_string(vertex_count) + " positions");
        std::vector<uint32_t> indices = triangles(mode, corners(prim, vertex_count, what));
        if (mode == TINYGLTF_MODE_TRIANGLES && indices.size() % 3 != 0)
            fail_file(path_, what + " has " + std::to_string(indices.size()) + " corners, not a multiple of 3");

        // At most half the machine's memory (as a model file may be at most half: check_model_size), all the copies
        // counted before the first is made: a 671-byte file instancing one triangle 10 million times loaded for
        // 2.4 GiB whatever STIPPLE_HOST_MEMORY_LIMIT said, and 66 million would have taken about 16 GiB.
        check_load_fits_memory(path_, "the scene (instances counted)", mesh_.positions.size() + uint64_t(vertex_count) * worlds.size(),
                               (mesh_.indices.size() + uint64_t(indices.size()) * worlds.size()) / 3);
        // The last copy takes the indices; the others copy them (a mesh drawn once copies nothing).
        for (size_t i = 0; i + 1 < worlds.size(); ++i) add_copy(positions, normals, indices, worlds[i]);
        add_copy(positions, normals, std::move(indices), worlds.back());
    }

    // One copy of a primitive's triangles, placed by `world`.
    void add_copy(const std::vector<float>& positions, const std::vector<float>& normals, std::vector<uint32_t> indices,
                  const glm::dmat4& world) {
        const size_t vertex_count = positions.size() / 3;
        // Instancing (nodes sharing a mesh, EXT_mesh_gpu_instancing) can multiply a small file into a
        // huge mesh: the limit applies to the result.
        if (mesh_.positions.size() + vertex_count > std::min<uint64_t>(options_.max_elements, UINT32_MAX) ||
            (mesh_.indices.size() + indices.size()) / 3 > options_.max_elements)
            fail_file(path_, "the scene has more than " + std::to_string(options_.max_elements) + " vertices or triangles");

        Mesh part;
        part.positions.resize(vertex_count);
        for (size_t i = 0; i < vertex_count; ++i) {
            const glm::dvec3 p(world * glm::dvec4(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2], 1.0));
            part.positions[i] = glm::vec3(p);
            if (keep_exact_) exact_.push_back(p);
        }
        const glm::dmat3 linear(world);
        if (glm::determinant(linear) < 0.0)  // a mirroring transform turns faces inside out: undo it
            for (size_t t = 0; t + 2 < indices.size(); t += 3) std::swap(indices[t + 1], indices[t + 2]);
        part.indices = std::move(indices);
        if (!normals.empty()) {
            const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(linear));
            part.normals.resize(vertex_count);
            for (size_t i = 0; i < vertex_count; ++i) {
                const glm::dvec3 n = normal_matrix * glm::dvec3(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]);
                const double length = glm::length(n);
                part.normals[i] = length > 0.0 ? glm::vec3(n / length) : glm::vec3(0.0f);
            }
        } else {
            compute_vertex_normals(part);  // per primitive, so every part has a full set
            mesh_.normals_computed = true;  // not the file's: loading computes them all again (load_mesh.cpp)
        }
        append_mesh(mesh_, part);
    }

    const std::string& path_;
    const tinygltf::Model& model_;
    const LoadOptions& options_;
    AccessorReader reader_;
    Mesh mesh_;
    // The placed positions in double, for a far origin (run). Not for a model that deforms: its skins and morph
    // targets are matched to the mesh as placed (anim/animated_model.cpp).
    bool keep_exact_;
    std::vector<glm::dvec3> exact_;
    std::vector<std::string> skipped_;  // primitives of points or lines, as "mesh M primitive P (mode X)"
    size_t instanced_nodes_ = 0, instances_ = 0;  // EXT_mesh_gpu_instancing, as drawn
};

}  // namespace

Mesh parse_gltf(const std::string& path, std::string_view bytes, const std::filesystem::path* base_dir,
                const LoadOptions& options, tinygltf::Model* document) {
    std::string decoded;
    tinygltf::Model model = read_gltf_model(path, bytes, base_dir, &decoded);
    Loader loader(path, model, options);
    Mesh mesh = loader.run();
    const std::string instancing = loader.instancing();
    if (!instancing.empty()) decoded += (decoded.empty() ? "" : ", ") + instancing;
    mesh.decoded = std::move(decoded);
    if (document) *document = std::move(model);
    return mesh;
}

}  // namespace stipple
