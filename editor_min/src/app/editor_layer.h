#pragma once
// The editor's ImGui frame on the runtime's loop: one FrameLayer whose pass draws the UI onto
// the LDR image (the frame graph places its barriers), so the viewport under it is exactly the
// frame `candela run` renders. The UI itself is built before the frame records (runEditor's
// before-render callback: it needs the extracted scene camera and picks the one rendered).
#include <memory>
#include <string>
#include <vector>

#include "candela/runtime/frame_layer.h"

struct ImDrawData;

namespace candela::ui {
class ImGuiLayer;
class ImGuiRenderer;
}  // namespace candela::ui

namespace candela::editor {

class EditorLayer : public runtime::FrameLayer {
public:
    EditorLayer();
    ~EditorLayer() override;

    std::string name() const override { return "editor_ui"; }
    void start(render::GpuContext& context, runtime::Window* window) override;
    std::vector<render::TargetAccess> uses() const override;
    void prepare(const runtime::FrameContext&, const runtime::FrameStats&) override {}
    void record(runtime::LayerPassContext& pass) override;
    void stop() override;

    bool started() const { return context_ != nullptr; }
    // Around the UI code of one frame (ImGui::Begin ...): the draw data endFrame() keeps is
    // what record() draws.
    void beginFrame(float width, float height, float deltaSeconds);
    void endFrame();

private:
    std::unique_ptr<ui::ImGuiLayer> context_;
    std::unique_ptr<ui::ImGuiRenderer> renderer_;
    const ImDrawData* draw_ = nullptr;
};

}  // namespace candela::editor
