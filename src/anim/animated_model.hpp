#pragma once
// A glTF model that moves: the rest mesh (the static loader's, or the file's rest pose where that
// differs), plus what deforms it (per-vertex influences and morph deltas, the node hierarchy, skins and
// animations).
//
// Deformation is unified as a palette of matrices: a vertex's position in object space is
//   sum_i weight_i * palette[slot_i] * (bind_position + sum_k morph_weight_k * delta_k)
// where a skin's slots hold world(joint, t) * inverse_bind (the skinned mesh node's own transform is
// ignored, as glTF requires) and an unskinned mesh instance has one slot, world(node, t), with
// weight 1. So one kernel (shaders/deform.comp) serves skins, node animation and static parts alike.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "mesh/load_mesh.hpp"
#include "mesh/mesh.hpp"

namespace stipple::anim {

inline constexpr int kNoNode = -1;
inline constexpr uint32_t kMaxInfluences = 8;  // JOINTS_0/WEIGHTS_0 and JOINTS_1/WEIGHTS_1

struct Node {
    std::string name;
    int parent = kNoNode;
    std::vector<int> children;
    // Rest transform: TRS, or a fixed matrix (a node with a matrix cannot be animated).
    glm::dvec3 translation{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 scale{1.0};
    bool has_matrix = false;
    glm::dmat4 matrix{1.0};
    int morph_set = -1;  // index into AnimatedModel::morph_sets when this node instances a morphed mesh
};

struct Skin {
    std::string name;
    std::vector<int> joints;               // node indices
    std::vector<glm::mat4> inverse_bind;   // one per joint (identity when the file gives none)
    uint32_t first_slot = 0;               // palette slot of joints[0]; the others follow
};

// One palette matrix: world(node, t) * inverse_bind; node kNoNode means the identity (a mesh that
// no node places: a file without scenes).
struct PaletteSlot {
    int node = kNoNode;
    glm::mat4 inverse_bind{1.0f};
};

// The morph weights of one mesh instance (a node with a morphed mesh): consecutive entries of the
// pose's weight array. Rest weights: the node's, else the mesh's, else zeros.
struct MorphSet {
    int node = kNoNode;
    std::string mesh_name;
    std::vector<std::string> target_names;  // empty strings where the file names none
    uint32_t first_weight = 0;
    std::vector<float> rest_weights;         // one per target
};

enum class Interpolation { Step, Linear, CubicSpline };
enum class ChannelPath { Translation, Rotation, Scale, Weights };

// Keyframes of one sampler. values holds, per key, `components` numbers (three elements per key for
// CUBICSPLINE: in-tangent, value, out-tangent). Rotations are x, y, z, w as in glTF.
struct Sampler {
    Interpolation interpolation = Interpolation::Linear;
    std::vector<float> times;  // strictly increasing, from 0 or later
    std::vector<float> values;
    uint32_t components = 0;   // 3 (translation, scale), 4 (rotation) or the morph target count
};

struct Channel {
    uint32_t sampler = 0;
    int node = kNoNode;
    ChannelPath path = ChannelPath::Translation;
};

struct Animation {
    std::string name;
    std::vector<Sampler> samplers;
    std::vector<Channel> channels;
    float duration = 0.0f;  // the last keyframe time of any sampler; the animation runs from 0
    // Channels of the file that move nothing drawn (no node, a property of an extension, a node that
    // neither places a drawn vertex nor is an ancestor of one that does, weights of a mesh not drawn):
    // not in `channels`. The duration still counts those that were read, so the loop is the file's.
    size_t idle_channels = 0;
};

// Up to kMaxInfluences (palette slot, weight) pairs; weights sum to 1; unused pairs are (0, 0).
struct Influences {
    std::array<uint32_t, kMaxInfluences> slot{};
    std::array<float, kMaxInfluences> weight{};
};

// Where a vertex's morph targets are: `count` consecutive deltas from `first_delta`, weighted by the
// pose's weights from `first_weight`. count 0: not morphed.
struct MorphRef {
    uint32_t first_delta = 0;
    uint32_t count = 0;
    uint32_t first_weight = 0;
};

struct MorphDelta {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f};
};

struct AnimatedModel {
    std::string source;
    // The rest mesh: the same triangles and vertex order as load_mesh_for_drawing(source), so stipples
    // generated on either stay valid on the other; its positions and normals too, unless the file's rest
    // pose (skins and default morph weights applied) differs from the static loader's placement, where
    // they are the rest pose's (and a face's winding follows the rest pose's mirroring). One exception: the
    // vertices a two-sided sheet's sides share stay one here (LoadOptions::split_two_sided_vertices), where
    // the static loader splits them.
    Mesh rest;
    // The file's rest pose differs from the static placement but collapses faces or leaves the coordinates
    // drawing allows: `rest` keeps the static placement (adopt_rest_pose).
    bool rest_pose_declined = false;
    // Per rest vertex, in the space its influences expect (bind space, or the mesh node's own space).
    std::vector<glm::vec3> bind_positions;
    std::vector<glm::vec3> bind_normals;
    std::vector<Influences> influences;
    std::vector<MorphRef> morph_refs;
    std::vector<MorphDelta> morph_deltas;

    std::vector<Node> nodes;
    std::vector<int> node_order;  // every node, parents before their children
    std::vector<Skin> skins;
    std::vector<PaletteSlot> palette;
    std::vector<MorphSet> morph_sets;
    uint32_t morph_weight_count = 0;
    std::vector<Animation> animations;

    size_t vertex_count() const { return rest.vertex_count(); }
    // Whether anything can move it: an animation with at least one channel (one that moves a drawn vertex).
    bool is_animated() const;
};

// Loads a .gltf or .glb with everything that animates it. Bad input (including bad animation data:
// mismatched sampler counts, key times below 0 or not increasing, joints beyond their skin, weights summing to zero,
// accessors of the wrong type) throws stipple::Error, one line naming the file and the field.
AnimatedModel load_animated_model(const std::string& path, const LoadOptions& options = {});

// The same from bytes in memory (the fuzzer): `name`'s extension chooses .gltf or .glb and names the
// model in every message; a .gltf read this way cannot refer to external buffer files.
AnimatedModel load_animated_model_from_bytes(const std::string& name, std::string_view bytes,
                                             const LoadOptions& options = {});

}  // namespace stipple::anim
