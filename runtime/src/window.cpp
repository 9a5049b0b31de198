#include "candela/runtime/window.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <stdexcept>

#include "window_key_map.h"

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

bool Window::shouldClose() const {
    return glfwWindowShouldClose(window_);
}

void Window::pollEvents() const {
    glfwPollEvents();
    if (!input_) return;
    if (glfwWindowShouldClose(window_)) input_->closeRequested = true;
    static_assert(kGamepadButtonCount == GLFW_GAMEPAD_BUTTON_LAST + 1);
    static_assert(kGamepadAxisCount == GLFW_GAMEPAD_AXIS_LAST + 1);
    // The first joystick GLFW's mapping database knows as a gamepad; GLFW polls joysticks
    // rather than sending events for them.
    GLFWgamepadstate pad;
    if (glfwJoystickIsGamepad(GLFW_JOYSTICK_1) && glfwGetGamepadState(GLFW_JOYSTICK_1, &pad)) {
        for (std::size_t b = 0; b < kGamepadButtonCount; ++b)
            input_->setButton(GamepadButton(b), pad.buttons[b] == GLFW_PRESS);
        for (std::size_t a = 0; a < kGamepadAxisCount; ++a)
            input_->setAxis(GamepadAxis(a), pad.axes[a]);
    }
}

void Window::setInputTarget(InputState* input) {
    input_ = input;
    hasCursor_ = false;
    if (!input) {
        glfwSetKeyCallback(window_, nullptr);
        glfwSetMouseButtonCallback(window_, nullptr);
        glfwSetCursorPosCallback(window_, nullptr);
        return;
    }
    glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int) {
        Window* window = static_cast<Window*>(glfwGetWindowUserPointer(w));
        std::optional<Key> mapped = keyFromGlfw(key);
        if (!mapped || !window->input_ || action == GLFW_REPEAT) return;
        window->input_->setKey(*mapped, action == GLFW_PRESS);
    });
    glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int) {
        Window* window = static_cast<Window*>(glfwGetWindowUserPointer(w));
        std::optional<MouseButton> mapped = mouseButtonFromGlfw(button);
        if (!mapped || !window->input_) return;
        window->input_->setButton(*mapped, action == GLFW_PRESS);
    });
    glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double x, double y) {
        Window* window = static_cast<Window*>(glfwGetWindowUserPointer(w));
        if (!window->input_) return;
        // The first position after a (re)start is a jump, not a motion.
        if (window->hasCursor_) {
            window->input_->mouseDeltaX += float(x - window->lastCursorX_);
            window->input_->mouseDeltaY += float(y - window->lastCursorY_);
        }
        window->hasCursor_ = true;
        window->lastCursorX_ = x;
        window->lastCursorY_ = y;
        window->input_->mouseX = float(x);
        window->input_->mouseY = float(y);
    });
}

void Window::setCursorCaptured(bool captured) {
    glfwSetInputMode(window_, GLFW_CURSOR, captured ? GLFW_CURSOR_DISABLED : GLFW_CURSOR_NORMAL);
    if (captured && glfwRawMouseMotionSupported()) {
        glfwSetInputMode(window_, GLFW_RAW_MOUSE_MOTION, GLFW_TRUE);
    }
    hasCursor_ = false;
}

void Window::setTitle(const std::string& title) {
    glfwSetWindowTitle(window_, title.c_str());
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
