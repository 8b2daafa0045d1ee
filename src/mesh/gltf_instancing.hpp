#pragma once
// EXT_mesh_gpu_instancing (gltfpack -mi, Blender's "GPU instances", three.js InstancedMesh exports): a
// node draws its mesh once per instance, at the node's world transform times the instance's
// TRANSLATION * ROTATION * SCALE (each attribute optional). The static and the animated loader expand
// the instances into copies of the mesh, the same copies in the same order, so that the animated model's
// rest mesh stays the static one.
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include "mesh/gltf_accessor.hpp"

namespace stipple {

// The instances' local transforms of node `node_index`, in order; empty when the node has no
// EXT_mesh_gpu_instancing (it draws its mesh once). Attributes of the application's own (_ID, ...) count
// instances too; a node with only those draws its mesh at the node's transform once per instance. Throws
// stipple::Error naming the field for an attribute of the wrong type, attributes of different counts, no
// instance, or more instances than the limit allows for the node's mesh (checked before any is read).
std::vector<glm::dmat4> read_gpu_instances(const std::string& path, const tinygltf::Model& model, int node_index,
                                           const AccessorReader& reader, const LoadOptions& options);

}  // namespace stipple
