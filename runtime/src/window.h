#pragma once
// A GLFW window with a Vulkan surface. Only the runtime knows about GLFW.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

struct GLFWwindow;

namespace candela::runtime {

class Window {
public:
    // Throws when GLFW cannot start (no display) or has no Vulkan support.
    Window(uint32_t width, uint32_t height, const std::string& title);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    static std::vector<std::string> requiredInstanceExtensions();

    VkSurfaceKHR createSurface(VkInstance instance);
    bool shouldClose() const;
    void pollEvents() const;
    // Blocks while minimised (0x0), so the swapchain is never created with a zero extent.
    void framebufferSize(uint32_t& width, uint32_t& height) const;
    bool consumeResized();

private:
    GLFWwindow* window_ = nullptr;
    bool resized_ = false;
};

}  // namespace candela::runtime
