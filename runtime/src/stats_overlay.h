#pragma once
// The demo's on-screen statistics (Dear ImGui through candela::ui): frame time, lights,
// occupied clusters and culling efficiency, drawn over the frame in a window. Headless runs get
// the same figures from --stats / --summary; --overlay draws it headless too.
#include <memory>

#include "candela/runtime/application.h"

struct ImDrawData;

namespace candela::ui {
class ImGuiLayer;
class ImGuiRenderer;
}  // namespace candela::ui

namespace candela::runtime {

class StatsOverlay : public FrameLayer {
public:
    // `headlessToo`: draw without a window as well (otherwise the overlay is window-only).
    explicit StatsOverlay(bool headlessToo);
    ~StatsOverlay() override;

    std::string name() const override { return "stats_overlay"; }
    void start(render::GpuContext& context, Window* window) override;
    std::vector<render::TargetAccess> uses() const override;
    void prepare(const FrameContext& frame, const FrameStats& stats) override;
    void record(LayerPassContext& pass) override;
    void stop() override;

private:
    bool headlessToo_;
    std::unique_ptr<ui::ImGuiLayer> layer_;
    std::unique_ptr<ui::ImGuiRenderer> imgui_;
    const ImDrawData* draw_ = nullptr;  // prepare()'s, valid until the next prepare()
};

}  // namespace candela::runtime
