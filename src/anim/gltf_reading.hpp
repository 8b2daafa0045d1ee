#pragma once
// The glTF reading behind load_animated_model (internal to src/anim). The scene reader walks the
// scene in the static loader's order (src/mesh/gltf_loader.cpp: nodes depth first, children in order,
// primitives in order, non-triangle primitives skipped), so its vertex streams line up one to one with
// load_mesh's vertices before they are reordered for drawing.
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include "anim/animated_model.hpp"
#include "mesh/load_mesh.hpp"

namespace stipple::anim {

// A run of consecutive vertices from one primitive of one mesh instance.
struct VertexRange {
    size_t first = 0;
    size_t count = 0;
    glm::dmat4 static_world{1.0};  // the transform load_mesh applied to them (the mesh node's rest world)
};

// Per vertex, in load_mesh's (file) order.
struct FileOrderStreams {
    std::vector<glm::vec3> bind_positions;
    std::vector<glm::vec3> file_normals;  // (0, 0, 0) where the file has none
    std::vector<Influences> influences;
    std::vector<MorphRef> morph_refs;
    std::vector<MorphDelta> morph_deltas;
    std::vector<VertexRange> ranges;
};

// Nodes (hierarchy, rest transforms, order), skins, palette slots, morph sets, and the vertex streams.
void read_gltf_scene(const std::string& path, const tinygltf::Model& gltf, const LoadOptions& options,
                     AnimatedModel& model, FileOrderStreams& streams);

// Animations, samplers and channels, every one validated (needs the nodes and morph sets).
void read_gltf_animations(const std::string& path, const tinygltf::Model& gltf, const LoadOptions& options,
                          AnimatedModel& model);

}  // namespace stipple::anim
