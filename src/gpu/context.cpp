#include "gpu/context.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "core/decimal.hpp"
#include "core/error.hpp"
#include "core/memory.hpp"
#include "gpu/memory_pool.hpp"
#include "gpu/vk_check.hpp"

namespace stipple::gpu {

namespace {

const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

std::atomic<uint32_t> g_validation_messages_in_process{0};

bool layer_available(const char* name) {
    uint32_t count = 0;
    VK_CHECK(vkEnumerateInstanceLayerProperties(&count, nullptr));
    std::vector<VkLayerProperties> layers(count);
    VK_CHECK(vkEnumerateInstanceLayerProperties(&count, layers.data()));
    for (const auto& layer : layers)
        if (std::strcmp(layer.layerName, name) == 0) return true;
    return false;
}

const char* device_type_name(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete GPU";
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated GPU";
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual GPU";
        case VK_PHYSICAL_DEVICE_TYPE_CPU: return "CPU";
        default: return "other";
    }
}

int device_type_rank(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 4;
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 3;
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
        case VK_PHYSICAL_DEVICE_TYPE_CPU: return 1;
        default: return 0;
    }
}

std::vector<VkPhysicalDevice> enumerate_devices(VkInstance instance) {
    uint32_t count = 0;
    VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
    std::vector<VkPhysicalDevice> devices(count);
    VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, devices.data()));
    return devices;
}

}  // namespace

bool ContextOptions::default_validation() {
    // Strict, as the other STIPPLE_* settings: "yes" or "off" read as on (anything but "0") hid a typo.
    if (const char* env = std::getenv("STIPPLE_VALIDATION"); env && *env) {
        if (std::strcmp(env, "1") == 0) return true;
        if (std::strcmp(env, "0") == 0) return false;
        fail(std::string("STIPPLE_VALIDATION=") + env + " must be 1 (validation on) or 0 (off)");
    }
#ifdef NDEBUG
    return false;
#else
    return true;
#endif
}

// STIPPLE_MAX_WORKGROUPS, read before anything is created (a typo fails without a device to clean up); 0 when unset.
static uint32_t workgroups_from_environment() {
    const char* text = std::getenv("STIPPLE_MAX_WORKGROUPS");
    if (!text || !*text) return 0;
    char* end = nullptr;
    const unsigned long long limit = std::strtoull(text, &end, 10);
    // A test setting: a typo must not silently test nothing.
    if (end == text || *end != '\0' || text[0] == '-' || limit < 1 || limit > 0xFFFFFFFFull)
        fail(std::string("STIPPLE_MAX_WORKGROUPS=") + text + " is not a workgroup count such as 7");
    return uint32_t(limit);
}

// STIPPLE_GPU_ALLOCATION_LIMIT (a test setting: how a device that allows few allocations refuses), 0 when unset.
// Read before the device is made: a refusal from the constructor after it would leak the device.
static uint32_t allocation_limit_from_environment() {
    const char* text = std::getenv("STIPPLE_GPU_ALLOCATION_LIMIT");
    if (!text || !*text) return 0;
    char* end = nullptr;
    const unsigned long long count = std::strtoull(text, &end, 10);
    // A typo must not silently test nothing.
    if (*end != '\0' || count < 1 || count > 0xFFFFFFFFull || text[0] == '-')
        fail(std::string("STIPPLE_GPU_ALLOCATION_LIMIT=") + text + " is not a count of allocations such as 100");
    return uint32_t(count);
}

// Allocations made outside the pool (the viewer's Dear ImGui backend: its font image and its frames' vertex
// and index buffers) are left room under the device's limit.
constexpr uint32_t kAllocationsOutsideThePool = 16;

