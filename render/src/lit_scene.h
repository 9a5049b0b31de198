#pragma once
// The lit inputs' sources as one unit (lit_inputs.h): the camera block, the lights and their
// cluster lists, the shadow maps, sky occlusion, the atmosphere's sky and the shading tables.
// Each frame it chooses the lighting variant the scene needs (prepare), uploads the camera and
// lights, declares the passes that make its parts (shadow maps, sky occlusion, cluster lists) and
// publishes them for the lit passes (LitFrame).
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "candela/render/renderer_options.h"
#include "frame_graph/frame_graph.h"
#include "lit_inputs.h"
#include "passes/lighting/lighting_pass.h"  // LightingFeatures

namespace candela::render {

class AtmospherePass;
class ClusterLightLists;
class ForwardTransparentPass;
class FrameBlackboard;
class FrameCamera;
class GpuContext;
class GpuLightBuffer;
class SceneResources;
class ShadingTables;
class ShadowPass;
class SkyOcclusionPass;
struct FrameInputs;
struct WorldBounds;

class LitScene {
public:
    LitScene(GpuContext& context, const RendererOptions& options);
    ~LitScene();

    FrameCamera& camera() { return *camera_; }
    ClusterLightLists& clusters() { return *clusters_; }
    const ShadingTables& tables() const { return *tables_; }

    // The atmosphere's tables (its sky is the environment the frame lights with), shadow maps for
    // the lights that cast, sky occlusion's maps; returns the lighting variant they leave.
    LightingFeatures prepare(FrameGraph& g, const FrameInputs& inputs, SceneResources& resources,
                             std::span<const WorldBounds> drawBounds, uint32_t width,
                             uint32_t height, RendererStats& stats);
    // The lights, the cluster grid's view and the camera block for this frame.
    void upload(const FrameInputs& inputs, const LightingFeatures& features, uint32_t width,
                uint32_t height);
    // The lights' and shadow maps' stats; the shadow casters' triangles into `work`.
    void collectFrameStats(RendererStats& stats, WorkCounters& work) const;

    // The camera and lights buffers in this frame's graph.
    struct Buffers {
        ResourceHandle camera, lights;
    };
    Buffers importBuffers(FrameGraph& g) const;
    // The shadow atlas and its tables, and sky occlusion's atlas, in this frame's graph.
    struct Maps {
        ResourceHandle shadowAtlas, shadowViews, shadowLights, skyOcclusionAtlas;
    };
    // The shadow maps' and sky occlusion's passes (kept maps: only imported).
    Maps declareMaps(FrameGraph& g, const FrameInputs& inputs, SceneResources& resources,
                     const LightingFeatures& features, ResourceHandle deformed,
                     RendererStats& stats);
    // The cluster lists from the G-buffer's depth (and the blended draws' occupancy), then the
    // lit inputs published for the lit passes (LitFrame, and ShadowFrame with shadows).
    void declareClusters(FrameGraph& g, const FrameInputs& inputs, SceneResources& resources,
                         const LightingFeatures& features, Buffers buffers, const Maps& maps,
                         ResourceHandle depth, ForwardTransparentPass* blended,
                         ResourceHandle deformed, FrameBlackboard& board, RendererStats& stats);
    // The sky behind the lit frame (scenes with an atmosphere); returns hdr's new version.
    ResourceHandle declareSky(FrameGraph& g, const FrameInputs& inputs, ResourceHandle camera,
                              ResourceHandle depth, ResourceHandle hdr,
                              std::vector<std::string>& features);

    // A cut or a resize: the camera forgets last frame's matrices.
    void restart();

private:
    GpuContext& context_;
    const RendererOptions& options_;
    std::unique_ptr<FrameCamera> camera_;  // the camera block and last frame's matrices
    std::unique_ptr<GpuLightBuffer> lights_;
    std::unique_ptr<ClusterLightLists> clusters_;  // grid, cluster buffers, assignment
    std::unique_ptr<ShadowPass> shadows_;
    std::unique_ptr<SkyOcclusionPass> skyOcclusion_;
    std::unique_ptr<AtmospherePass> atmosphere_;  // made on the first frame with a sky
    std::unique_ptr<ShadingTables> tables_;       // LUT, LTC table, rect textures, placeholders
};

}  // namespace candela::render
