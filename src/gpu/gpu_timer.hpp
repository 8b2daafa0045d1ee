#pragma once
// GPU time per pass from timestamp queries: mark() after each pass; durations are the differences
// between consecutive marks, read once the frame has finished.
#include <string>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

namespace stipple::gpu {

class Context;

class GpuTimer {
public:
    GpuTimer(const Context& context, uint32_t max_marks = 16);
    ~GpuTimer();
    GpuTimer(const GpuTimer&) = delete;
    GpuTimer& operator=(const GpuTimer&) = delete;

    bool enabled() const { return pool_ != VK_NULL_HANDLE; }
    void begin_frame(VkCommandBuffer cb);           // resets the queries and writes the start mark
    void mark(VkCommandBuffer cb, const char* pass);  // the end of `pass`
    // (pass, milliseconds) of the last recorded frame; call after its submission has completed.
    std::vector<std::pair<std::string, double>> read() const;

private:
    const Context& context_;
    VkQueryPool pool_ = VK_NULL_HANDLE;
    uint32_t max_marks_ = 0;
    std::vector<std::string> passes_;
};

}  // namespace stipple::gpu
