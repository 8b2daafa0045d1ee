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
// projected area under kDepthComputeBelowPx), fixed-function otherwise and on a GPU; compute: wherever
// the device can (64-bit integers in shaders); fixed: the fixed-function pass. A frame with a toon
// object (§3.1: its shading is drawn by the depth pass) uses the fixed-function pass whatever the choice.
enum class DepthRaster { Auto, Compute, Fixed };
// auto's bound, in square pixels per triangle facing the eye over the frame's objects. The compute pass
// gives large triangles a workgroup each, which a software rasteriser's tiles beat: on the bunny at
// 1280x1024 (lavapipe, 2 cores) compute took 8.7 ms against 17.4 for the pass and its copy at 8.6 px a
// triangle, and broke even at about 40 px (the bunny at 0.45 of its framing distance); at 320 px (the
// fox) it took 9.6 ms against 3.1.
inline constexpr float kDepthComputeBelowPx = 24.0f;
const char* depth_raster_name(DepthRaster mode);
std::optional<DepthRaster> parse_depth_raster(const std::string& name);
// Whether `mode` rasterises by compute on this device (before the per-frame toon exception).
bool depth_raster_by_compute(DepthRaster mode, const gpu::Context& context);

}  // namespace stipple
