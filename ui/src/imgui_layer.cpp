#include "candela/ui/imgui_layer.h"

#include <backends/imgui_impl_glfw.h>

namespace candela::ui {

ImGuiLayer::ImGuiLayer(GLFWwindow* window) : window_(window) {
    IMGUI_CHECKVERSION();
    context_ = ImGui::CreateContext();
    ImGui::SetCurrentContext(context_);
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.LogFilename = nullptr;
    ImGui::StyleColorsDark();
    // The draw pass uses a 32-bit vertex offset per command; ImDrawIdx stays 16-bit.
    io.BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset;
    // Install GLFW callbacks (chained to any the window already has).
    if (window_) ImGui_ImplGlfw_InitForVulkan(window_, true);
}

ImGuiLayer::~ImGuiLayer() {
    ImGui::SetCurrentContext(context_);
    if (window_) ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext(context_);
}

void ImGuiLayer::beginFrame(float width, float height, float deltaSeconds) {
    ImGui::SetCurrentContext(context_);
    ImGuiIO& io = ImGui::GetIO();
    if (window_) {
        ImGui_ImplGlfw_NewFrame();
        if (deltaSeconds > 0.0f) io.DeltaTime = deltaSeconds;
    } else {
        io.DisplaySize = ImVec2(width, height);
        io.DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
        io.DeltaTime = deltaSeconds > 0.0f ? deltaSeconds : 1.0f / 60.0f;
    }
    ImGui::NewFrame();
}

ImDrawData* ImGuiLayer::endFrame() {
    ImGui::SetCurrentContext(context_);
    ImGui::Render();
    return ImGui::GetDrawData();
}

}  // namespace candela::ui
