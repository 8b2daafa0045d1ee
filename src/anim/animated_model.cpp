#include "anim/animated_model.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>

#include "anim/deform_cpu.hpp"
#include "anim/gltf_probe.hpp"
#include "anim/gltf_reading.hpp"
#include "anim/pose.hpp"
#include "core/error.hpp"
#include "mesh/loader_util.hpp"

namespace stipple::anim {

namespace {

struct DrawingOrder {
    Mesh mesh;                    // as load_mesh_for_drawing returns it
    std::vector<uint32_t> origin;  // per vertex of `mesh`, its index in the file-order mesh
};

// optimize_draw_order moves every per-vertex stream of a Mesh with one remap and reads only the
// positions and indices to choose it. So a copy whose normals hold vertex numbers (exact in float: 16
// bits each in x and y) comes out in the same order with each vertex's origin attached, and the
// animation streams can follow whatever the reordering does.
DrawingOrder reorder_for_drawing(const Mesh& file_order) {
    Mesh tagged = file_order;
    for (size_t i = 0; i < tagged.normals.size(); ++i)
        tagged.normals[i] = glm::vec3(static_cast<float>(i & 0xFFFFu), static_cast<float>(i >> 16), 0.0f);
    optimize_draw_order(tagged);
    DrawingOrder order;
    order.origin.resize(tagged.positions.size());
    order.mesh.source = file_order.source;
    order.mesh.winding = file_order.winding;
    order.mesh.duplicates_dropped = file_order.duplicates_dropped;
    order.mesh.decoded = file_order.decoded;
    order.mesh.normals.resize(tagged.positions.size());
    for (size_t i = 0; i < tagged.positions.size(); ++i) {
        const uint32_t o = static_cast<uint32_t>(tagged.normals[i].x) | static_cast<uint32_t>(tagged.normals[i].y) << 16;
        STIPPLE_CHECK(o < file_order.positions.size() && file_order.positions[o] == tagged.positions[i],
                      "the draw order's vertex origins are inconsistent");
        order.origin[i] = o;
        order.mesh.normals[i] = file_order.normals[o];
    }
    order.mesh.positions = std::move(tagged.positions);
    order.mesh.indices = std::move(tagged.indices);
    return order;
}

std::string lower_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

void require_gltf_name(const std::string& name) {
    const std::string ext = lower_extension(name);
    if (ext != ".gltf" && ext != ".glb") fail_file(name, "animation needs a glTF file (.gltf or .glb)");
}

// glTF's rest pose is the file's geometry with its skins and default morph weights applied, where the
// static loader places each primitive by its node alone: it knows no morph targets, and it places a
// skinned mesh by the mesh node's transform, which glTF says to ignore. Where the two differ (a mesh
// whose default weights are not zero, a skinned mesh under a scaled or turned node), the rest mesh takes
// the rest pose, so that the stipple counts, the stretch (current area over rest area) and the bounds
// are measured on what is drawn when nothing moves: measured on the static placement, a box whose
// default weight doubled it drew 1.5 times the ink of the same box stored doubled, and a skin under a
// node of scale 0.5 drew 36% ink instead of 24%. The faces keep the static loader's winding except
// where the rest pose's mirroring differs from the mesh node's (a skinned mesh under a mirroring node).
// A rest pose that collapses faces or leaves the coordinates drawing allows is not adopted. Returns
// whether it changed anything.
bool adopt_rest_pose(const std::string& path, AnimatedModel& model, const FileOrderStreams& streams,
                     const std::vector<uint32_t>& origin, double tolerance) {
    const Pose pose = evaluate_pose(model, kRestPose, 0.0);
    const DeformedGeometry rest = deform_cpu(model, pose);
    bool moved = false;
    for (size_t v = 0; v < rest.positions.size(); ++v) {
        const glm::vec3& p = rest.positions[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            fail_file(path, "vertex " + std::to_string(origin[v]) +
                                " is not finite in the rest pose (its skin's joints and inverse bind matrices applied)");
        moved = moved || glm::length(glm::dvec3(p) - glm::dvec3(model.rest.positions[v])) > tolerance;
    }
    if (!moved) return false;
    // A rest pose that collapses faces (a joint at scale 0: a part hidden until the animation grows it)
    // would give them no stipples ever, and one beyond the coordinates drawing allows would draw nothing:
    // such a file keeps the static placement's mesh, as before.
    Mesh adopted = model.rest;
    adopted.positions = rest.positions;
    adopted.normals = rest.normals;
    for (size_t t = 0; t < adopted.triangle_count(); ++t) {
        const double before = triangle_area(model.rest, t);
        if (before > 0.0 && !(triangle_area(adopted, t) > 1e-6 * before)) return model.rest_pose_declined = true, false;
    }
    try {
        validate_mesh(adopted);
    } catch (const Error&) {
        return model.rest_pose_declined = true, false;
    }
    model.rest = std::move(adopted);

    // Which file-order vertices the static loader mirrored (and so re-wound).
    std::vector<uint8_t> static_mirror(streams.bind_positions.size(), 0);
    for (const VertexRange& range : streams.ranges) {
        const bool mirror = glm::determinant(glm::dmat3(range.static_world)) < 0.0;
        std::fill(static_mirror.begin() + range.first, static_mirror.begin() + range.first + range.count, mirror);
    }
    for (size_t t = 0; t + 2 < model.rest.indices.size(); t += 3) {
        const uint32_t v = model.rest.indices[t];
        const bool rest_mirror = glm::determinant(glm::dmat3(blend_matrix(model, pose, v))) < 0.0;
        if (rest_mirror != bool(static_mirror[origin[v]])) std::swap(model.rest.indices[t + 1], model.rest.indices[t + 2]);
    }
    return true;
}

// Drops the channels that move no drawn vertex: a node's transform reaches the drawing only through the
// palette slots the vertices' influences use (a skin's joints, or the node of a rigid mesh instance) and
// those nodes' ancestors; weights only through a morph set some vertex reads. A file whose animations
// drive only such nodes (an empty node, a node outside the scene, the joints of a skin no drawn mesh
// uses) is then still, as it looks: drawn by every path, one frame for its sequence, its CPU paths
// allowed, rather than "animated" with nothing moving.
void drop_channels_that_move_nothing(AnimatedModel& model) {
    std::vector<char> slot_used(model.palette.size(), 0);
    std::vector<char> weights_used(model.morph_weight_count, 0);
    for (size_t v = 0; v < model.influences.size(); ++v) {
        const Influences& inf = model.influences[v];
        for (uint32_t i = 0; i < kMaxInfluences; ++i)
            if (inf.weight[i] != 0.0f && inf.slot[i] < slot_used.size()) slot_used[inf.slot[i]] = 1;
        const MorphRef& ref = model.morph_refs[v];
        if (ref.count > 0 && ref.first_weight < weights_used.size()) weights_used[ref.first_weight] = 1;
    }
    std::vector<char> moves(model.nodes.size(), 0);  // the node's transform reaches a drawn vertex
    for (size_t s = 0; s < model.palette.size(); ++s)
        for (int n = slot_used[s] ? model.palette[s].node : kNoNode; n != kNoNode && !moves[n]; n = model.nodes[n].parent)
            moves[n] = 1;
    auto idle = [&](const Channel& c) {
        if (c.path != ChannelPath::Weights) return !moves[c.node];
        const int set = model.nodes[c.node].morph_set;
        return set < 0 || !weights_used[model.morph_sets[set].first_weight];
    };
    for (Animation& a : model.animations) {
        const size_t before = a.channels.size();
        std::erase_if(a.channels, idle);
        a.idle_channels += before - a.channels.size();
    }
}

// The animated model over the static loader's mesh (file order) of the same document: the streams read
// here are matched to its vertices.
AnimatedModel build_animated_model(const std::string& path, const Mesh& file_order, const tinygltf::Model& gltf,
                                   const LoadOptions& options) {
    AnimatedModel model;
    model.source = path;
    FileOrderStreams streams;
    read_gltf_scene(path, gltf, options, model, streams);
    read_gltf_animations(path, gltf, options, model);

    const size_t n = file_order.vertex_count();
    if (streams.bind_positions.size() != n)
        fail_file(path, "internal: the animation data has " + std::to_string(streams.bind_positions.size()) +
                            " vertices, the static mesh " + std::to_string(n));
    // Rest normals back into each vertex's own space: the static loader mapped file normals by the
    // inverse transpose of the mesh node's transform, so its transpose maps them back. Deriving them
    // from the rest normals keeps whatever the static loader decided (computed normals, a flip).
    std::vector<glm::vec3> bind_normals(n);
    const Bounds bounds = compute_bounds(file_order);
    const double tolerance = 1e-5 * std::max(1e-30, double(glm::length(bounds.max - bounds.min)));
    for (const VertexRange& range : streams.ranges) {
        const glm::dmat3 transpose = glm::transpose(glm::dmat3(range.static_world));
        for (size_t v = range.first; v < range.first + range.count; ++v) {
            const glm::dvec3 placed = glm::dvec3(range.static_world * glm::dvec4(glm::dvec3(streams.bind_positions[v]), 1.0));
            // Within the tolerance, or the float rounding of where it lies: a part a thousandth of a unit across
            // placed 3 units out (an instance scaled down, found by fuzzing) rounds by more than its own 1e-5.
            const double far = std::max({std::abs(placed.x), std::abs(placed.y), std::abs(placed.z)});
            if (glm::length(placed - glm::dvec3(file_order.positions[v])) > std::max(tolerance, 4.0 * 0x1p-23 * far))
                fail_file(path, "internal: vertex " + std::to_string(v) + " of the animation data is not the static mesh's");
            const glm::dvec3 normal = transpose * glm::dvec3(file_order.normals[v]);
            const double length = glm::length(normal);
            bind_normals[v] = length > 0.0 ? glm::vec3(normal / length) : glm::vec3(0.0f, 0.0f, 1.0f);
            // Loading turns a file normal that disagrees with its faces around (turn_normals_to_faces);
            // the vertex's morph normal deltas turn with it.
            if (glm::dot(glm::dvec3(bind_normals[v]), glm::dvec3(streams.file_normals[v])) < 0.0) {
                const MorphRef& ref = streams.morph_refs[v];
                for (uint32_t k = 0; k < ref.count; ++k) {
                    glm::vec3& delta = streams.morph_deltas[ref.first_delta + k].normal;
                    delta = -delta;
                }
            }
        }
    }

    DrawingOrder order = reorder_for_drawing(file_order);
    model.rest = std::move(order.mesh);
    const size_t drawn = model.rest.vertex_count();
    model.bind_positions.resize(drawn);
    model.bind_normals.resize(drawn);
    model.influences.resize(drawn);
    model.morph_refs.resize(drawn);
    for (size_t i = 0; i < drawn; ++i) {
        const uint32_t o = order.origin[i];
        model.bind_positions[i] = streams.bind_positions[o];
        model.bind_normals[i] = bind_normals[o];
        model.influences[i] = streams.influences[o];
        // Deltas regrouped in drawing order, so that neighbouring vertices read neighbouring deltas.
        MorphRef ref = streams.morph_refs[o];
        const uint32_t first = static_cast<uint32_t>(model.morph_deltas.size());
        for (uint32_t k = 0; k < ref.count; ++k) model.morph_deltas.push_back(streams.morph_deltas[ref.first_delta + k]);
        ref.first_delta = first;
        model.morph_refs[i] = ref;
    }
    adopt_rest_pose(path, model, streams, order.origin, tolerance);
    drop_channels_that_move_nothing(model);
    return model;
}

}  // namespace

bool AnimatedModel::is_animated() const {
    return std::any_of(animations.begin(), animations.end(), [](const Animation& a) { return !a.channels.empty(); });
}

namespace {

// The static loader's options for the rest mesh: no vertex of the file split (its skin and morph data are
// per vertex; a two-sided sheet's split vertices made the load fail), and where the file has animations no
// triangle dropped for two of its vertices at one place (the animation may pull them apart). A file that only
// poses its rest (skins or morph weights, no animation) drops them as a static model does.
LoadOptions rest_mesh_options(const LoadOptions& options, bool may_move) {
    LoadOptions rest = options;
    rest.split_two_sided_vertices = false;
    rest.drop_collapsed_by_position = !may_move;
    return rest;
}

}  // namespace

AnimatedModel load_animated_model(const std::string& path, const LoadOptions& options) {
    require_gltf_name(path);
    // The static loader decides the rest mesh (its checks, normals and orientation).
    tinygltf::Model gltf;
    const Mesh file_order = load_gltf_mesh(path, rest_mesh_options(options, gltf_declares_animations(path)), gltf);
    return build_animated_model(path, file_order, gltf, options);
}

AnimatedModel load_animated_model_from_bytes(const std::string& name, std::string_view bytes, const LoadOptions& options) {
    require_gltf_name(name);
    tinygltf::Model gltf;
    const Mesh file_order = load_gltf_mesh_from_bytes(name, bytes, nullptr, rest_mesh_options(options, true), gltf);
    return build_animated_model(name, file_order, gltf, options);
}

}  // namespace stipple::anim
