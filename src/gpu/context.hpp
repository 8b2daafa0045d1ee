#pragma once
// The Vulkan instance, the chosen physical device, the logical device and its one queue.
// Headless by default; the viewer asks for the surface extensions it needs.
#include <atomic>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace stipple::gpu {

class MemoryPool;

struct ContextOptions {
    int device_index = -1;  // --device N; -1 picks the best (discrete > integrated > virtual > CPU)
    // Validation layer: on in debug builds; STIPPLE_VALIDATION=1 forces it on, =0 off.
    bool validation = default_validation();
    std::vector<const char*> instance_extensions;  // e.g. from glfwGetRequiredInstanceExtensions
    bool swapchain = false;                        // enable VK_KHR_swapchain on the device
    bool verbose = false;

    static bool default_validation();
};

// Optional features, recorded as enabled so the passes can adapt (lavapipe has all of them).
struct DeviceFeatures {
    bool large_points = false;
    bool wide_lines = false;
    bool int64 = false;  // shaderInt64: the depth pass as compute (render/depth_raster.hpp)
    bool pipeline_statistics = false;
    bool timestamps = false;
    // The device reads RGB32F and RGB32UI uniform texel buffers (optional in Vulkan): a mesh's vertex or
    // triangle is then one texel; else one float or index a texel.
    bool vec3_texels = false;
    float max_point_size = 1.0f;
    float max_line_width = 1.0f;
    double timestamp_period_ns = 1.0;
    uint32_t timestamp_valid_bits = 64;  // the queue's; the bits above are undefined, and the count wraps there
};

inline constexpr VkImageAspectFlags kDepthStencilAspect = VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;

// A depth aspect copied to a buffer holds 32-bit words: floats for D32_SFLOAT(_S8_UINT), or 24-bit
// unorm in the low bits (X8_D24) for D24_UNORM_S8_UINT. Window depth in [0, 1].
inline float depth_to_float(VkFormat format, uint32_t word) {
    if (format == VK_FORMAT_D24_UNORM_S8_UINT || format == VK_FORMAT_X8_D24_UNORM_PACK32)
        return float(word & 0xFFFFFFu) / 16777215.0f;
    float value;
    static_assert(sizeof value == sizeof word);
    std::memcpy(&value, &word, sizeof value);
    return value;
}

// How long a wait for the device may take before the program gives up (Context::wait_for_fence). The longest
// single submission is one frame or tile: seconds on lavapipe at the largest sizes.
inline constexpr int kDeviceWaitSeconds = 300;
// The least address space (ulimit -v) a process that creates a device is allowed: a render's peak on
// lavapipe is 0.9-1.0 GiB (VmPeak: the default scene 951 MB, igea 1,023 MB on 2 cores), and lavapipe's
// compiler crashed the process below it (at 400-850 MB); half a GiB more for the thread stacks of machines of
// more cores.
inline constexpr uint64_t kDriverAddressSpace = uint64_t(1536) << 20;

class Context {
public:
    explicit Context(const ContextOptions& options = {});
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physical_device = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t queue_family = 0;
    VkCommandPool command_pool = VK_NULL_HANDLE;  // for one-shot and per-frame command buffers
    VkPhysicalDeviceProperties properties{};
    VkPhysicalDeviceMemoryProperties memory_properties{};
    DeviceFeatures features;
    std::string device_name;
    // Depth with a stencil (the stencil marks covered pixels, see gpu::CoverageStencil):
    // D24_UNORM_S8_UINT where supported, else D32_SFLOAT_S8_UINT. Create depth images with
    // kDepthStencilAspect; read back only the depth aspect (see depth_to_float).
    VkFormat depth_format = VK_FORMAT_UNDEFINED;

    // Validation messages (warnings and errors) seen so far; every one is also printed on stderr.
    // A run or test with a non-zero count has failed.
    uint32_t validation_message_count() const { return validation_messages_.load(); }
    bool validation_enabled() const { return messenger_ != VK_NULL_HANDLE; }

