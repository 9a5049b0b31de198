#pragma once
// A GLFW window (its Vulkan surface: window_surface.h, inside the runtime). Only the runtime
// knows about GLFW; input reaches games as InputState.
#include <cstdint>
#include <string>
#include <vector>

#include "candela/runtime/input_state.h"

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

    bool shouldClose() const;
    void pollEvents() const;
    // Blocks while minimised (0x0), so the swapchain is never created with a zero extent.
    void framebufferSize(uint32_t& width, uint32_t& height) const;
    bool consumeResized();

    // Keyboard, mouse and the close button are written into `input` from now on (by
    // pollEvents); null stops it. The state must outlive the window or be unset first.
    void setInputTarget(InputState* input);
    // Hides the cursor and reports unbounded motion (mouse look); false restores it.
    void setCursorCaptured(bool captured);
    void setTitle(const std::string& title);
    // For libraries that take the GLFW window directly (the ImGui layer).
    GLFWwindow* glfwHandle() const { return window_; }

private:
    GLFWwindow* window_ = nullptr;
    bool resized_ = false;
    InputState* input_ = nullptr;
    bool hasCursor_ = false;
    double lastCursorX_ = 0.0, lastCursorY_ = 0.0;
};

}  // namespace candela::runtime
