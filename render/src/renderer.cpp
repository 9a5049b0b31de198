#include "candela/render/renderer.h"

#include <cmath>

#include "candela/render/gpu_context.h"
#include "passes/tonemap/tonemap_pass.h"
#include "passes/triangle/triangle_pass.h"

namespace candela::render {

float exposureFromEv100(float ev100) {
    return 1.0f / (1.2f * std::exp2(ev100));
}

Renderer::Renderer(GpuContext& context, uint32_t width, uint32_t height)
    : context_(context), width_(width), height_(height) {
    createTargets();
    trianglePass_ = std::make_unique<TrianglePass>(context_);
    tonemapPass_ = std::make_unique<TonemapPass>(context_);
}

Renderer::~Renderer() = default;

void Renderer::resize(uint32_t width, uint32_t height) {
    width_ = width;
    height_ = height;
    createTargets();
}

void Renderer::createTargets() {
    // RGBA32F, not 16F: captures are compared at 1e-4..1e-5 relative, below half precision.
    hdr_ = GpuImage(context_, {VK_FORMAT_R32G32B32A32_SFLOAT, width_, height_, 1, false,
                               VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_STORAGE_BIT |
                                   VK_IMAGE_USAGE_TRANSFER_SRC_BIT});
    ldr_ = GpuImage(context_, {VK_FORMAT_R8G8B8A8_UNORM, width_, height_, 1, false,
                               VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT});
}

void Renderer::recordFrame(VkCommandBuffer cmd, const FrameInputs& inputs) {
    transitionImage(cmd, hdr_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                    VK_PIPELINE_STAGE_2_TRANSFER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, 0,
                    VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    trianglePass_->record(cmd, hdr_, inputs.clearRadiance, inputs.triangleRadiance);

    transitionImage(cmd, hdr_, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                    VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                    VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
    transitionImage(cmd, ldr_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                    VK_PIPELINE_STAGE_2_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                    VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    tonemapPass_->record(cmd, hdr_, ldr_, exposureFromEv100(inputs.ev100));

    transitionImage(cmd, hdr_, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT,
                    VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
    transitionImage(cmd, ldr_, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                    VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
}

std::vector<std::string> Renderer::features() const {
    return {"test_triangle", "tonemap_aces"};
}

}  // namespace candela::render
