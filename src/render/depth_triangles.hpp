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

// auto: list the triangles of objects whose triangles are small on screen when the frames show that it
// pays (DepthCullChooser); on: list every object's (toon ones excepted); off: never.
enum class DepthCull { Auto, On, Off };
const char* depth_cull_name(DepthCull mode);
std::optional<DepthCull> parse_depth_cull(const std::string& name);

// auto's first guess, before it has timed anything: list an object's triangles when their mean
// projected area (facing the eye, square pixels) is under this. The listing pass reads every triangle,
// so it pays only where many triangles cover no pixel centre (a triangle of area a covers about a
// centres on average) and those cost the rasteriser more than the pass does.
inline constexpr float kDepthCullBelowPx = 0.75f;
// auto considers listing only below this mean area: above it nearly every triangle covers a centre.
inline constexpr float kDepthCullConsiderPx = 2.0f;

// The mean screen area, in square pixels, of the object's triangles that face the eye: for a closed
// convex surface a quarter of its area faces the eye, carried by about half its triangles. From the
// rest shape's area, the object's scale and the view depth of its centre; 0 when the eye is in it.
float mean_front_triangle_px(const ObjectGpu& object, const gpu::ObjectUniforms& uniforms, const FrameView& view);

// Whether listing could change the object's depth pass at all: toon objects shade in the depth pass and
// draw their whole mesh (ties between equal depths would follow the list's order).
bool may_list_depth_triangles(const ObjectGpu& object);

// auto's choice, from the frames' own GPU times. What a dropped triangle saves the rasteriser differs
// from mesh to mesh and view to view (a front face between pixel centres costs it its setup; a face
// away, culled by its winding, almost nothing), so no estimate from the geometry tells in advance
// whether the list pays, nor does it stay put: the same 650k-triangle hand at the same view gained a
// third of its frame in one run and nothing in another (its whole depth pass took 38 ms or 65). The chooser starts with the estimate (kDepthCullBelowPx), then times
// kDepthCullTimedFrames frames alternating between the two (the depth pass plus the list), keeps the
// one whose fastest frame was faster for kDepthCullHoldFrames frames, and times both again after that or
// once the view's scale has changed by more than half. The image is the same either way; only the time
// changes.
inline constexpr int kDepthCullTimedFrames = 6;
inline constexpr int kDepthCullHoldFrames = 120;
class DepthCullChooser {
public:
    // Before a frame: whether the objects considered (kDepthCullConsiderPx) list their triangles.
    // `mean_px`: the smallest mean front-triangle area among them; 0 when none is considered.
    bool next_frame(float mean_px);
    // After the frame that next_frame chose for: the GPU milliseconds of its depth pass and list.
    void frame_done(double depth_ms);

private:
    enum class Phase { Timing, Holding };
    Phase phase_ = Phase::Timing;
    bool fresh_ = true;           // nothing timed since objects were last considered
    bool guess_ = false;          // the estimate's choice when the timing started (timed first)
    bool listed_ = false;         // the last choice
    bool awaiting_ = false;       // a choice made for a frame not yet reported
    int frame_ = 0;                   // frames of this round so far (an untimed one, then the timed ones)
    double best_ms_[2] = {0.0, 0.0};  // the fastest GPU ms timed, whole and listed (0: none yet)
    int hold_left_ = 0;
    float decided_px_ = 0.0f;     // the scale when the choice was made
};

// Grows the object's list to hold every triangle (rewriting its descriptor set); the GPU must not be
// using the object (StippleRenderer::prepare's contract).
void ensure_depth_triangles(ObjectGpu& object);

}  // namespace stipple
