#include "candela/render/renderer.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "candela/render/gpu_context.h"
#include "candela/render/scene_resources.h"
#include "gbuffer_targets.h"
#include "gpu_camera.h"
#include "gpu_light.h"
#include "passes/gbuffer/gbuffer_pass.h"
#include "passes/lighting/lighting_pass.h"
#include "passes/tonemap/tonemap_pass.h"
#include "passes/triangle/triangle_pass.h"

namespace candela::render {

float exposureFromEv100(float ev100) {
    return 1.0f / (1.2f * std::exp2(ev100));
}

namespace {

// The shader variant a scene needs: only the shading models its drawn materials use and the
// light shapes its lights have.
LightingFeatures featuresOf(const FrameScene& scene, const SceneResources& resources) {
    LightingFeatures f;
    for (const DrawItem& draw : scene.draws) {
        switch (resources.material(draw.material).shadingModel) {
            case content::ShadingModel::Subsurface:
                f.subsurface = true;
                break;
            case content::ShadingModel::Legacy:
                f.legacyDiffuseSpecular = true;
                break;
            default:
                break;
        }
    }
    for (const LightInstance& l : scene.lights) {
        if (l.light.type == content::LightType::Directional) continue;
        f.sphereLights |= l.light.sourceRadius > 0.0f;
        f.tubeLights |= l.light.sourceLength > 0.0f;
        f.spotLights |= l.light.type == content::LightType::Spot;
    }
    return f;
}

}  // namespace

Renderer::Renderer(GpuContext& context, uint32_t width, uint32_t height)
    : context_(context),
      width_(width),
      height_(height),
      cameraBuffer_(context, sizeof(GpuCamera), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                    MemoryLocation::HostVisible),
      lightBuffer_(context, sizeof(GpuLight), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                   MemoryLocation::HostVisible) {
    createTargets();
    trianglePass_ = std::make_unique<TrianglePass>(context_);
    gbufferPass_ = std::make_unique<GBufferPass>(context_);
    lightingPass_ = std::make_unique<LightingPass>(context_);
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
    gbuffer_ = std::make_unique<GBufferTargets>(context_, width_, height_);
}

void Renderer::uploadFrameData(const FrameInputs& inputs) {
    const FrameScene& scene = inputs.scene;
    lightCount_ = uint32_t(scene.lights.size());
    VkDeviceSize lightBytes = std::max<VkDeviceSize>(lightCount_, 1) * sizeof(GpuLight);
    if (lightBuffer_.size() < lightBytes) {
        lightBuffer_ = GpuBuffer(context_, lightBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                 MemoryLocation::HostVisible);
    }
    auto* lights = static_cast<GpuLight*>(lightBuffer_.mapped());
    for (uint32_t i = 0; i < lightCount_; ++i)
        lights[i] = packLight(scene.lights[i]);

    GpuCamera camera{};
    camera.viewProjection = scene.camera.projection * scene.camera.view;
    camera.inverseViewProjection = glm::inverse(camera.viewProjection);
    camera.cameraPosition = glm::vec4(scene.camera.position, 1.0f);
    camera.frameInfo = glm::uvec4(width_, height_, lightCount_, 0u);
    std::memcpy(cameraBuffer_.mapped(), &camera, sizeof(camera));
}

void Renderer::recordScene(VkCommandBuffer cmd, const FrameInputs& inputs,
                           SceneResources& resources) {
    LightingFeatures features = featuresOf(inputs.scene, resources);
    lightingPass_->setFeatures(features);
    features_ = features.names();
    uploadFrameData(inputs);

    for (const GpuImage& image : gbuffer_->color) {
        transitionImage(cmd, image, VK_IMAGE_LAYOUT_UNDEFINED,
                        VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                        VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, 0,
                        VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                        VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    }
    transitionImage(
        cmd, gbuffer_->depth, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
        VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, 0,
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
        VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
            VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT);
    gbufferPass_->record(cmd, *gbuffer_, hdr_, inputs.clearRadiance, inputs.scene, resources,
                         cameraBuffer_);

    for (const GpuImage& image : gbuffer_->color) {
        transitionImage(
            cmd, image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
            VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    }
    transitionImage(cmd, gbuffer_->depth, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                    VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    transitionImage(cmd, hdr_, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                    VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                    VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    lightingPass_->record(cmd, *gbuffer_, hdr_, cameraBuffer_, lightBuffer_);
}

void Renderer::recordFrame(VkCommandBuffer cmd, const FrameInputs& inputs,
                           SceneResources* resources) {
    transitionImage(cmd, hdr_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                    VK_PIPELINE_STAGE_2_TRANSFER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, 0,
                    VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    if (inputs.testTriangleRadiance || !resources) {
        trianglePass_->record(cmd, hdr_, inputs.clearRadiance,
                              inputs.testTriangleRadiance.value_or(inputs.clearRadiance));
        features_ = {"test_triangle"};
        transitionImage(
            cmd, hdr_, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
            VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
    } else {
        recordScene(cmd, inputs, *resources);
    }
    features_.push_back("tonemap_aces");

    transitionImage(cmd, ldr_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                    VK_PIPELINE_STAGE_2_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                    VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    VkMemoryBarrier2 lit{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    lit.srcStageMask = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    lit.srcAccessMask = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
    lit.dstStageMask = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    lit.dstAccessMask = VK_ACCESS_2_SHADER_STORAGE_READ_BIT;
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.memoryBarrierCount = 1;
    dependency.pMemoryBarriers = &lit;
    vkCmdPipelineBarrier2(cmd, &dependency);
    tonemapPass_->record(cmd, hdr_, ldr_, exposureFromEv100(inputs.scene.camera.ev100));

    transitionImage(cmd, hdr_, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT,
                    VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
    transitionImage(cmd, ldr_, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                    VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
}

}  // namespace candela::render
