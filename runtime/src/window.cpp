#include "window.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <stdexcept>

namespace candela::runtime {

namespace {
void ensureGlfw() {
    static bool initialised = false;
    if (initialised) return;
    if (!glfwInit()) throw std::runtime_error("GLFW could not initialise (no display?)");
    if (!glfwVulkanSupported()) throw std::runtime_error("GLFW found no Vulkan loader");
    initialised = true;
}
}  // namespace

std::vector<std::string> Window::requiredInstanceExtensions() {
    ensureGlfw();
    uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    return std::vector<std::string>(names, names + count);
}

Window::Window(uint32_t width, uint32_t height, const std::string& title) {
    ensureGlfw();
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    window_ = glfwCreateWindow(int(width), int(height), title.c_str(), nullptr, nullptr);
    if (!window_) throw std::runtime_error("GLFW could not create a window");
    glfwSetWindowUserPointer(window_, this);
    glfwSetFramebufferSizeCallback(window_, [](GLFWwindow* w, int, int) {
        static_cast<Window*>(glfwGetWindowUserPointer(w))->resized_ = true;
    });
}

Window::~Window() {
    if (window_) glfwDestroyWindow(window_);
}

VkSurfaceKHR Window::createSurface(VkInstance instance) {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    if (glfwCreateWindowSurface(instance, window_, nullptr, &surface) != VK_SUCCESS) {
        throw std::runtime_error("GLFW could not create a Vulkan surface for the window");
    }
    return surface;
}

bool Window::shouldClose() const {
    return glfwWindowShouldClose(window_);
}

void Window::pollEvents() const {
    glfwPollEvents();
}

void Window::framebufferSize(uint32_t& width, uint32_t& height) const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    while ((w == 0 || h == 0) && !glfwWindowShouldClose(window_)) {
        glfwWaitEvents();
        glfwGetFramebufferSize(window_, &w, &h);
    }
    width = uint32_t(w > 0 ? w : 1);
    height = uint32_t(h > 0 ? h : 1);
}

bool Window::consumeResized() {
    bool was = resized_;
    resized_ = false;
    return was;
}

}  // namespace candela::runtime
