// Layouts of the deformation kernel (shaders/deform.comp), shared by C++ and GLSL like shared_types.h:
// C++ includes it through src/anim/deform_layout.hpp, which static_asserts every size and offset.
// Kept apart from shared_types.h because only the deformation pass binds these.
#ifndef STIPPLE_DEFORM_TYPES_H
#define STIPPLE_DEFORM_TYPES_H

#include "shared_types.h"

#ifdef __cplusplus
namespace stipple::gpu {
#endif

STIPPLE_CONST uint kDeformWorkgroupSize = 64;
// Influences per vertex: glTF's JOINTS_0/WEIGHTS_0 and JOINTS_1/WEIGHTS_1.
STIPPLE_CONST uint kDeformMaxInfluences = 8;
// deform.comp's specialisation constant: how many of a vertex's influence pairs it reads (the most
// that any vertex of the model uses; pack_deform_vertices puts the used pairs first). A software GPU
// runs both sides of a data-dependent branch, so skipping unused pairs at run time saves nothing there.
STIPPLE_CONST uint kSpecDeformInfluences = 0;
// Palette slots are stored as 16-bit numbers, two per uint.
STIPPLE_CONST uint kDeformMaxPaletteSlots = 65536;
// Morph weights: the first weight in 16 bits, the target count in the other 16.
STIPPLE_CONST uint kDeformMaxMorphWeights = 65536;

// polygon_constants.comp's own set: the deformed mesh as texel buffers (a software GPU fetches a
// texel's components in one gather, where it loads a storage buffer's floats lane by lane), and the
// polygons it writes.
STIPPLE_CONST uint kBindingPolygonPositions = 0;  // texel buffer: the object's vertices (RGB32F, or R32F)
STIPPLE_CONST uint kBindingPolygonIndices = 1;    // texel buffer: its triangles (RGB32UI, or R32UI)
STIPPLE_CONST uint kBindingPolygonInfos = 2;      // TriangleInfo[] (storage, read and written)
// Whether the texel buffers hold a vertex (triangle) per texel (1) or one float (index) per texel (0):
// three-component texel buffers are optional in Vulkan.
STIPPLE_CONST uint kSpecPolygonVec3Texels = 0;

// Descriptor bindings of the deformation pass's own set (set 0 of its pipeline layout).
STIPPLE_CONST uint kBindingDeformVertices = 0;     // DeformVertex[] as RGBA32UI texels, five a vertex (read)
STIPPLE_CONST uint kBindingDeformMorphDeltas = 1;  // MorphDelta[] as RGBA32F texels, two a delta (read)
STIPPLE_CONST uint kBindingDeformPalette = 2;      // vec4[3 per slot] (read): top three rows of world(node, t) * inverse bind
STIPPLE_CONST uint kBindingDeformMorphWeights = 3; // float[] (read): this frame's morph weights
STIPPLE_CONST uint kBindingDeformPositions = 4;    // float[] (write): 3 floats per vertex, as kBindingMeshPositions
STIPPLE_CONST uint kBindingDeformNormals = 5;      // float[] (write): 3 floats per vertex, unit length

// One vertex as the kernel reads it: its undeformed place in the space its influences expect (the
// skin's bind space, or the mesh node's own space), and up to 8 (palette slot, weight) pairs whose
// weights sum to 1. Unused pairs have weight 0. 80 bytes.
struct DeformVertex {
    vec3 position;
    uint morph_first;    // index of its first MorphDelta (its targets' deltas are consecutive)
    vec3 normal;
    uint morph_weights;  // first weight index | target count << 16 (count 0: not morphed)
    uvec4 slots;         // palette slots, 16 bits each: slot 2i in the low half of component i
    vec4 weights0;       // weights of slots 0-3
    vec4 weights1;       // weights of slots 4-7
};

// One morph target's displacement of one vertex (w unused).
struct MorphDelta {
    vec4 position;
    vec4 normal;
};

// Push constants of the deformation pass.
struct DeformPush {
    uint vertex_count;
    uint pad0;
    uint pad1;
    uint pad2;
};

// polygon_constants.comp's push constants. 48 bytes.
struct PolygonConstantsPush {
    vec4 box_min;    // xyz: the object-space box the centroids are quantised in (every pose)
    vec4 box_size;   // xyz: its extent
    uint triangle_count;
    uint pad0;
    uint pad1;
    uint pad2;
};

#ifdef __cplusplus
}  // namespace stipple::gpu
#endif

#endif
