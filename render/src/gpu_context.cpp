#include "candela/render/gpu_context.h"

#include <algorithm>
#include <cstdio>
#if defined(__SANITIZE_ADDRESS__)
#include <dlfcn.h>
#include <link.h>
#endif
#include <cstring>
#include <stdexcept>

#include "vk/memory_allocator.h"
#include "vk/vk_check.h"

namespace candela::render {

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool layerAvailable(const char* name) {
    uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    return std::any_of(layers.begin(), layers.end(), [&](const VkLayerProperties& l) {
        return std::strcmp(l.layerName, name) == 0;
    });
}

// Discrete GPUs first, lavapipe (a CPU device) last: the engine must also run with no GPU.
int deviceTypeRank(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
            return 4;
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
            return 3;
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
            return 2;
        case VK_PHYSICAL_DEVICE_TYPE_CPU:
            return 1;
        default:
            return 0;
    }
}

// LeakSanitizer checks at exit, after the loader has unloaded drivers and layers; their leaks
// then show as "<unknown module>" and cannot be suppressed by name. Marking the loaded Vulkan
// modules RTLD_NODELETE keeps them mapped, so tests/sanitizers/lsan.supp can name them.
void keepVulkanModulesLoadedForLeakReports() {
#if defined(__SANITIZE_ADDRESS__)
    dl_iterate_phdr(
        [](dl_phdr_info* info, size_t, void*) {
            const char* name = info->dlpi_name;
            if (name && (std::strstr(name, "vulkan") || std::strstr(name, "VkLayer"))) {
                dlopen(name, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
            }
            return 0;
        },
        nullptr);
#endif
}

}  // namespace

VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                   void* user) {
    auto* context = static_cast<GpuContext*>(user);
    context->validationMessages_.fetch_add(1);
    if (context->echoValidationMessages_) {
        const char* level =
            (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "error" : "warning";
        std::fprintf(stderr, "validation %s: %s\n", level, data->pMessage);
    }
    return VK_FALSE;
}

GpuContext::GpuContext(const GpuContextOptions& options)
    : echoValidationMessages_(options.echoValidationMessages) {
    createInstance(options);
    pickPhysicalDevice(options.preferredDevice);
    createDevice(options.swapchain);
    keepVulkanModulesLoadedForLeakReports();
}

GpuContext::~GpuContext() {
    if (device_) {
        vkDeviceWaitIdle(device_);
        vkDestroyCommandPool(device_, oneShotPool_, nullptr);
        memoryAllocator_.reset();
        vkDestroyDevice(device_, nullptr);
    }
    if (messenger_) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
        destroy(instance_, messenger_, nullptr);
    }
    if (instance_) vkDestroyInstance(instance_, nullptr);
}

void GpuContext::createInstance(const GpuContextOptions& options) {
    bool validation = false;
    if (options.validation != ValidationMode::Off) {
        validation = layerAvailable(kValidationLayer);
        if (!validation && options.validation == ValidationMode::Required) {
            throw std::runtime_error(
                "validation layer VK_LAYER_KHRONOS_validation is required but not installed "
                "(Debian package vulkan-validationlayers)");
        }
    }

    std::vector<const char*> extensions;
    for (const std::string& e : options.instanceExtensions)
        extensions.push_back(e.c_str());
    if (validation) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    std::vector<const char*> layers;
    if (validation) layers.push_back(kValidationLayer);

    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "candela";
    app.pEngineName = "candela";
    app.apiVersion = VK_API_VERSION_1_3;

    VkDebugUtilsMessengerCreateInfoEXT messengerInfo{
        VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messengerInfo.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                    VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messengerInfo.pfnUserCallback = onValidationMessage;
    messengerInfo.pUserData = this;

    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    info.enabledLayerCount = static_cast<uint32_t>(layers.size());
    info.ppEnabledLayerNames = layers.data();
    // Chained so that instance creation and destruction are validated too.
    if (validation) info.pNext = &messengerInfo;
    CANDELA_VK_CHECK(vkCreateInstance(&info, nullptr, &instance_));

    if (validation) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
        CANDELA_VK_CHECK(create(instance_, &messengerInfo, nullptr, &messenger_));
    }
}

