#pragma once
// The machine's limit for the vertex path (issue 17, target 2): a bare pass drawing the same number of
// culled and drawn points as the vertex path does for a model, with a trivial shader (no vertex
// inputs, no buffers; culled points beyond the far plane, drawn ones as points of the stipples' size), timed with
// timestamp queries. The vertex path's stipple pass time over the probe's says how far the path is
// from what the rasteriser can do with that many points ("x of the limit").
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
    double frame(uint64_t culled, uint64_t drawn, uint64_t footprint_pixels, float point_size);

private:
    double frame_ms(uint32_t total, uint32_t drawn, float side, float point_size);

    const gpu::Context& context_;
    VkExtent2D extent_;
    gpu::Image color_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

}  // namespace stipple::bench