Context::Context(const ContextOptions& options) {
    // Under an address-space limit (ulimit -v) too small for the driver, lavapipe's compiler crashed the
    // process in pipeline creation (a segmentation fault, no message): refused here in one line instead.
    if (const std::optional<uint64_t> limit = address_space_limit(); limit && *limit < kDriverAddressSpace)
        fail("the address-space limit (ulimit -v) is " + byte_size(*limit) + ", below the " + byte_size(kDriverAddressSpace) +
             " the Vulkan driver and its shader compiler need (lavapipe reserves about 1 GiB): raise it");
    // The loader needs a runtime dir on some set-ups; an unset XDG_RUNTIME_DIR only causes warnings.
    const uint32_t asked_groups_x = workgroups_from_environment();
    const uint32_t asked_allocations = allocation_limit_from_environment();
    create_instance(options);
    pick_physical_device(options);
    create_device(options);
    const uint32_t device_allocations = properties.limits.maxMemoryAllocationCount;
    const uint32_t allocations = asked_allocations ? std::min(asked_allocations, device_allocations)
                                                   : device_allocations - std::min(kAllocationsOutsideThePool, device_allocations / 2);
    memory_pool_ = std::make_unique<MemoryPool>(device, memory_properties, properties.limits.nonCoherentAtomSize, allocations,
                                                allocated_bytes_);
    const uint32_t device_groups_x = properties.limits.maxComputeWorkGroupCount[0];
    max_groups_x_ = asked_groups_x ? std::min(asked_groups_x, device_groups_x) : device_groups_x;
}

uint32_t validation_messages_in_process() { return g_validation_messages_in_process.load(); }

Context::~Context() {
    if (device) {
        vkDeviceWaitIdle(device);
        memory_pool_.reset();
        if (command_pool) vkDestroyCommandPool(device, command_pool, nullptr);
        vkDestroyDevice(device, nullptr);
    }
    if (messenger_) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy) destroy(instance, messenger_, nullptr);
    }
    if (instance) vkDestroyInstance(instance, nullptr);
}

VKAPI_ATTR VkBool32 VKAPI_CALL Context::debug_callback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                       VkDebugUtilsMessageTypeFlagsEXT,
                                                       const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    if (severity < VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) return VK_FALSE;
    auto* context = static_cast<Context*>(user);
    context->validation_messages_.fetch_add(1);
    g_validation_messages_in_process.fetch_add(1);
    std::fprintf(stderr, "vulkan validation: %s\n", data->pMessage ? data->pMessage : "(no message)");
    return VK_FALSE;
}

void Context::create_instance(const ContextOptions& options) {
    std::vector<const char*> extensions = options.instance_extensions;
    std::vector<const char*> layers;
    bool validation = options.validation;
    if (validation) {
        if (!layer_available(kValidationLayer))
            fail(std::string("validation was requested but ") + kValidationLayer +
                 " is not installed (apt-get install vulkan-validationlayers, or set STIPPLE_VALIDATION=0)");
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    }

    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "stipple";
    app.apiVersion = VK_API_VERSION_1_3;

    VkDebugUtilsMessengerCreateInfoEXT messenger_info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messenger_info.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger_info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                 VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                 VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messenger_info.pfnUserCallback = debug_callback;
    messenger_info.pUserData = this;

    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pNext = validation ? &messenger_info : nullptr;  // also catches messages of create/destroy
    info.pApplicationInfo = &app;
    info.enabledLayerCount = uint32_t(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VkResult result = vkCreateInstance(&info, nullptr, &instance);
    if (result == VK_ERROR_INCOMPATIBLE_DRIVER)
        fail("no Vulkan 1.3 driver found (on a machine without a GPU install mesa-vulkan-drivers for lavapipe)");
    VK_CHECK(result);

    if (validation) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
        if (!create) fail("VK_EXT_debug_utils is missing although the validation layer is present");
        VK_CHECK(create(instance, &messenger_info, nullptr, &messenger_));
    }
}

