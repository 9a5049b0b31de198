// ImGui drawn onto the tonemapped image: pixels change exactly where the ImGui window is,
// the HDR capture is untouched, and the validation layer reports nothing.
#include <gtest/gtest.h>

#include <cstdlib>

#include "candela/render/frame_capture.h"
#include "candela/render/frame_inputs.h"
#include "candela/render/frame_submitter.h"
#include "candela/render/gpu_context.h"
#include "candela/render/renderer.h"
#include "candela/ui/imgui_layer.h"
#include "candela/ui/imgui_renderer.h"

namespace candela::ui {
namespace {

constexpr uint32_t kSize = 128;
// The ImGui window's rectangle in pixels.
constexpr int kLeft = 16, kTop = 24, kWidth = 72, kHeight = 56;

render::GpuContextOptions requiredValidation() {
    render::GpuContextOptions options;
    options.validation = render::ValidationMode::Required;
    return options;
}

// Renders one frame of `inputs`; when `ui` is given, draws it over the LDR target first.
render::CapturedFrame renderFrame(render::GpuContext& context, render::Renderer& renderer,
                                  const render::FrameInputs& inputs, ImGuiRenderer* ui,
                                  const ImDrawData* data) {
    render::FrameSubmitter submitter(context);
    render::FrameReadback readback(context, kSize, kSize);
    VkCommandBuffer cmd = renderer.recordFrame(submitter, inputs, nullptr);
    if (ui) ui->record(cmd, *data, renderer.ldrTarget(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    readback.recordCopy(cmd, renderer);
    submitter.submit();
    submitter.waitIdle();
    return readback.read();
}

bool insideWindow(uint32_t x, uint32_t y, int margin) {
    return int(x) >= kLeft - margin && int(x) < kLeft + kWidth + margin &&
           int(y) >= kTop - margin && int(y) < kTop + kHeight + margin;
}

TEST(ImGuiOverlay, DrawsTheWindowAndNothingElse) {
    render::GpuContext context(requiredValidation());
    render::Renderer renderer(context, kSize, kSize);
    render::FrameInputs inputs;
    inputs.clearRadiance = {0.5f, 0.5f, 0.5f, 1.0f};
    inputs.testTriangleRadiance = std::array<float, 4>{2.0f, 1.0f, 0.5f, 1.0f};

    ImGuiLayer layer;
    ImGuiRenderer ui(context);
    const render::CapturedFrame before = renderFrame(context, renderer, inputs, nullptr, nullptr);

    layer.beginFrame(float(kSize), float(kSize), 1.0f / 60.0f);
    ImGui::SetNextWindowPos(ImVec2(float(kLeft), float(kTop)));
    ImGui::SetNextWindowSize(ImVec2(float(kWidth), float(kHeight)));
    ImGui::Begin("panel", nullptr, ImGuiWindowFlags_NoSavedSettings);
    ImGui::TextUnformatted("Candela");
    ImGui::End();
    ImDrawData* data = layer.endFrame();
    ASSERT_GT(data->TotalVtxCount, 0);
    const render::CapturedFrame after = renderFrame(context, renderer, inputs, &ui, data);

    ASSERT_EQ(before.ldrRgba.size(), after.ldrRgba.size());
    uint32_t changedInside = 0, pixelsInside = 0;
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            const size_t i = (size_t(y) * kSize + x) * 4;
            bool differs = false;
            for (int c = 0; c < 3; ++c)
                differs |= before.ldrRgba[i + c] != after.ldrRgba[i + c];
            if (insideWindow(x, y, 0)) {
                ++pixelsInside;
                if (differs) ++changedInside;
            } else if (!insideWindow(x, y, 1)) {
                // One pixel of slack for the anti-aliased border.
                ASSERT_FALSE(differs) << "pixel " << x << "," << y << " outside the window changed";
            }
        }
    }
    // The window background (alpha 0.94) covers the whole rectangle.
    EXPECT_EQ(changedInside, pixelsInside);
    EXPECT_EQ(before.hdrRgb, after.hdrRgb) << "the UI must not touch the scene radiance";
    EXPECT_EQ(context.validationMessages(), 0u);
}

TEST(ImGuiOverlay, GrowsBuffersForLargeFramesWithoutValidationMessages) {
    render::GpuContext context(requiredValidation());
    render::Renderer renderer(context, kSize, kSize);
    render::FrameInputs inputs;
    ImGuiLayer layer;
    ImGuiRenderer ui(context);
    for (int frame = 0; frame < 3; ++frame) {
        layer.beginFrame(float(kSize), float(kSize), 1.0f / 60.0f);
        // Frame 0 is small; later frames hold 80,000 vertices: buffers grow past their first
        // 64 KiB and 16-bit indices need per-command vertex offsets.
        ImDrawList* list = ImGui::GetForegroundDrawList();
        const int rects = frame == 0 ? 1 : 20000;
        for (int r = 0; r < rects; ++r) {
            const float x = float(r % 100), y = float((r / 100) % 100);
            list->AddRectFilled(ImVec2(x, y), ImVec2(x + 8, y + 8), IM_COL32(255, 0, 0, 8));
        }
        ImDrawData* data = layer.endFrame();
        ASSERT_EQ(data->TotalVtxCount, rects * 4);
        const render::CapturedFrame captured = renderFrame(context, renderer, inputs, &ui, data);
        ASSERT_EQ(captured.ldrRgba.size(), size_t(kSize) * kSize * 4);
    }
    EXPECT_EQ(context.validationMessages(), 0u);
}

}  // namespace
}  // namespace candela::ui
