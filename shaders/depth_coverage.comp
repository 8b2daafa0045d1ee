#version 460
// The coverage stencil (CoverageStencil::Write: 1 where a surface covers the pixel) made from the depth
// words of the depth pass as compute (shaders/depth_raster.comp), as the bytes a copy into the depth
// image's stencil aspect reads: four pixels a word. Written into the splat's background buffer, which
// is scratch until the splat fills it later in the frame.
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"
#include "dispatch.h"

layout(local_size_x = kDensityWorkgroupSize) in;

layout(constant_id = kSpecDepthUnorm24) const bool kDepthUnorm24 = true;

layout(set = 0, binding = kBindingFrame) uniform FrameBlock { FrameUniforms frame; };
layout(set = 1, binding = kBindingSplatBackground, std430) writeonly buffer CoverageBytes { uint coverage_bytes[]; };
layout(set = 1, binding = kBindingSceneDepth, std430) readonly buffer SceneDepth { uint scene_depth[]; };

bool covered(uint word) {  // as splat.comp's uncovered(), negated
    if (kDepthUnorm24) return (word & 0xFFFFFFu) != 0xFFFFFFu;
    return uintBitsToFloat(word) < 1.0;
}

void main() {
    uint pixels = uint(frame.viewport.x) * uint(frame.viewport.y);
    uint word = linear_invocation();
    uint first = word * 4u;
    if (first >= pixels) return;
    uint bytes = 0u;
    for (uint k = 0u; k < 4u; ++k)
        if (first + k < pixels && covered(scene_depth[first + k])) bytes |= 1u << (8u * k);
    coverage_bytes[word] = bytes;
}
