#include "window_surface.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <stdexcept>

namespace candela::runtime {

VkSurfaceKHR createWindowSurface(Window& window, VkInstance instance) {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    if (glfwCreateWindowSurface(instance, window.glfwHandle(), nullptr, &surface) != VK_SUCCESS) {
        throw std::runtime_error("GLFW could not create a Vulkan surface for the window");
    }
    return surface;
}

}  // namespace candela::runtime
