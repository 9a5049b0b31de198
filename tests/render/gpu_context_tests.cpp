// Device creation on whatever Vulkan 1.3 device exists (lavapipe in CI), validation on.
#include <gtest/gtest.h>

#include "candela/render/gpu_buffer.h"
#include "offscreen_frame.h"

using namespace candela::render;

TEST(GpuContext, CreatesDeviceWithValidation) {
    GpuContext context(test::requiredValidation());
    EXPECT_TRUE(context.validationEnabled());
    EXPECT_FALSE(context.deviceName().empty());
    EXPECT_GE(context.properties().apiVersion, VK_API_VERSION_1_3);
    EXPECT_NE(context.device(), VK_NULL_HANDLE);
    EXPECT_NE(context.cmdPushDescriptorSet, nullptr);
    EXPECT_EQ(context.validationMessages(), 0u);
}

TEST(GpuContext, PrefersNamedDevice) {
    GpuContextOptions options = test::requiredValidation();
    options.preferredDevice = "llvmpipe";
    GpuContext context(options);
    // Where lavapipe exists it is chosen by name; elsewhere the best device still comes up.
    EXPECT_FALSE(context.deviceName().empty());
}

// Proves the counter is wired: an invalid create-info must be reported, not ignored.
TEST(GpuContext, CountsValidationMessages) {
    GpuContextOptions options = test::requiredValidation();
    options.echoValidationMessages = false;
    GpuContext context(options);
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = 0;  // VUID-VkBufferCreateInfo-size-00912: size must be > 0
    info.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    VkBuffer buffer = VK_NULL_HANDLE;
    vkCreateBuffer(context.device(), &info, nullptr, &buffer);
    if (buffer) vkDestroyBuffer(context.device(), buffer, nullptr);
    EXPECT_GT(context.validationMessages(), 0u);
}

TEST(GpuContext, HostVisibleBufferIsMapped) {
    GpuContext context(test::requiredValidation());
    GpuBuffer buffer(context, 256, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryLocation::HostVisible);
    EXPECT_NE(buffer.mapped(), nullptr);
    GpuBuffer moved = std::move(buffer);
    EXPECT_EQ(buffer.handle(), VK_NULL_HANDLE);
    EXPECT_NE(moved.handle(), VK_NULL_HANDLE);
    EXPECT_EQ(context.validationMessages(), 0u);
}
