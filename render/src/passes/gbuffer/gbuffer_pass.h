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
    // Whether this frame's opaque draws include a layered material: picks the variants that
    // blend material layers (built on first use, so frames without layers never pay for them).
    void prepare(bool materialLayers);
    bool materialLayers() const { return materialLayers_; }
    // Colour, motion, HDR and depth in attachment-optimal layouts (frame graph:
    // ColorAttachment, DepthWrite); all are cleared. `previousWorlds`: one mat4 per scene draw
    // (the draw's world matrix in the previous frame), for the motion vectors.
    // targets.extended picks gbuffer_extended.frag (anisotropy and clear-coat targets too).
    void record(VkCommandBuffer cmd, const GBufferTargets& targets, const ImageRef& hdr,
                const std::array<float, 4>& clearRadiance, const FrameScene& scene,
                SceneResources& resources, const GpuBuffer& cameraBuffer,
                const GpuBuffer& previousWorlds) const;

private:
    GpuContext& context_;
    Pipeline pipeline_;
    Pipeline extendedPipeline_;  // also writes targets.anisotropy and targets.clearCoat
    Pipeline layeredPipeline_;   // gbuffer_layered.frag, once prepare(true) was called
    Pipeline extendedLayeredPipeline_;
    bool materialLayers_ = false;
    bool layeredBuilt_ = false;
};

}  // namespace candela::render
