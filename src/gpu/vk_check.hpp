#pragma once
// Every VkResult is checked; a failure throws with the call and the result's name (release builds too).
#include <string>

#include <vulkan/vulkan.h>

#include "core/error.hpp"

namespace stipple::gpu {

const char* vk_result_name(VkResult result);

inline void vk_check(VkResult result, const char* call, const char* file, int line) {
    if (result == VK_ERROR_DEVICE_LOST)
        fail("the GPU device was lost (its driver reset it or crashed) in " + std::string(call) +
             ": nothing more can be drawn; start again, and if it repeats lower the load (--dmax, image size)");
    if (result != VK_SUCCESS)
        fail(std::string("Vulkan call failed: ") + call + " returned " + vk_result_name(result) + " (" + file + ":" +
             std::to_string(line) + ")");
}

}  // namespace stipple::gpu

#define VK_CHECK(call) ::stipple::gpu::vk_check((call), #call, __FILE__, __LINE__)
