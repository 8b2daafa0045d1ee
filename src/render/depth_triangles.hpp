#pragma once
// The depth pass of an object whose triangles are smaller than the pixels: a compute pass
// (shaders/depth_triangles.comp) lists the triangles that may cover a pixel centre, and the depth pass
// draws that list (an indexed indirect draw) instead of the whole mesh. The depth, the stencil and the
// image are the same either way; what changes is the work of a software rasteriser, which sets up every
// triangle it is given on one thread, whether or not the triangle covers a pixel.
#include <optional>
#include <string>

#include "render/object_gpu.hpp"

namespace stipple {

struct FrameView;

// auto: list the triangles when they are small on screen (uses_depth_triangles); on/off: always/never.
enum class DepthCull { Auto, On, Off };
const char* depth_cull_name(DepthCull mode);
std::optional<DepthCull> parse_depth_cull(const std::string& name);

// Below this mean projected area of a triangle facing the eye, in square pixels, auto lists them: the
// listing pass reads each triangle as the depth pass would, so it pays only where most triangles
// cover no pixel centre (a triangle of area a covers about a centres on average).
inline constexpr float kDepthCullBelowPx = 0.75f;

// The mean screen area, in square pixels, of the object's triangles that face the eye: for a closed
// convex surface a quarter of its area faces the eye, carried by about half its triangles. From the
// rest shape's area, the object's scale and the view depth of its centre; 0 when the eye is in it.
float mean_front_triangle_px(const ObjectGpu& object, const gpu::ObjectUniforms& uniforms, const FrameView& view);

// Whether the object's depth pass draws the list this frame. Toon objects shade in the depth pass and
// draw their whole mesh (ties between equal depths would follow the list's order).
bool uses_depth_triangles(const ObjectGpu& object, const gpu::ObjectUniforms& uniforms, const FrameView& view,
                          DepthCull mode);

// Grows the object's list to hold every triangle (rewriting its descriptor set); the GPU must not be
// using the object (StippleRenderer::prepare's contract).
void ensure_depth_triangles(ObjectGpu& object);

}  // namespace stipple