void Context::pick_physical_device(const ContextOptions& options) {
    std::vector<VkPhysicalDevice> devices = enumerate_devices(instance);
    if (devices.empty()) fail("no Vulkan device found (install mesa-vulkan-drivers for lavapipe)");
    if (options.device_index >= 0) {
        if (options.device_index >= int(devices.size()))
            fail("--device " + std::to_string(options.device_index) + " is out of range: there are " +
                 std::to_string(devices.size()) + " Vulkan devices (0.." + std::to_string(devices.size() - 1) + ")");
        physical_device = devices[size_t(options.device_index)];
    } else {
        int best_rank = -1;
        for (VkPhysicalDevice candidate : devices) {
            VkPhysicalDeviceProperties props;
            vkGetPhysicalDeviceProperties(candidate, &props);
            if (props.apiVersion < VK_API_VERSION_1_3) continue;
            int rank = device_type_rank(props.deviceType);
            if (rank > best_rank) best_rank = rank, physical_device = candidate;
        }
        if (!physical_device) fail("no Vulkan 1.3 device found");
    }
    vkGetPhysicalDeviceProperties(physical_device, &properties);
    vkGetPhysicalDeviceMemoryProperties(physical_device, &memory_properties);
    if (properties.apiVersion < VK_API_VERSION_1_3)
        fail(std::string("device '") + properties.deviceName + "' supports only Vulkan " +
             std::to_string(VK_API_VERSION_MAJOR(properties.apiVersion)) + "." +
             std::to_string(VK_API_VERSION_MINOR(properties.apiVersion)) + "; stipple needs 1.3");
    device_name = properties.deviceName;

    uint32_t family_count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical_device, &family_count, nullptr);
    std::vector<VkQueueFamilyProperties> families(family_count);
    vkGetPhysicalDeviceQueueFamilyProperties(physical_device, &family_count, families.data());
    bool found = false;
    for (uint32_t i = 0; i < family_count && !found; ++i) {
        const VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
        if ((families[i].queueFlags & need) == need) queue_family = i, found = true;
        features.timestamps = found && families[i].timestampValidBits > 0;
        features.timestamp_valid_bits = families[i].timestampValidBits;
    }
    if (!found) fail(std::string("device '") + device_name + "' has no graphics+compute queue");
    if (options.verbose)
        std::fprintf(stderr, "stipple: using Vulkan device '%s' (%s)\n", device_name.c_str(),
                     device_type_name(properties.deviceType));
}

// A depth format with a stencil (the coverage stencil) that can be copied out (the compute splat).
// 24-bit unorm first: it is what the paper's hardware had, and on lavapipe a 32-bit float depth with
// a stencil is stored in 8 bytes per pixel, which made every depth pass about 4 ms slower at 1280x1024.
static VkFormat choose_depth_format(VkPhysicalDevice physical_device) {
    const VkFormatFeatureFlags needed =
        VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_FORMAT_FEATURE_TRANSFER_SRC_BIT |
        VK_FORMAT_FEATURE_TRANSFER_DST_BIT;  // also copied in (the depth pass as compute)
    for (VkFormat format : {VK_FORMAT_D24_UNORM_S8_UINT, VK_FORMAT_D32_SFLOAT_S8_UINT}) {
        VkFormatProperties properties{};
        vkGetPhysicalDeviceFormatProperties(physical_device, format, &properties);
        if ((properties.optimalTilingFeatures & needed) == needed) return format;
    }
    fail("the device has no depth format with a stencil that can be drawn to and copied");
}

