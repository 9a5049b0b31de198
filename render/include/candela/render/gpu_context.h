#pragma once
// The Vulkan instance, the chosen physical device, its logical device and one queue.
// Validation messages are counted so tests can fail on any of them.
#include <vulkan/vulkan.h>

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "candela/render/memory_allocation.h"
#include "candela/render/validation_mode.h"

namespace candela::render {

class MemoryAllocator;

struct GpuContextOptions {
    ValidationMode validation = ValidationMode::IfPresent;
    std::vector<std::string> instanceExtensions;  // e.g. what GLFW needs for a surface
    bool swapchain = false;                       // enable VK_KHR_swapchain on the device
    std::string preferredDevice;                  // substring of a device name; empty = best
    bool echoValidationMessages = true;           // print each message to stderr
};

class GpuContext {
public:
    explicit GpuContext(const GpuContextOptions& options);
    ~GpuContext();
    GpuContext(const GpuContext&) = delete;
    GpuContext& operator=(const GpuContext&) = delete;

    VkInstance instance() const { return instance_; }
    VkPhysicalDevice physicalDevice() const { return physicalDevice_; }
    VkDevice device() const { return device_; }
    VkQueue queue() const { return queue_; }
    uint32_t queueFamily() const { return queueFamily_; }
    const std::string& deviceName() const { return deviceName_; }
    bool validationEnabled() const { return messenger_ != VK_NULL_HANDLE; }
    const VkPhysicalDeviceProperties& properties() const { return properties_; }
    // Whether the device has geometry shaders (enabled when it does): GBAA's G-buffer variant
    // needs one to see each triangle's edges (lavapipe has them; it has no fragment-shader
    // barycentrics, VK_KHR/NV_fragment_shader_barycentric).
    bool geometryShaders() const { return geometryShaders_; }

    // Warnings and errors reported by the validation layer since start-up.
    uint32_t validationMessages() const { return validationMessages_.load(); }

    // Push descriptors (VK_KHR_push_descriptor) keep passes free of descriptor pools.
    PFN_vkCmdPushDescriptorSetKHR cmdPushDescriptorSet = nullptr;

    uint32_t findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required) const;

    // Where GpuBuffer and GpuImage get their memory (render/src/vk/memory_allocator.h).
    MemoryAllocator& memoryAllocator() { return *memoryAllocator_; }
    // Blocks, bytes obtained from Vulkan and bytes bound to live resources.
    MemoryStatistics memoryStatistics() const;

    // Records into a fresh command buffer, submits it and waits: for uploads and readbacks.
    void submitAndWait(const std::function<void(VkCommandBuffer)>& record);

    // Pipelines created since start-up and the wall-clock time their creation took (--stats
    // `pipelines`): on a CPU device, compiling shaders is most of a short run's cost.
    struct PipelineStatistics {
        uint32_t created = 0;
        double createMs = 0.0;
    };
    PipelineStatistics pipelineStatistics() const {
        return {pipelinesCreated_.load(), double(pipelineCreateNs_.load()) * 1e-6};
    }
    void notePipelineCreated(uint64_t nanoseconds) {
        pipelinesCreated_.fetch_add(1);
        pipelineCreateNs_.fetch_add(nanoseconds);
    }

private:
    void createInstance(const GpuContextOptions& options);
    void pickPhysicalDevice(const std::string& preferred);
    void createDevice(bool swapchain);

    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice_ = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties properties_{};
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    uint32_t queueFamily_ = 0;
    VkCommandPool oneShotPool_ = VK_NULL_HANDLE;
    std::unique_ptr<MemoryAllocator> memoryAllocator_;  // freed before the device
    std::string deviceName_;
    bool echoValidationMessages_ = true;
    bool geometryShaders_ = false;
    std::atomic<uint32_t> validationMessages_{0};
    std::atomic<uint32_t> pipelinesCreated_{0};
    std::atomic<uint64_t> pipelineCreateNs_{0};

    friend VKAPI_ATTR VkBool32 VKAPI_CALL
    onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT, VkDebugUtilsMessageTypeFlagsEXT,
                        const VkDebugUtilsMessengerCallbackDataEXT*, void*);
};

}  // namespace candela::render
