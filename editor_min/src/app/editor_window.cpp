#include "app/editor_window.h"

#include <GLFW/glfw3.h>

#include <stdexcept>

namespace candela::editor {

EditorWindow::EditorWindow(uint32_t width, uint32_t height, const std::string& title) {
    if (!glfwInit()) {
        throw std::runtime_error("cannot open a window (no display; run under xvfb-run -a)");
    }
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        throw std::runtime_error("GLFW reports no Vulkan support");
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    window_ = glfwCreateWindow(int(width), int(height), title.c_str(), nullptr, nullptr);
    if (!window_) {
        glfwTerminate();
        throw std::runtime_error("window creation failed");
    }
}

EditorWindow::~EditorWindow() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

std::vector<std::string> EditorWindow::requiredInstanceExtensions() {
    uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    return std::vector<std::string>(names, names + count);
}

VkSurfaceKHR EditorWindow::createSurface(VkInstance instance) {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    if (glfwCreateWindowSurface(instance, window_, nullptr, &surface) != VK_SUCCESS) {
        throw std::runtime_error("glfwCreateWindowSurface failed");
    }
    return surface;
}

bool EditorWindow::shouldClose() const {
    return glfwWindowShouldClose(window_);
}

void EditorWindow::requestClose() {
    glfwSetWindowShouldClose(window_, GLFW_TRUE);
}

void EditorWindow::pollEvents() const {
    glfwPollEvents();
}

void EditorWindow::framebufferSize(uint32_t& width, uint32_t& height) const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    while ((w == 0 || h == 0) && !glfwWindowShouldClose(window_)) {
        glfwWaitEvents();
        glfwGetFramebufferSize(window_, &w, &h);
    }
    width = uint32_t(w > 0 ? w : 1);
    height = uint32_t(h > 0 ? h : 1);
}

}  // namespace candela::editor