void GpuContext::pickPhysicalDevice(const std::string& preferred) {
    uint32_t count = 0;
    vkEnumeratePhysicalDevices(instance_, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(instance_, &count, devices.data());

    int bestRank = -1;
    for (VkPhysicalDevice candidate : devices) {
        VkPhysicalDeviceProperties props;
        vkGetPhysicalDeviceProperties(candidate, &props);
        if (props.apiVersion < VK_API_VERSION_1_3) continue;  // dynamic rendering, sync2
        int rank = deviceTypeRank(props.deviceType);
        if (!preferred.empty() && std::strstr(props.deviceName, preferred.c_str())) rank += 10;
        if (rank > bestRank) {
            bestRank = rank;
            physicalDevice_ = candidate;
            properties_ = props;
        }
    }
    if (!physicalDevice_) {
        throw std::runtime_error(
            "no Vulkan 1.3 device found (install mesa-vulkan-drivers for lavapipe)");
    }
    deviceName_ = properties_.deviceName;
}

void GpuContext::createDevice(bool swapchain) {
    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice_, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice_, &familyCount, families.data());
    const VkQueueFlags needed = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    bool found = false;
    for (uint32_t i = 0; i < familyCount; ++i) {
        if ((families[i].queueFlags & needed) == needed) {
            queueFamily_ = i;
            found = true;
            break;
        }
    }
    if (!found) throw std::runtime_error(deviceName_ + " has no graphics+compute queue");

    float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = queueFamily_;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;

    VkPhysicalDeviceVulkan13Features features13{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    features13.dynamicRendering = VK_TRUE;
    features13.synchronization2 = VK_TRUE;
    features13.maintenance4 = VK_TRUE;  // glslang emits LocalSizeId for Vulkan 1.3 targets
    VkPhysicalDeviceVulkan12Features features12{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    features12.pNext = &features13;
    features12.hostQueryReset = VK_TRUE;
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    features.pNext = &features12;
    // The transparency occupancy pass records cluster boxes from fragment shaders.
    features.features.fragmentStoresAndAtomics = VK_TRUE;
    // GBAA's edge variant of the G-buffer pipelines (--aa gbaa) needs a geometry shader; only
    // frames that ask for it build one, enabling the feature costs the others nothing.
    VkPhysicalDeviceFeatures supported{};
    vkGetPhysicalDeviceFeatures(physicalDevice_, &supported);
    geometryShaders_ = supported.geometryShader == VK_TRUE;
    features.features.geometryShader = supported.geometryShader;

    std::vector<const char*> extensions{VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME};
    if (swapchain) extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);

    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.pNext = &features;
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queueInfo;
    info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    CANDELA_VK_CHECK(vkCreateDevice(physicalDevice_, &info, nullptr, &device_));
    vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
    cmdPushDescriptorSet = reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(
        vkGetDeviceProcAddr(device_, "vkCmdPushDescriptorSetKHR"));

    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    poolInfo.queueFamilyIndex = queueFamily_;
    CANDELA_VK_CHECK(vkCreateCommandPool(device_, &poolInfo, nullptr, &oneShotPool_));
    memoryAllocator_ = std::make_unique<MemoryAllocator>(physicalDevice_, device_);
}

uint32_t GpuContext::findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required) const {
    return memoryAllocator_->findMemoryType(typeBits, required);
}

MemoryStatistics GpuContext::memoryStatistics() const {
    return memoryAllocator_->statistics();
}

void GpuContext::submitAndWait(const std::function<void(VkCommandBuffer)>& record) {
    VkCommandBufferAllocateInfo allocInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocInfo.commandPool = oneShotPool_;
    allocInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocInfo.commandBufferCount = 1;
    VkCommandBuffer cmd;
    CANDELA_VK_CHECK(vkAllocateCommandBuffers(device_, &allocInfo, &cmd));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    CANDELA_VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
    record(cmd);
    CANDELA_VK_CHECK(vkEndCommandBuffer(cmd));
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    CANDELA_VK_CHECK(vkQueueSubmit(queue_, 1, &submit, VK_NULL_HANDLE));
    CANDELA_VK_CHECK(vkQueueWaitIdle(queue_));
    vkFreeCommandBuffers(device_, oneShotPool_, 1, &cmd);
}

}  // namespace candela::render