void Context::create_device(const ContextOptions& options) {
    VkPhysicalDeviceFeatures supported{};
    vkGetPhysicalDeviceFeatures(physical_device, &supported);
    VkPhysicalDeviceVulkan12Features supported12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceVulkan13Features supported13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    supported12.pNext = &supported13;
    VkPhysicalDeviceFeatures2 supported2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    supported2.pNext = &supported12;
    vkGetPhysicalDeviceFeatures2(physical_device, &supported2);
    if (!supported13.dynamicRendering || !supported13.synchronization2)
        fail("device '" + device_name + "' lacks dynamic rendering or synchronization2");
    // Compute passes that append to a list do one atomic per subgroup (ballot, and the prefix sums of
    // the survivors' list), not one per item.
    VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
    VkPhysicalDeviceProperties2 properties2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    properties2.pNext = &subgroup;
    vkGetPhysicalDeviceProperties2(physical_device, &properties2);
    if (!(subgroup.supportedStages & VK_SHADER_STAGE_COMPUTE_BIT) ||
        !(subgroup.supportedOperations & VK_SUBGROUP_FEATURE_BALLOT_BIT) ||
        !(subgroup.supportedOperations & VK_SUBGROUP_FEATURE_ARITHMETIC_BIT))
        fail("device '" + device_name + "' lacks subgroup ballot or arithmetic operations in compute shaders");

    VkPhysicalDeviceFeatures enabled{};
    enabled.largePoints = supported.largePoints;
    enabled.wideLines = supported.wideLines;
    enabled.pipelineStatisticsQuery = supported.pipelineStatisticsQuery;
    enabled.vertexPipelineStoresAndAtomics = supported.vertexPipelineStoresAndAtomics;
    enabled.fragmentStoresAndAtomics = supported.fragmentStoresAndAtomics;
    enabled.multiDrawIndirect = supported.multiDrawIndirect;
    enabled.depthBiasClamp = supported.depthBiasClamp;
    enabled.shaderInt64 = supported.shaderInt64;  // the depth pass as compute (shaders/depth_raster.comp)
    VkPhysicalDeviceVulkan12Features enabled12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    enabled12.hostQueryReset = supported12.hostQueryReset;
    enabled12.shaderFloat16 = VK_FALSE;
    VkPhysicalDeviceVulkan13Features enabled13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    enabled13.dynamicRendering = VK_TRUE;
    enabled13.synchronization2 = VK_TRUE;
    enabled12.pNext = &enabled13;

    features.large_points = supported.largePoints;
    features.wide_lines = supported.wideLines;
    features.int64 = supported.shaderInt64;
    features.pipeline_statistics = supported.pipelineStatisticsQuery;
    features.max_point_size = supported.largePoints ? properties.limits.pointSizeRange[1] : 1.0f;
    features.max_line_width = supported.wideLines ? properties.limits.lineWidthRange[1] : 1.0f;
    features.timestamp_period_ns = properties.limits.timestampPeriod;
    features.timestamps = features.timestamps && properties.limits.timestampComputeAndGraphics;
    auto reads_uniform_texels = [&](VkFormat format) {
        VkFormatProperties format_properties{};
        vkGetPhysicalDeviceFormatProperties(physical_device, format, &format_properties);
        return (format_properties.bufferFeatures & VK_FORMAT_FEATURE_UNIFORM_TEXEL_BUFFER_BIT) != 0;
    };
    features.vec3_texels =
        reads_uniform_texels(VK_FORMAT_R32G32B32_SFLOAT) && reads_uniform_texels(VK_FORMAT_R32G32B32_UINT);
    depth_format = choose_depth_format(physical_device);

    float priority = 1.0f;
    VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queue_info.queueFamilyIndex = queue_family;
    queue_info.queueCount = 1;
    queue_info.pQueuePriorities = &priority;

    std::vector<const char*> extensions;
    if (options.swapchain) extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    // How much memory is left, for a clear message before an object that cannot fit is uploaded.
    uint32_t available_count = 0;
    VK_CHECK(vkEnumerateDeviceExtensionProperties(physical_device, nullptr, &available_count, nullptr));
    std::vector<VkExtensionProperties> available(available_count);
    VK_CHECK(vkEnumerateDeviceExtensionProperties(physical_device, nullptr, &available_count, available.data()));
    available.resize(available_count);
    for (const VkExtensionProperties& e : available)
        if (std::strcmp(e.extensionName, VK_EXT_MEMORY_BUDGET_EXTENSION_NAME) == 0) memory_budget_ = true;
    if (memory_budget_) extensions.push_back(VK_EXT_MEMORY_BUDGET_EXTENSION_NAME);

    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.pNext = &enabled12;
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queue_info;
    info.pEnabledFeatures = &enabled;
    info.enabledExtensionCount = uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VK_CHECK(vkCreateDevice(physical_device, &info, nullptr, &device));
    vkGetDeviceQueue(device, queue_family, 0, &queue);

    VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool_info.queueFamilyIndex = queue_family;
    VK_CHECK(vkCreateCommandPool(device, &pool_info, nullptr, &command_pool));
}

VkCommandBuffer Context::begin_one_shot() const {
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = command_pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cb = VK_NULL_HANDLE;
    VK_CHECK(vkAllocateCommandBuffers(device, &alloc, &cb));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(cb, &begin));
    return cb;
}

void Context::submit_and_wait(VkCommandBuffer cb) const {
    VK_CHECK(vkEndCommandBuffer(cb));
    VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence = VK_NULL_HANDLE;
    VK_CHECK(vkCreateFence(device, &fence_info, nullptr, &fence));
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cb;
    VkResult result = vkQueueSubmit(queue, 1, &submit, fence);
    if (result == VK_SUCCESS) {
        try {
            wait_for_fence(fence);
        } catch (...) {  // a lost device: what was made here is still freed
            vkDestroyFence(device, fence, nullptr);
            vkFreeCommandBuffers(device, command_pool, 1, &cb);
            throw;
        }
    }
    vkDestroyFence(device, fence, nullptr);
    vkFreeCommandBuffers(device, command_pool, 1, &cb);
    VK_CHECK(result);
}

