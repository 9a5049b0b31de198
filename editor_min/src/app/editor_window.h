#pragma once
// The editor's GLFW window. The editor owns its GLFWwindow (unlike the runtime's Window) because
// ImGui's GLFW backend installs its input callbacks on it.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

struct GLFWwindow;

namespace candela::editor {

class EditorWindow {
public:
    // Throws with a clear message when there is no display or no Vulkan support.
    EditorWindow(uint32_t width, uint32_t height, const std::string& title);
    ~EditorWindow();
    EditorWindow(const EditorWindow&) = delete;
    EditorWindow& operator=(const EditorWindow&) = delete;

    static std::vector<std::string> requiredInstanceExtensions();
    VkSurfaceKHR createSurface(VkInstance instance);

    GLFWwindow* handle() const { return window_; }
    bool shouldClose() const;
    void requestClose();
    void pollEvents() const;
    // Blocks while minimised (0x0), so the swapchain never gets a zero extent.
    void framebufferSize(uint32_t& width, uint32_t& height) const;

private:
    GLFWwindow* window_ = nullptr;
};

}  // namespace candela::editor
