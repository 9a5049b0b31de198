#include "stats_overlay.h"

#include <algorithm>
#include <vector>

#include "candela/runtime/layer_pass_context.h"
#include "candela/runtime/window.h"
#include "candela/ui/imgui_layer.h"
#include "candela/ui/imgui_renderer.h"

namespace candela::runtime {

namespace {

// Median of the last `count` frame times: steadier to read than the latest one.
double recentMedianMs(const std::vector<double>& frameMs, size_t count) {
    if (frameMs.empty()) return 0.0;
    size_t n = std::min(count, frameMs.size());
    std::vector<double> recent(frameMs.end() - std::ptrdiff_t(n), frameMs.end());
    std::nth_element(recent.begin(), recent.begin() + std::ptrdiff_t(n / 2), recent.end());
    return recent[n / 2];
}

}  // namespace

StatsOverlay::StatsOverlay(bool headlessToo) : headlessToo_(headlessToo) {}

StatsOverlay::~StatsOverlay() = default;

void StatsOverlay::start(render::GpuContext& context, Window* window) {
    if (!window && !headlessToo_) return;
    layer_ = std::make_unique<ui::ImGuiLayer>(window ? window->glfwHandle() : nullptr);
    imgui_ = std::make_unique<ui::ImGuiRenderer>(context);
}

std::vector<render::TargetAccess> StatsOverlay::uses() const {
    if (!layer_) return {};
    return {{render::FrameTarget::Ldr, render::TargetUse::ColorAttachment}};
}

void StatsOverlay::prepare(const FrameContext& frame, const FrameStats& stats) {
    if (!layer_) return;
    layer_->beginFrame(float(frame.width), float(frame.height), float(frame.deltaSeconds));
    ImGui::SetNextWindowPos(ImVec2(8.0f, 8.0f));
    ImGui::SetNextWindowBgAlpha(0.6f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration |
                                   ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoNav |
                                   ImGuiWindowFlags_NoFocusOnAppearing;
    if (ImGui::Begin("Candela stats", nullptr, flags)) {
        if (stats.frames.empty()) {
            ImGui::TextUnformatted("first frame...");
        } else {
            // The previous frame's figures: this one has not rendered yet.
            const render::RendererStats& last = stats.frames.back();
            const double ms = recentMedianMs(stats.frameMs, 30);
            ImGui::Text("frame     %6.2f ms  (%.0f fps)", ms, ms > 0.0 ? 1000.0 / ms : 0.0);
            ImGui::Text("lights    %6u", last.lights);
            ImGui::Text("clusters  %6u / %u occupied", last.clustersOccupied, last.clusters);
            ImGui::Text("culling   %6.1f %% of evaluated pairs lit",
                        100.0 * cullingEfficiency(last));
            ImGui::Text("light assign %.2f ms, lighting %.2f ms", last.lightAssignMs,
                        last.lightingMs);
            // The frame graph's passes in execution order (GPU ms; the CPU assignment's CPU ms).
            if (ImGui::CollapsingHeader("passes")) {
                for (const auto& [name, passMs] : last.passMs) {
                    ImGui::Text("%-28s %7.2f ms", name.c_str(), passMs);
                }
            }
        }
        if (!frame.headless) ImGui::TextUnformatted("WASD/QE fly, shift fast, hold mouse: look");
    }
    ImGui::End();
    draw_ = layer_->endFrame();
}

void StatsOverlay::record(LayerPassContext& pass) {
    if (draw_)
        imgui_->recordInPass(pass.commandBuffer(), *draw_, pass.image(render::FrameTarget::Ldr));
}

void StatsOverlay::stop() {
    draw_ = nullptr;
    imgui_.reset();
    layer_.reset();
}

}  // namespace candela::runtime
