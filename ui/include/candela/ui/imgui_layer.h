#pragma once
// One Dear ImGui context, fed either by a GLFW window (mouse, keyboard, size) or headless
// (the caller gives the display size and drives input through ImGuiIO). Frames go:
//   layer.beginFrame(width, height, dt);  ImGui::Begin(...) ...;  ImDrawData* d = layer.endFrame();
// then ImGuiRenderer::record draws `d` onto an image.
#include <imgui.h>

struct GLFWwindow;

namespace candela::ui {

class ImGuiLayer {
public:
    // `window` null: headless. No imgui.ini is read or written, so runs are reproducible.
    explicit ImGuiLayer(GLFWwindow* window = nullptr);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    // Starts a frame. With a window, size and input come from GLFW and the arguments are
    // ignored except `deltaSeconds` when positive; headless, they set the display size and
    // the time step.
    void beginFrame(float width, float height, float deltaSeconds);
    // Finishes the frame; the returned data stays valid until the next beginFrame().
    ImDrawData* endFrame();

    ImGuiContext* context() const { return context_; }
    bool windowed() const { return window_ != nullptr; }

private:
    ImGuiContext* context_ = nullptr;
    GLFWwindow* window_ = nullptr;
};

}  // namespace candela::ui
