#pragma once
// Animated objects in the renderer (issue 16). Before the density pass of each frame, for every animated
// object: the deformation kernel (shaders/deform.comp, anim::GpuDeformer) skins and morphs its vertices
// straight into ObjectGeometry::positions and ::normals, then shaders/polygon_constants.comp recomputes
// its polygons' centroid, normal and area into PolygonConstants::gpu. Every later pass (density, depth,
// stipples, splat, lines) reads the deformed geometry as it reads a static object's: the candidates are
// (u, v) in their polygon, so they move with the surface, and the edge table does not depend on the pose.
//
// What stays constant: the bounds sphere is the rest mesh's (it set the reference view of generation, so
// it must set the reference scale of the density too), and the box the centroids are quantised in holds
// every pose of every animation (anim::StretchHeadroom::bounds). The CPU density paths read CPU copies
// of the polygons that would be the rest pose's: they are refused for animated objects.
#include <memory>
#include <span>

#include <vulkan/vulkan.h>

#include "anim/gpu_deform.hpp"
#include "anim/headroom.hpp"
#include "anim/pose.hpp"
#include "gpu/pipelines.hpp"
#include "mesh/mesh.hpp"

namespace stipple {

namespace gpu {
class Context;
}
struct ObjectGpu;

// The polygon pass's view of one animated object: texel views of its mesh buffers and a descriptor set
// naming them and its polygons (DeformPass makes it the first time the object is recorded).
struct PolygonBinding {
    VkDevice device = VK_NULL_HANDLE;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkDescriptorSet set = VK_NULL_HANDLE;

    PolygonBinding() = default;
    ~PolygonBinding();
    PolygonBinding(const PolygonBinding&) = delete;
    PolygonBinding& operator=(const PolygonBinding&) = delete;
};

// What moves one object, and when it is.
struct ObjectAnimation {
    anim::Motion motion;
    std::unique_ptr<anim::GpuDeformer> deformer;  // writes into the object's own mesh buffers
    int animation = 0;       // an index into the model's animations, or anim::kRestPose
    double seconds = 0.0;    // into the animation (wrapped or clamped by `loop`)
    bool loop = true;
    anim::Pose pose;         // evaluated by prepare(), sent by the frame's recording
    std::unique_ptr<PolygonBinding> polygons;  // made by DeformPass on first use
};

// The area at which each polygon's candidates are all due: its rest area (`mesh` is the motion's rest
// mesh) times the headroom it was generated with (generate_stipples), so the density asks for
// candidates * current / full of them. CPU only (the viewer's worker prepares it).
std::vector<float> animated_full_areas(const Mesh& mesh, const anim::Motion& motion);

// Makes `object` (its geometry and polygons just uploaded from the motion's rest mesh) animated: its
// per-polygon full areas and a deformer writing into its mesh buffers. Before its descriptor set is written.
std::unique_ptr<ObjectAnimation> create_object_animation(const gpu::Context& context, ObjectGpu& object,
                                                         const anim::Motion& motion, std::span<const float> full_areas);

// Throws a one-line stipple::Error when `object` is animated and its density path runs on the CPU.
void check_animated_path(const ObjectGpu& object);

// The pass that recomputes animated objects' polygon constants (shaders/polygon_constants.comp).
class DeformPass {
public:
    // vec3_texels: the layout of the objects' mesh texel views (ObjectGeometry::position_texels), a vertex
    // (triangle) per texel, else a float (index).
    DeformPass(const gpu::Context& context, bool vec3_texels);
    ~DeformPass();
    DeformPass(const DeformPass&) = delete;
    DeformPass& operator=(const DeformPass&) = delete;

    // Evaluates each animated object's pose (CPU; a few matrices per joint).
    static void evaluate(std::span<const std::unique_ptr<ObjectGpu>> objects);
    // Records the deformation of every animated object (skinning and morphing into its mesh buffers).
    // Returns whether there was any; then record_polygons must follow.
    bool record_skinning(VkCommandBuffer cb, std::span<const std::unique_ptr<ObjectGpu>> objects) const;
    // Their polygon constants from the deformed meshes, then orders every later reader of the mesh and the
    // polygons (vertex input, vertex shaders, compute) after both passes.
    void record_polygons(VkCommandBuffer cb, std::span<const std::unique_ptr<ObjectGpu>> objects) const;

private:
    // What the constructor made, destroyed; also when it throws midway (a destructor does not run then).
    void release();
    void bind(ObjectGpu& object) const;

    const gpu::Context& context_;
    bool vec3_texels_ = false;  // the objects' mesh texel views hold a vertex (triangle) per texel
    VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    gpu::LazyPipeline pipeline_;  // made with the first animated object's frame
};

}  // namespace stipple
