#pragma once
// The machine's limit for the vertex path (issue 17, target 2): a bare pass drawing the same number of
// culled and drawn points as the vertex path does for a model, with a trivial shader (no vertex
// inputs, no buffers; culled points beyond the far plane, drawn ones as points of the stipples' size), timed with
// timestamp queries. The vertex path's stipple pass time over the probe's says how far the path is
// from what the rasteriser can do with that many points ("x of the limit").
// A second probe draws the same points with the stipple pass's fixed-function state (depth test
// against a depth buffer, the coverage stencil test, blending; still the trivial shaders): how much of
// the gap is that state's work, which any drawing of these stipples does, and how much our shaders'.
// (On lavapipe the two probes take the same time within ±10%: the gap is the shaders'.)
#include <cstdint>

#include <vulkan/vulkan.h>

#include "gpu/resources.hpp"

namespace stipple::gpu {
class Context;
}

namespace stipple::bench {

class LimitProbe {
public:
    LimitProbe(const gpu::Context& context, VkExtent2D extent);
    ~LimitProbe();
    LimitProbe(const LimitProbe&) = delete;
    LimitProbe& operator=(const LimitProbe&) = delete;

    // One frame of the probe: `culled + drawn` points, the drawn ones `point_size` pixels wide in a
    // centred square of `footprint_pixels` pixels. Returns the GPU milliseconds of its pass (without timestamps, on a
    // device that has none, the wall time of the submission instead).
    // `with_state`: with the stipple pass's depth, stencil and blending.
    double frame(uint64_t culled, uint64_t drawn, uint64_t footprint_pixels, float point_size, bool with_state = false);

private:
    // What the constructor made, destroyed; also when it throws midway (a destructor does not run then).
    void release();
    VkImageAspectFlags depth_aspect() const;
    double frame_ms(uint32_t total, uint32_t drawn, float side, float point_size, bool with_state);

    const gpu::Context& context_;
    VkExtent2D extent_;
    VkFormat depth_format_;  // the context's, as the stipple pass's
    gpu::Image color_;
    gpu::Image depth_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    VkPipeline state_pipeline_ = VK_NULL_HANDLE;  // with the stipple pass's depth, stencil and blending
};

}  // namespace stipple::bench
