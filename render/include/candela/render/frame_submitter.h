#pragma once
// One frame in flight: a command buffer, its fence, and the swapchain-acquire semaphore.
// One is enough here: on a CPU device the GPU and the CPU share the same cores anyway.
#include <vulkan/vulkan.h>

namespace candela::render {

class GpuContext;

class FrameSubmitter {
public:
    explicit FrameSubmitter(GpuContext& context);
    ~FrameSubmitter();
    FrameSubmitter(const FrameSubmitter&) = delete;
    FrameSubmitter& operator=(const FrameSubmitter&) = delete;

    // Waits for the previous frame, then resets and begins the command buffer.
    VkCommandBuffer begin();
    // Ends and submits; waits on `wait` at the transfer stage and signals `signal` if given.
    void submit(VkSemaphore wait = VK_NULL_HANDLE, VkSemaphore signal = VK_NULL_HANDLE);
    // Blocks until the last submission has finished on the device.
    void waitIdle();

    VkSemaphore imageAvailable() const { return imageAvailable_; }

private:
    GpuContext& context_;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
    VkSemaphore imageAvailable_ = VK_NULL_HANDLE;
    bool inFlight_ = false;
};

}  // namespace candela::render
