// Nodes, skins, mesh instances and their per-vertex deformation data, read in the static loader's
// vertex order (see gltf_reading.hpp). Every index and count is checked: tinygltf checks none.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <optional>
#include <utility>

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "anim/gltf_reading.hpp"
#include "anim/trs.hpp"
#include "core/printf_string.hpp"
#include "core/error.hpp"
#include "deform_types.h"
#include "mesh/gltf_accessor.hpp"
#include "mesh/gltf_instancing.hpp"

namespace stipple::anim {

namespace {

const std::vector<int> kWeightTypes = {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};
const std::vector<int> kJointTypes = {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};

std::string indexed(const std::string& array, size_t i) { return array + "[" + std::to_string(i) + "]"; }

constexpr uint32_t kNoSlot = UINT32_MAX;  // add_primitive: no palette slot chosen by the caller
// How far a vertex's skin weights may sum from 1 before the file is warned about (rounding stays below it).
constexpr double kWeightSumWarning = 0.05;

class SceneReader {
public:
    SceneReader(const std::string& path, const tinygltf::Model& gltf, const LoadOptions& options, AnimatedModel& model,
                FileOrderStreams& streams)
        : path_(path), gltf_(gltf), options_(options), accessors_(path, gltf, options), model_(model), streams_(streams) {}

    void run() {
        read_nodes();
        read_skins();
        if (gltf_.scenes.empty()) {
            // As the static loader: no scene says what is shown, so every mesh once, untransformed.
            for (size_t m = 0; m < gltf_.meshes.size(); ++m) add_instance(static_cast<int>(m), kNoNode, glm::dmat4(1.0));
            return;
        }
        const int scene = gltf_.defaultScene >= 0 ? gltf_.defaultScene : 0;
        if (static_cast<size_t>(scene) >= gltf_.scenes.size())
            fail_file(path_, "default scene " + std::to_string(scene) + " does not exist");
        std::vector<std::pair<int, glm::dmat4>> stack;
        const std::vector<int>& roots = gltf_.scenes[scene].nodes;
        for (auto it = roots.rbegin(); it != roots.rend(); ++it) {
            if (*it < 0 || static_cast<size_t>(*it) >= model_.nodes.size())
                fail_file(path_, indexed("scenes", scene) + ".nodes: node " + std::to_string(*it) + " does not exist");
            stack.emplace_back(*it, glm::dmat4(1.0));
        }
        std::vector<char> seen(model_.nodes.size(), 0);
        while (!stack.empty()) {
            const auto [index, parent] = stack.back();
            stack.pop_back();
            if (seen[index]) fail_file(path_, "node " + std::to_string(index) + " is reached twice (the node hierarchy must be a tree)");
            seen[index] = 1;
            const Node& node = model_.nodes[index];
            const glm::dmat4 world =
                parent * (node.has_matrix ? node.matrix : trs_matrix(node.translation, node.rotation, node.scale));
            if (gltf_.nodes[index].mesh >= 0)
                add_instance(gltf_.nodes[index].mesh, index, world,
                             read_gpu_instances(path_, gltf_, index, accessors_, options_));
            for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) stack.emplace_back(*it, world);
        }
    }

private:
    void read_nodes() {
        model_.nodes.resize(gltf_.nodes.size());
        for (size_t i = 0; i < gltf_.nodes.size(); ++i) {
            const tinygltf::Node& in = gltf_.nodes[i];
            Node& node = model_.nodes[i];
            const std::string field = indexed("nodes", i);
            node.name = in.name;
            if (!in.matrix.empty()) {
                if (in.matrix.size() != 16) fail_file(path_, field + ".matrix: must have 16 numbers");
                node.has_matrix = true;
                node.matrix = glm::make_mat4(in.matrix.data());  // both glTF and glm are column-major
            }
            if (!in.translation.empty()) {
                if (in.translation.size() != 3) fail_file(path_, field + ".translation: must have 3 numbers");
                node.translation = glm::dvec3(in.translation[0], in.translation[1], in.translation[2]);
            }
            if (!in.rotation.empty()) {
                if (in.rotation.size() != 4) fail_file(path_, field + ".rotation: must have 4 numbers");
                const glm::dquat q(in.rotation[3], in.rotation[0], in.rotation[1], in.rotation[2]);  // x, y, z, w
                const double length = glm::length(q);
                if (!std::isfinite(length) || length < 1e-12) fail_file(path_, field + ".rotation: not a rotation quaternion");
                node.rotation = glm::normalize(q);
            }
            if (!in.scale.empty()) {
                if (in.scale.size() != 3) fail_file(path_, field + ".scale: must have 3 numbers");
                node.scale = glm::dvec3(in.scale[0], in.scale[1], in.scale[2]);
            }
            for (int child : in.children) {
                if (child < 0 || static_cast<size_t>(child) >= gltf_.nodes.size())
                    fail_file(path_, field + ".children: node " + std::to_string(child) + " does not exist");
                if (model_.nodes[child].parent != kNoNode || static_cast<size_t>(child) == i)
                    fail_file(path_, field + ".children: node " + std::to_string(child) +
                                         " has a second parent (the node hierarchy must be a tree)");
                model_.nodes[child].parent = static_cast<int>(i);
                node.children.push_back(child);
            }
        }
        // Parents before children; a node never reached from a root sits on a cycle.
        for (size_t i = 0; i < model_.nodes.size(); ++i) {
            if (model_.nodes[i].parent != kNoNode) continue;
            std::vector<int> stack{static_cast<int>(i)};
            while (!stack.empty()) {
                const int n = stack.back();
                stack.pop_back();
                model_.node_order.push_back(n);
                for (int child : model_.nodes[n].children) stack.push_back(child);
            }
        }
        if (model_.node_order.size() != model_.nodes.size())
            fail_file(path_, "nodes: the node hierarchy has a cycle");
    }