    // One-shot command buffer: record, then submit and wait.
    VkCommandBuffer begin_one_shot() const;
    void submit_and_wait(VkCommandBuffer command_buffer) const;
    // Waits for `fence` (every fence wait of the program goes through here; vkDeviceWaitIdle, which has no
    // limit, is left where the device is all but idle: teardown, a new swapchain, an object replaced in the
    // viewer), at most kDeviceWaitSeconds of waiting: a device that never finishes
    // (lavapipe when it could not start its threads, under a limit on processes) made the program wait
    // forever. Past that it says so in one line and ends the process with exit status 1 (its work still
    // pending, nothing can be destroyed cleanly).
    void wait_for_fence(VkFence fence) const;

    uint32_t find_memory_type(uint32_t type_bits, VkMemoryPropertyFlags required,
                              VkMemoryPropertyFlags preferred = 0) const;

    // Bytes of device-local memory this process may still allocate: the budget minus what is in use
    // (VK_EXT_memory_budget) where the device offers it, and never more than the largest device-local heap
    // less what this context holds (lavapipe has no budget, and its figure did not shrink: a scene of a
    // thousand objects, each checked alone, grew to 5 GB). STIPPLE_GPU_MEMORY_LIMIT (e.g. 64M: how a smaller
    // device would refuse, tried on a big one) bounds what the context holds in all.
    uint64_t device_memory_available() const;
    // Bytes of memory this context's buffers and images hold now (the shared blocks whole: MemoryPool).
    uint64_t bytes_allocated() const { return allocated_bytes_.load(); }
    // Where buffers and images get their memory. The device's limit on allocations
    // (maxMemoryAllocationCount) is lowered by STIPPLE_GPU_ALLOCATION_LIMIT (e.g. 100: how a device that
    // allows few would refuse a crowd, tried on one that allows 2^32).
    MemoryPool& memory_pool() const { return *memory_pool_; }
    // The largest storage buffer a shader may read (maxStorageBufferRange). Lowered by
    // STIPPLE_MAX_STORAGE_BUFFER (e.g. 16M: how a device with a smaller limit draws large images in tiles).
    uint64_t max_storage_buffer_bytes() const;
    // The most pixels a frame's word buffers may hold: a word each, in a storage buffer that the compute
    // passes also read as texels (the lesser of max_storage_buffer_bytes / 4 and maxTexelBufferElements).
    uint64_t max_pixel_words() const;
    // The most workgroups a compute dispatch may have along x (maxComputeWorkGroupCount[0]); wider work goes
    // in rows along y (gpu::dispatch_groups, shaders/dispatch.h). Lowered by STIPPLE_MAX_WORKGROUPS (e.g. 7:
    // how a huge model is dispatched, tried on a small one).
    uint32_t max_groups_x() const { return max_groups_x_; }

    // Lists the devices Vulkan sees, "index: name (type)", for --help-style output and errors.
    static std::vector<std::string> list_devices();

private:
    void create_instance(const ContextOptions& options);
    void pick_physical_device(const ContextOptions& options);
    void create_device(const ContextOptions& options);

    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    bool memory_budget_ = false;  // VK_EXT_memory_budget enabled
    uint32_t max_groups_x_ = 65535;
    std::atomic<uint32_t> validation_messages_{0};
    mutable std::atomic<uint64_t> allocated_bytes_{0};
    std::unique_ptr<MemoryPool> memory_pool_;  // made with the device, freed before it
    static VKAPI_ATTR VkBool32 VKAPI_CALL debug_callback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                         VkDebugUtilsMessageTypeFlagsEXT types,
                                                         const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                         void* user);
};

// Validation messages seen by every Context this process made, alive or gone: a command whose own
// checks do not look (a probe device, a survey's contexts) still fails by it (main.cpp).
uint32_t validation_messages_in_process();

}  // namespace stipple::gpu
