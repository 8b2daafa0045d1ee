#include "gpu/gpu_timer.hpp"

#include "core/error.hpp"
#include "gpu/context.hpp"
#include "gpu/vk_check.hpp"

namespace stipple::gpu {

GpuTimer::GpuTimer(const Context& context, uint32_t max_marks) : context_(context), max_marks_(max_marks) {
    if (!context.features.timestamps) return;  // the timer then reports nothing
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = max_marks + 1;
    VK_CHECK(vkCreateQueryPool(context.device, &info, nullptr, &pool_));
}

GpuTimer::~GpuTimer() {
    if (pool_) vkDestroyQueryPool(context_.device, pool_, nullptr);
}

void GpuTimer::begin_frame(VkCommandBuffer cb) {
    passes_.clear();
    if (!pool_) return;
    vkCmdResetQueryPool(cb, pool_, 0, max_marks_ + 1);
    vkCmdWriteTimestamp2(cb, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, 0);
}

void GpuTimer::mark(VkCommandBuffer cb, const char* pass) {
    if (!pool_) return;
    STIPPLE_CHECK(passes_.size() < max_marks_, "too many GPU timer marks in one frame");
    passes_.emplace_back(pass);
    vkCmdWriteTimestamp2(cb, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, uint32_t(passes_.size()));
}

std::vector<std::pair<std::string, double>> GpuTimer::read() const {
    std::vector<std::pair<std::string, double>> result;
    if (!pool_ || passes_.empty()) return result;
    std::vector<uint64_t> ticks(passes_.size() + 1);
    VK_CHECK(vkGetQueryPoolResults(context_.device, pool_, 0, uint32_t(ticks.size()), ticks.size() * sizeof(uint64_t),
                                   ticks.data(), sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    // Only the queue's valid bits count (36-64 on real devices): masked, a difference across the counter's
    // wrap is still right.
    const uint32_t bits = context_.features.timestamp_valid_bits;
    const uint64_t valid = bits >= 64 ? ~uint64_t(0) : (uint64_t(1) << bits) - 1;
    for (size_t i = 0; i < passes_.size(); ++i)
        result.emplace_back(passes_[i],
                            double((ticks[i + 1] - ticks[i]) & valid) * context_.features.timestamp_period_ns * 1e-6);
    return result;
}

}  // namespace stipple::gpu