    void read_skins() {
        for (size_t s = 0; s < gltf_.skins.size(); ++s) {
            const tinygltf::Skin& in = gltf_.skins[s];
            const std::string field = indexed("skins", s);
            Skin skin;
            skin.name = in.name;
            for (int joint : in.joints) {
                if (joint < 0 || static_cast<size_t>(joint) >= model_.nodes.size())
                    fail_file(path_, field + ".joints: node " + std::to_string(joint) + " does not exist");
                // glTF: a skin's joints are unique (a vertex naming either copy could mean either bind matrix).
                if (std::find(skin.joints.begin(), skin.joints.end(), joint) != skin.joints.end())
                    fail_file(path_, field + indexed(".joints", skin.joints.size()) + ": node " + std::to_string(joint) +
                                         " is listed twice (glTF: a skin's joints are unique)");
                skin.joints.push_back(joint);
            }
            skin.inverse_bind.assign(skin.joints.size(), glm::mat4(1.0f));
            if (in.inverseBindMatrices >= 0) {
                const std::vector<float> m = accessors_.floats(in.inverseBindMatrices, TINYGLTF_TYPE_MAT4, {},
                                                               field + ".inverseBindMatrices");
                if (m.size() / 16 < skin.joints.size())
                    fail_file(path_, field + ".inverseBindMatrices: " + std::to_string(m.size() / 16) +
                                         " matrices for " + std::to_string(skin.joints.size()) + " joints");
                for (size_t j = 0; j < skin.joints.size(); ++j) {
                    // glTF requires the fourth row (0, 0, 0, 1): another one (all zeros, as a broken exporter
                    // writes) takes every vertex the joint moves to the camera's plane or to infinity, and the
                    // object vanished without a word. Checked loosely, as exporters round.
                    const float* row = &m[16 * j];
                    if (std::abs(row[3]) > 1e-3f || std::abs(row[7]) > 1e-3f || std::abs(row[11]) > 1e-3f ||
                        std::abs(row[15] - 1.0f) > 1e-3f)
                        fail_file(path_, field + printf_string(".inverseBindMatrices: matrix %zu's fourth row is (%g, %g, %g, %g); "
                                                               "glTF requires (0, 0, 0, 1)", j, double(row[3]), double(row[7]),
                                                               double(row[11]), double(row[15])));
                    // An inverse bind matrix is the inverse of the joint's bind pose, so it has one itself: a
                    // singular one (a row or column of zeros) flattens every vertex the joint moves onto a plane
                    // or a line, and the skinned object vanished without a word.
                    const glm::dmat3 linear(glm::make_mat4(row));
                    const double size = std::max({glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2])});
                    const double det = glm::determinant(linear);
                    if (!std::isfinite(det) || !(std::abs(det) > 1e-9 * size * size * size))
                        fail_file(path_, field + printf_string(".inverseBindMatrices: matrix %zu is singular (its 3x3 part has "
                                                               "determinant %g): no bind pose inverts to it", j, det));
                    skin.inverse_bind[j] = glm::make_mat4(row);
                }
            }
            skin.first_slot = static_cast<uint32_t>(model_.palette.size());
            for (size_t j = 0; j < skin.joints.size(); ++j) add_slot(PaletteSlot{skin.joints[j], skin.inverse_bind[j]});
            model_.skins.push_back(std::move(skin));
        }
    }

    uint32_t add_slot(const PaletteSlot& slot) {
        if (model_.palette.size() >= gpu::kDeformMaxPaletteSlots)
            fail_file(path_, "more than " + std::to_string(gpu::kDeformMaxPaletteSlots) + " joints and animated nodes");
        model_.palette.push_back(slot);
        return static_cast<uint32_t>(model_.palette.size() - 1);
    }

    // The slot that moves an unskinned mesh instance rigidly with its node.
    uint32_t node_slot(int node) {
        const auto [it, added] = node_slots_.try_emplace(node, 0u);
        if (added) it->second = add_slot(PaletteSlot{node, glm::mat4(1.0f)});
        return it->second;
    }

    // The mesh of a node (or of no node: kNoNode), once, or once per EXT_mesh_gpu_instancing instance
    // (`instances`, their local transforms; gltf_instancing.hpp), as the static loader places them.
    void add_instance(int mesh_index, int node_index, const glm::dmat4& world, const std::vector<glm::dmat4>& instances = {}) {
        if (mesh_index < 0 || static_cast<size_t>(mesh_index) >= gltf_.meshes.size())
            fail_file(path_, "mesh " + std::to_string(mesh_index) + " does not exist");
        const tinygltf::Mesh& mesh = gltf_.meshes[mesh_index];
        const std::string mesh_field = indexed("meshes", mesh_index);
        int skin = -1;
        if (node_index != kNoNode) {
            skin = gltf_.nodes[node_index].skin;
            if (skin != -1 && (skin < 0 || static_cast<size_t>(skin) >= model_.skins.size()))
                fail_file(path_, indexed("nodes", node_index) + ".skin: skin " + std::to_string(skin) + " does not exist");
        }
        if (skin >= 0 && !instances.empty())
            fail_file(path_, indexed("nodes", node_index) +
                                 ".extensions.EXT_mesh_gpu_instancing: instances of a skinned mesh cannot be animated");
        // One morph set for all the copies: they share the node's weights.
        const MorphRef morph = add_morph_set(mesh, mesh_index, node_index);
        // An instance moves rigidly with its node, placed by its own transform: a slot of its own.
        const size_t copies = std::max<size_t>(instances.size(), 1);
        std::vector<uint32_t> slots(copies, kNoSlot);
        for (size_t i = 0; i < instances.size(); ++i) {
            if (model_.palette.size() >= gpu::kDeformMaxPaletteSlots)
                fail_file(path_, indexed("nodes", node_index) + ".extensions.EXT_mesh_gpu_instancing: " +
                                     std::to_string(instances.size()) + " instances; an animated model moves at most " +
                                     std::to_string(gpu::kDeformMaxPaletteSlots) + " instances, joints and nodes in all");
            slots[i] = add_slot(PaletteSlot{node_index, glm::mat4(instances[i])});
        }
        // Primitive by primitive, each at every instance: the static loader's order (gltf_loader.cpp).
        for (size_t p = 0; p < mesh.primitives.size(); ++p) {
            const tinygltf::Primitive& prim = mesh.primitives[p];
            const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
            if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN)
                continue;  // the static loader skips these too (and warns)
            for (size_t i = 0; i < copies; ++i)
                add_primitive(prim, mesh_field + indexed(".primitives", p), node_index, skin,
                              instances.empty() ? world : world * instances[i], morph, slots[i]);
        }
    }

    MorphRef add_morph_set(const tinygltf::Mesh& mesh, int mesh_index, int node_index) {
        const std::string mesh_field = indexed("meshes", mesh_index);
        const size_t targets = mesh.primitives.empty() ? 0 : mesh.primitives[0].targets.size();
        for (size_t p = 1; p < mesh.primitives.size(); ++p)
            if (mesh.primitives[p].targets.size() != targets)
                fail_file(path_, mesh_field + indexed(".primitives", p) + ".targets: " +
                                     std::to_string(mesh.primitives[p].targets.size()) + " morph targets, but primitive 0 has " +
                                     std::to_string(targets));
        if (targets == 0) return MorphRef{};
        MorphSet set;
        set.node = node_index;
        set.mesh_name = mesh.name;
        set.first_weight = model_.morph_weight_count;
        if (set.first_weight + targets > gpu::kDeformMaxMorphWeights || targets > 0xFFFF)
            fail_file(path_, mesh_field + ": more than " + std::to_string(gpu::kDeformMaxMorphWeights) + " morph weights in all");
        for (size_t k = 0; k < targets; ++k) set.target_names.push_back(target_name(mesh, k));
        const std::vector<double>* weights = &mesh.weights;
        std::string weights_field = mesh_field + ".weights";
        if (node_index != kNoNode && !gltf_.nodes[node_index].weights.empty()) {  // the node's weights win
            weights = &gltf_.nodes[node_index].weights;
            weights_field = indexed("nodes", node_index) + ".weights";
        }
        if (!weights->empty() && weights->size() != targets)
            fail_file(path_, weights_field + ": " + std::to_string(weights->size()) + " weights for " +
                                 std::to_string(targets) + " morph targets");
        set.rest_weights.assign(targets, 0.0f);
        for (size_t k = 0; k < weights->size(); ++k) set.rest_weights[k] = static_cast<float>((*weights)[k]);
        model_.morph_weight_count += static_cast<uint32_t>(targets);
        if (node_index != kNoNode) model_.nodes[node_index].morph_set = static_cast<int>(model_.morph_sets.size());
        model_.morph_sets.push_back(std::move(set));
        return MorphRef{0, static_cast<uint32_t>(targets), model_.morph_sets.back().first_weight};
    }

    std::string target_name(const tinygltf::Mesh& mesh, size_t k) const {
        // Names come from the common "targetNames" extra, else from the target's POSITION accessor.
        if (mesh.extras.Has("targetNames")) {
            const tinygltf::Value& names = mesh.extras.Get("targetNames");
            if (names.IsArray() && k < names.ArrayLen() && names.Get(static_cast<int>(k)).IsString())
                return names.Get(static_cast<int>(k)).Get<std::string>();
        }
        const auto& target = mesh.primitives[0].targets[k];
        const auto position = target.find("POSITION");
        if (position != target.end() && position->second >= 0 &&
            static_cast<size_t>(position->second) < gltf_.accessors.size())
            return gltf_.accessors[position->second].name;
        return "";
    }

    const int* attribute(const tinygltf::Primitive& prim, const char* name) const {
        const auto it = prim.attributes.find(name);
        return it == prim.attributes.end() ? nullptr : &it->second;
    }

    // `rigid_slot`: the palette slot of an unskinned primitive, or kNoSlot for its node's (node_slot).
    void add_primitive(const tinygltf::Primitive& prim, const std::string& field, int node_index, int skin,
                       const glm::dmat4& world, MorphRef morph, uint32_t rigid_slot) {
        const int* position = attribute(prim, "POSITION");
        if (!position) fail_file(path_, field + ".attributes: no POSITION");
        const std::vector<float> positions =
            accessors_.numbers(*position, TINYGLTF_TYPE_VEC3, kGltfQuantizedTypes, kGltfQuantizedTypes,
                               field + ".attributes.POSITION");
        const size_t count = positions.size() / 3;
        const size_t first = streams_.bind_positions.size();
        streams_.ranges.push_back(VertexRange{first, count, world});
        for (size_t v = 0; v < count; ++v)
            streams_.bind_positions.emplace_back(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
        streams_.file_normals.resize(first + count, glm::vec3(0.0f));
        if (const int* normal = attribute(prim, "NORMAL")) {
            // As leniently as the static loader, which recomputes a normal that is not finite.
            const std::vector<float> n = per_vertex(*normal, count, field + ".attributes.NORMAL", {}, true);
            for (size_t v = 0; v < count; ++v) streams_.file_normals[first + v] = glm::vec3(n[3 * v], n[3 * v + 1], n[3 * v + 2]);
        }
        if (skin >= 0) {
            add_skin_influences(prim, field, skin, count);
        } else {
            Influences rigid;
            rigid.slot[0] = rigid_slot != kNoSlot ? rigid_slot : node_index == kNoNode ? identity_slot() : node_slot(node_index);
            rigid.weight[0] = 1.0f;
            streams_.influences.resize(first + count, rigid);
        }
        add_morph_deltas(prim, field, count, morph);
    }

    uint32_t identity_slot() {
        if (!identity_slot_) identity_slot_ = add_slot(PaletteSlot{});
        return *identity_slot_;
    }

    // A VEC3 per vertex: FLOAT, normalized BYTE or SHORT (KHR_mesh_quantization), or those listed in `plain`.
    std::vector<float> per_vertex(int accessor, size_t count, const std::string& field, const std::vector<int>& plain,
                                  bool allow_non_finite = false) const {
        std::vector<float> values =
            accessors_.numbers(accessor, TINYGLTF_TYPE_VEC3, plain, kGltfSignedTypes, field, allow_non_finite);
        if (values.size() / 3 != count)
            fail_file(path_, field + ": " + std::to_string(values.size() / 3) + " elements for " + std::to_string(count) + " vertices");
        return values;
    }

    void add_skin_influences(const tinygltf::Primitive& prim, const std::string& field, int skin_index, size_t count) {
        const Skin& skin = model_.skins[skin_index];
        const std::string skin_field = indexed("skins", skin_index);
        const size_t first = streams_.influences.size();
        streams_.influences.resize(first + count);
        std::vector<uint32_t> used(count, 0);  // influences filled so far per vertex
        std::vector<double> sums(count, 0.0);
        if (attribute(prim, "JOINTS_2") && !warned_extra_sets_) {
            std::fprintf(stderr, "%s: warning: %s has more than 8 joint influences per vertex; JOINTS_2 and later are ignored\n",
                         path_.c_str(), field.c_str());
            warned_extra_sets_ = true;
        }
        for (int set = 0; set < 2; ++set) {
            const std::string joints_name = "JOINTS_" + std::to_string(set), weights_name = "WEIGHTS_" + std::to_string(set);
            const int* joints = attribute(prim, joints_name.c_str());
            const int* weights = attribute(prim, weights_name.c_str());
            if (!joints && !weights) {
                if (set == 0) fail_file(path_, field + ".attributes: has no JOINTS_0/WEIGHTS_0, but its node uses " + skin_field);
                continue;
            }
            const std::string joints_field = field + ".attributes." + joints_name, weights_field = field + ".attributes." + weights_name;
            if (!joints) fail_file(path_, field + ".attributes: has " + weights_name + " but no " + joints_name);
            if (!weights) fail_file(path_, field + ".attributes: has " + joints_name + " but no " + weights_name);
            const std::vector<uint32_t> j = accessors_.uints(*joints, TINYGLTF_TYPE_VEC4, kJointTypes, joints_field);
            const std::vector<float> w = accessors_.floats(*weights, TINYGLTF_TYPE_VEC4, kWeightTypes, weights_field);
            for (const auto& [size, where] : {std::pair{j.size(), &joints_field}, std::pair{w.size(), &weights_field}})
                if (size / 4 != count)
                    fail_file(path_, *where + ": " + std::to_string(size / 4) + " elements for " + std::to_string(count) + " vertices");
            for (size_t v = 0; v < count; ++v) {
                for (int c = 0; c < 4; ++c) {
                    const float weight = w[4 * v + c];
                    if (weight < 0.0f)
                        fail_file(path_, weights_field + ": vertex " + std::to_string(v) + " has a negative weight");
                    if (weight == 0.0f) continue;  // an unused influence: its joint index does not matter
                    const uint32_t joint = j[4 * v + c];
                    if (joint >= skin.joints.size())
                        fail_file(path_, joints_field + ": vertex " + std::to_string(v) + " refers to joint " +
                                             std::to_string(joint) + ", but " + skin_field + " has " +
                                             std::to_string(skin.joints.size()) + " joints");
                    Influences& inf = streams_.influences[first + v];
                    inf.slot[used[v]] = skin.first_slot + joint;
                    inf.weight[used[v]] = weight;
                    ++used[v];
                    sums[v] += weight;
                }
            }
        }
        size_t off = 0;  // vertices whose weights sum to well other than 1 (glTF requires 1)
        double lowest = HUGE_VAL, highest = -HUGE_VAL;
        for (size_t v = 0; v < count; ++v) {
            if (!(sums[v] > 0.0))
                fail_file(path_, field + ".attributes.WEIGHTS_0: vertex " + std::to_string(v) + "'s weights sum to zero");
            // Exporters round weights; the blend must stay affine, so they are made to sum to 1.
            Influences& inf = streams_.influences[first + v];
            for (uint32_t i = 0; i < used[v]; ++i) inf.weight[i] = static_cast<float>(inf.weight[i] / sums[v]);
            if (std::abs(sums[v] - 1.0) > kWeightSumWarning) ++off, lowest = std::min(lowest, sums[v]), highest = std::max(highest, sums[v]);
        }
        // Beyond rounding (8-bit weights are off by up to 8/255 at 8 influences), the file is wrong: said once a
        // primitive, since what is drawn (the weights scaled) may not be what its author meant.
        if (off > 0)
            std::fprintf(stderr, "%s: warning: %s.attributes.%s: %zu of %zu vertices' weights sum to other than 1 "
                                 "(%.3g to %.3g); each vertex's are scaled to sum to 1\n",
                         excerpt(path_, 400).c_str(), field.c_str(), attribute(prim, "WEIGHTS_1") ? "WEIGHTS_0/WEIGHTS_1" : "WEIGHTS_0",
                         off, count, lowest, highest);
    }

    void add_morph_deltas(const tinygltf::Primitive& prim, const std::string& field, size_t count, MorphRef morph) {
        const size_t first = streams_.morph_refs.size();
        streams_.morph_refs.resize(first + count, MorphRef{});
        if (morph.count == 0) return;
        const size_t base = streams_.morph_deltas.size();
        // Vertices and targets are each bounded, their product is not: a 1.3 KB file of a million vertices
        // and 50 targets asked for 1.2 GB (found by review, 2026-12-04).
        if (count * morph.count > options_.max_elements - std::min<uint64_t>(base, options_.max_elements))
            fail_file(path_, field + ": " + std::to_string(count) + " vertices x " + std::to_string(morph.count) +
                                 " morph targets is more than the " + std::to_string(options_.max_elements) +
                                 " morph deltas a model may have");
        streams_.morph_deltas.resize(base + count * morph.count);
        for (size_t k = 0; k < morph.count; ++k) {
            const auto& target = prim.targets[k];
            const std::string target_field = field + indexed(".targets", k);
            for (const char* name : {"POSITION", "NORMAL"}) {
                const auto it = target.find(name);
                if (it == target.end()) continue;
                const bool is_position = name[0] == 'P';
                const std::vector<float> d =
                    per_vertex(it->second, count, target_field + "." + name, is_position ? kGltfSignedTypes : std::vector<int>{});
                for (size_t v = 0; v < count; ++v) {
                    MorphDelta& delta = streams_.morph_deltas[base + v * morph.count + k];
                    (is_position ? delta.position : delta.normal) = glm::vec3(d[3 * v], d[3 * v + 1], d[3 * v + 2]);
                }
            }
        }
        for (size_t v = 0; v < count; ++v)
            streams_.morph_refs[first + v] = MorphRef{static_cast<uint32_t>(base + v * morph.count), morph.count, morph.first_weight};
    }

    const std::string& path_;
    const tinygltf::Model& gltf_;
    const LoadOptions& options_;
    AccessorReader accessors_;
    AnimatedModel& model_;
    FileOrderStreams& streams_;
    std::map<int, uint32_t> node_slots_;
    std::optional<uint32_t> identity_slot_;
    bool warned_extra_sets_ = false;
};

}  // namespace

void read_gltf_scene(const std::string& path, const tinygltf::Model& gltf, const LoadOptions& options,
                     AnimatedModel& model, FileOrderStreams& streams) {
    SceneReader(path, gltf, options, model, streams).run();
}

}  // namespace stipple::anim
