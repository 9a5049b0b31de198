#pragma once
// Rasterises the scene's meshes into the G-buffer, depth and the HDR target (emissive).
#include "candela/render/frame_scene.h"
#include "candela/render/pipeline.h"
#include "frame_graph/graph_resources.h"

namespace candela::render {

class GpuBuffer;
class GpuContext;
class SceneResources;
struct GBufferTargets;

class GBufferPass {
public:
    explicit GBufferPass(GpuContext& context);
    // Colour, HDR and depth in attachment-optimal layouts (frame graph: ColorAttachment,
    // DepthWrite); all are cleared. targets.extended picks gbuffer_extended.frag.
    void record(VkCommandBuffer cmd, const GBufferTargets& targets, const ImageRef& hdr,
                const std::array<float, 4>& clearRadiance, const FrameScene& scene,
                SceneResources& resources, const GpuBuffer& cameraBuffer) const;

private:
    Pipeline pipeline_;
    Pipeline extendedPipeline_;  // also writes targets.anisotropy and targets.clearCoat
};

}  // namespace candela::render
