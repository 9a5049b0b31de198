#include "app/editor_layer.h"

#include "candela/runtime/layer_pass_context.h"
#include "candela/runtime/window.h"
#include "candela/ui/imgui_layer.h"
#include "candela/ui/imgui_renderer.h"

namespace candela::editor {

EditorLayer::EditorLayer() = default;

EditorLayer::~EditorLayer() = default;

void EditorLayer::start(render::GpuContext& context, runtime::Window* window) {
    // After the window installed its input callbacks: ImGui's chain to them.
    context_ = std::make_unique<ui::ImGuiLayer>(window ? window->glfwHandle() : nullptr);
    renderer_ = std::make_unique<ui::ImGuiRenderer>(context);
}

std::vector<render::TargetAccess> EditorLayer::uses() const {
    if (!draw_) return {};
    return {{render::FrameTarget::Ldr, render::TargetUse::ColorAttachment}};
}

void EditorLayer::beginFrame(float width, float height, float deltaSeconds) {
    draw_ = nullptr;
    context_->beginFrame(width, height, deltaSeconds);
}

void EditorLayer::endFrame() {
    draw_ = context_->endFrame();
}

void EditorLayer::record(runtime::LayerPassContext& pass) {
    if (draw_) {
        renderer_->recordInPass(pass.commandBuffer(), *draw_, pass.image(render::FrameTarget::Ldr));
    }
}

void EditorLayer::stop() {
    draw_ = nullptr;
    renderer_.reset();
    context_.reset();
}

}  // namespace candela::editor
