#pragma once
// The depth pass as compute (shaders/depth_raster.comp): the scene's depth written straight into the
// words the splat and the object-space lines test against, by a compute pass over the triangles spread
// over every core, instead of the fixed-function depth pass and its copy into words. On a software
// GPU the fixed-function pass sets up every triangle on one thread (docs/architecture.md, "Depth by
// compute"). Where a frame needs the depth image itself (stipples drawn by the points pipeline), the
// words are copied into it, with the coverage stencil made from them, so every path tests against the
// same depth; the Raskar-Cohen lines test the words in their fragment shader (silhouette_words.frag).
#include <optional>
#include <string>

namespace stipple {

namespace gpu {
class Context;
}

// auto: compute on a CPU device (lavapipe) for frames whose triangles are small on screen (their mean
// projected area under kDepthComputeBelowPx) or whose objects cover little of it (kDepthComputeBelowFrame),
// fixed-function otherwise, on a GPU, and where an object is drawn by the points pipeline (the vertex,
// indirect and cpu paths test the depth image, and copying the words into it costs more than compute
// saves); compute: wherever the device can (64-bit integers in shaders); fixed: the fixed-function pass.
// A frame with a toon object (§3.1: its shading is drawn by the depth pass) uses the fixed-function pass
// whatever the choice.
enum class DepthRaster { Auto, Compute, Fixed };
// auto's bounds. The compute pass saves the fixed-function pass's per-triangle work on one thread and
// the copy into words, and pays more per pixel covered (a software rasteriser fills 4x4 blocks at once).
// So it wins where triangles are many for the pixels they cover, and loses where a close view covers
// the frame with mid-sized ones. Measured at 1280x1024 (lavapipe, 2 cores; depth pass + copy against
// compute, ms, docs/architecture.md): the bunny framed (8.6 px a triangle) 12.5-14.7 against 7.0-7.9;
// at 0.45 of its framing distance (43 px, the frame covered) 11.1-13.2 against 13.7-16.1; the fox
// (320 px a triangle, its surface 0.4 of the frame) 2.5-2.9 against 1.4-2.2; spot (112 px, 0.5)
// 5.8-6.3 against 4.9-5.0; a 12-triangle box (0.75) 4.0-5.4 against 4.8-5.4.
// Mean projected area of a triangle facing the eye, square pixels, under which compute is used:
inline constexpr float kDepthComputeBelowPx = 24.0f;
// ... or the objects' facing surface (triangles times that mean) under this share of the frame.
inline constexpr double kDepthComputeBelowFrame = 0.6;
const char* depth_raster_name(DepthRaster mode);
std::optional<DepthRaster> parse_depth_raster(const std::string& name);
// Whether `mode` rasterises by compute on this device (before the per-frame toon exception).
bool depth_raster_by_compute(DepthRaster mode, const gpu::Context& context);

}  // namespace stipple
