#include "candela/render/frame_submitter.h"

#include <cstdint>

#include "candela/render/gpu_context.h"
#include "vk/vk_check.h"

namespace candela::render {

FrameSubmitter::FrameSubmitter(GpuContext& context) : context_(context) {
    VkDevice device = context.device();
    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;  // reset whole, once per begin()
    poolInfo.queueFamilyIndex = context.queueFamily();
    CANDELA_VK_CHECK(vkCreateCommandPool(device, &poolInfo, nullptr, &pool_));
    VkCommandBufferAllocateInfo allocInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocInfo.commandPool = pool_;
    allocInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocInfo.commandBufferCount = 1;
    CANDELA_VK_CHECK(vkAllocateCommandBuffers(device, &allocInfo, &cmd_));
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    CANDELA_VK_CHECK(vkCreateFence(device, &fenceInfo, nullptr, &fence_));
    VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    CANDELA_VK_CHECK(vkCreateSemaphore(device, &semaphoreInfo, nullptr, &imageAvailable_));
}

FrameSubmitter::~FrameSubmitter() {
    VkDevice device = context_.device();
    waitIdle();
    vkDestroySemaphore(device, imageAvailable_, nullptr);
    vkDestroyFence(device, fence_, nullptr);
    vkDestroyCommandPool(device, pool_, nullptr);
}

void FrameSubmitter::waitIdle() {
    if (!inFlight_) return;
    CANDELA_VK_CHECK(vkWaitForFences(context_.device(), 1, &fence_, VK_TRUE, UINT64_MAX));
    CANDELA_VK_CHECK(vkResetFences(context_.device(), 1, &fence_));
    inFlight_ = false;
}

VkCommandBuffer FrameSubmitter::begin() {
    waitIdle();
    CANDELA_VK_CHECK(vkResetCommandPool(context_.device(), pool_, 0));
    VkCommandBufferBeginInfo beginInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    beginInfo.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    CANDELA_VK_CHECK(vkBeginCommandBuffer(cmd_, &beginInfo));
    return cmd_;
}

void FrameSubmitter::submit(VkSemaphore wait, VkSemaphore signal) {
    CANDELA_VK_CHECK(vkEndCommandBuffer(cmd_));
    VkCommandBufferSubmitInfo cmdInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
    cmdInfo.commandBuffer = cmd_;
    VkSemaphoreSubmitInfo waitInfo{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    waitInfo.semaphore = wait;
    waitInfo.stageMask = VK_PIPELINE_STAGE_2_TRANSFER_BIT;  // the swapchain blit
    VkSemaphoreSubmitInfo signalInfo{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    signalInfo.semaphore = signal;
    signalInfo.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    VkSubmitInfo2 submitInfo{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    submitInfo.commandBufferInfoCount = 1;
    submitInfo.pCommandBufferInfos = &cmdInfo;
    submitInfo.waitSemaphoreInfoCount = wait ? 1 : 0;
    submitInfo.pWaitSemaphoreInfos = &waitInfo;
    submitInfo.signalSemaphoreInfoCount = signal ? 1 : 0;
    submitInfo.pSignalSemaphoreInfos = &signalInfo;
    CANDELA_VK_CHECK(vkQueueSubmit2(context_.queue(), 1, &submitInfo, fence_));
    inFlight_ = true;
}

}  // namespace candela::render
