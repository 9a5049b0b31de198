#pragma once
// Owns the frame's render targets and passes, and records one frame into a command buffer:
// G-buffer (+ emissive) -> deferred lighting -> exposure + tonemap.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "candela/render/frame_inputs.h"
#include "candela/render/gpu_buffer.h"
#include "candela/render/gpu_image.h"

namespace candela::render {

class GpuContext;
class SceneResources;
class TonemapPass;
class TrianglePass;
class GBufferPass;
class LightingPass;
struct GBufferTargets;

class Renderer {
public:
    Renderer(GpuContext& context, uint32_t width, uint32_t height);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    void resize(uint32_t width, uint32_t height);
    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }

    // Records every pass of one frame. `resources` holds the meshes and materials the scene's
    // draws refer to (may be null when there are none). Afterwards both targets are in
    // TRANSFER_SRC_OPTIMAL, ready for capture or for a blit to the swapchain.
    void recordFrame(VkCommandBuffer cmd, const FrameInputs& inputs, SceneResources* resources);

    const GpuImage& hdrTarget() const { return hdr_; }  // RGBA32F scene radiance
    const GpuImage& ldrTarget() const { return ldr_; }  // RGBA8, sRGB-encoded values

    // What this renderer enabled for the last recorded frame, for --stats.
    std::vector<std::string> features() const { return features_; }

private:
    void createTargets();
    void recordScene(VkCommandBuffer cmd, const FrameInputs& inputs, SceneResources& resources);
    void uploadFrameData(const FrameInputs& inputs);

    GpuContext& context_;
    uint32_t width_;
    uint32_t height_;
    GpuImage hdr_;
    GpuImage ldr_;
    std::unique_ptr<GBufferTargets> gbuffer_;
    GpuBuffer cameraBuffer_;
    GpuBuffer lightBuffer_;
    uint32_t lightCount_ = 0;
    std::unique_ptr<TrianglePass> trianglePass_;
    std::unique_ptr<GBufferPass> gbufferPass_;
    std::unique_ptr<LightingPass> lightingPass_;
    std::unique_ptr<TonemapPass> tonemapPass_;
    std::vector<std::string> features_;
};

// Exposure scale for an EV100 (the same formula the shaders use).
float exposureFromEv100(float ev100);

}  // namespace candela::render
