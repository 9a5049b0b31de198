#pragma once
// Vulkan result checking: setup failures become exceptions that name the call.
#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>

namespace candela::render {

const char* vkResultName(VkResult result);

[[noreturn]] inline void throwVkError(const char* call, VkResult result) {
    throw std::runtime_error(std::string("Vulkan call failed: ") + call + " -> " +
                             vkResultName(result));
}

}  // namespace candela::render

#define CANDELA_VK_CHECK(call)                                        \
    do {                                                              \
        VkResult candelaVkResult_ = (call);                           \
        if (candelaVkResult_ != VK_SUCCESS) {                         \
            ::candela::render::throwVkError(#call, candelaVkResult_); \
        }                                                             \
    } while (false)
