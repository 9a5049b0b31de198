#pragma once
// Rasterises the scene's meshes into the G-buffer, depth and the HDR target (emissive).
#include "candela/render/frame_scene.h"
#include "candela/render/pipeline.h"

namespace candela::render {

class GpuBuffer;
class GpuContext;
class GpuImage;
class SceneResources;
struct GBufferTargets;

class GBufferPass {
public:
    explicit GBufferPass(GpuContext& context);
    // G-buffer colour, HDR and depth must be in attachment-optimal layouts.
    void record(VkCommandBuffer cmd, const GBufferTargets& targets, const GpuImage& hdr,
                const std::array<float, 4>& clearRadiance, const FrameScene& scene,
                SceneResources& resources, const GpuBuffer& cameraBuffer) const;

private:
    Pipeline pipeline_;
};

}  // namespace candela::render