void Context::wait_for_fence(VkFence fence) const {
    // In slices, and only slices that ran out count: a process stopped meanwhile (Ctrl-Z, a debugger, a job
    // scheduler) finds at most one slice run out when it resumes, not the whole limit spent.
    constexpr int kSliceSeconds = 5;
    for (int slices = 0; slices < kDeviceWaitSeconds / kSliceSeconds; ++slices) {
        const VkResult result = vkWaitForFences(device, 1, &fence, VK_TRUE, uint64_t(kSliceSeconds) * 1000000000ull);
        if (result == VK_TIMEOUT) continue;
        VK_CHECK(result);
        return;
    }
    std::fflush(stdout);  // what was said so far ("wrote ..." lines) is kept
    std::fprintf(stderr, "stipple: the Vulkan device did not finish its work within %d s (a driver that could not "
                         "start its threads, under a limit on processes such as ulimit -u?)\n", kDeviceWaitSeconds);
    std::fflush(stderr);
    std::_Exit(1);
}

// A size in bytes from an environment variable ("64M", "2G", "512k" or bytes: parse_byte_size); 0 when unset.
static uint64_t size_from_environment(const char* name) {
    const char* text = std::getenv(name);
    if (!text || !*text) return 0;  // unset, or set to nothing
    const std::optional<uint64_t> bytes = parse_byte_size(text);
    // A test setting: a typo must not silently test nothing.
    if (!bytes || *bytes < 1)
        fail(std::string(name) + "=" + text + " is not a size such as 64M (bytes, or a number with k, M or G)");
    return *bytes;
}

uint64_t Context::device_memory_available() const {
    VkPhysicalDeviceMemoryBudgetPropertiesEXT budget{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MEMORY_BUDGET_PROPERTIES_EXT};
    VkPhysicalDeviceMemoryProperties2 properties2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MEMORY_PROPERTIES_2};
    if (memory_budget_) properties2.pNext = &budget;
    vkGetPhysicalDeviceMemoryProperties2(physical_device, &properties2);
    const uint64_t held = bytes_allocated();
    const auto less_held = [&](uint64_t total) { return total > held ? total - held : 0; };
    uint64_t best = 0;
    for (uint32_t h = 0; h < memory_properties.memoryHeapCount; ++h) {
        if (!(memory_properties.memoryHeaps[h].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)) continue;
        uint64_t left = less_held(memory_properties.memoryHeaps[h].size);
        if (memory_budget_)
            left = std::min(left, budget.heapBudget[h] > budget.heapUsage[h] ? budget.heapBudget[h] - budget.heapUsage[h] : 0);
        best = std::max(best, left);
    }
    if (const uint64_t limit = size_from_environment("STIPPLE_GPU_MEMORY_LIMIT")) best = std::min(best, less_held(limit));
    return best;
}

uint64_t Context::max_storage_buffer_bytes() const {
    const uint64_t device = properties.limits.maxStorageBufferRange;
    const uint64_t limit = size_from_environment("STIPPLE_MAX_STORAGE_BUFFER");
    return limit ? std::min(device, limit) : device;
}

uint64_t Context::max_pixel_words() const {
    return std::min<uint64_t>(max_storage_buffer_bytes() / 4u, properties.limits.maxTexelBufferElements);
}

uint32_t Context::find_memory_type(uint32_t type_bits, VkMemoryPropertyFlags required,
                                   VkMemoryPropertyFlags preferred) const {
    for (int pass = 0; pass < 2; ++pass) {
        VkMemoryPropertyFlags want = pass == 0 ? (required | preferred) : required;
        for (uint32_t i = 0; i < memory_properties.memoryTypeCount; ++i)
            if ((type_bits & (1u << i)) && (memory_properties.memoryTypes[i].propertyFlags & want) == want) return i;
    }
    fail("no Vulkan memory type with the required properties");
}

std::vector<std::string> Context::list_devices() {
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.apiVersion = VK_API_VERSION_1_3;
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    VkInstance instance = VK_NULL_HANDLE;
    VK_CHECK(vkCreateInstance(&info, nullptr, &instance));
    std::vector<std::string> names;
    std::vector<VkPhysicalDevice> devices = enumerate_devices(instance);
    for (size_t i = 0; i < devices.size(); ++i) {
        VkPhysicalDeviceProperties props;
        vkGetPhysicalDeviceProperties(devices[i], &props);
        names.push_back(std::to_string(i) + ": " + props.deviceName + " (" + device_type_name(props.deviceType) + ")");
    }
    vkDestroyInstance(instance, nullptr);
    return names;
}

}  // namespace stipple::gpu
