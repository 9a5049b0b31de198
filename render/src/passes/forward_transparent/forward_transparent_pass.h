#pragma once
// Alpha-blended (glTF BLEND) surfaces, drawn forward after deferred lighting: sorted back to
// front per draw, depth-tested against the G-buffer depth without writing it, shaded with the
// shared light code and the clustered light lists (forward+), blended "over" into the HDR
// target. Before light assignment, their fragments mark the clusters they occupy so those
// lists hold the lights that reach them. With MSAA (`samples` > 1) the pass draws into
// multisampled copies of the HDR, motion and depth targets (recordExpand fills them from the
// deferred result) and resolves them back by plain averaging at the end of its rendering.
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "candela/render/frame_scene.h"
#include "candela/render/gpu_buffer.h"
#include "candela/render/pipeline.h"
#include "frame_graph/graph_resources.h"
#include "passes/lighting/lighting_pass.h"
#include "vk/sampler.h"

namespace candela::render {

class GpuContext;
class GpuImage;
class SceneResources;
struct ClusterGrid;
struct EnvironmentDescriptors;
struct ShadowDescriptors;

class ForwardTransparentPass {
public:
    // samples: 1, or the forward MSAA sample count (RendererOptions::msaaSamples).
    ForwardTransparentPass(GpuContext& context, VkSampleCountFlagBits samples);
    ~ForwardTransparentPass();
    ForwardTransparentPass(const ForwardTransparentPass&) = delete;
    ForwardTransparentPass& operator=(const ForwardTransparentPass&) = delete;

    // Collects the frame's blended draws the camera sees (`visible`: per draw, kDrawCulled or
    // its level of detail; drawsInView), sorted back to front by the view depth of their bounds
    // centre, and selects the shader variant. False when there are none: the frame then records
    // nothing of this pass. `previousWorlds` (one mat4 per scene draw, gbuffer.vert's motion
    // vectors) is bound by every draw this frame records.
    bool prepare(const FrameScene& scene, SceneResources& resources,
                 std::span<const uint8_t> visible, const LightingFeatures& features,
                 const GpuBuffer& previousWorlds);
    size_t drawCount() const { return sorted_.size(); }

    // Clustered culling only: three frame-graph passes after DepthOccupancyPass and before its
    // outputs are read, adding the clusters (and view-space boxes) the blended fragments occupy
    // to its outputs. `bounds` is a transient of boundsBytes(grid) (storage, transfer dst):
    // clearBounds writes it (TransferDst); markOccupancy reads depth (Sampled, fragment),
    // camera (Uniform), depthRange (StorageRead, fragment) and writes bounds
    // (StorageReadWrite, fragment); mergeOccupancy reads bounds and updates tileMasks and
    // clusterBounds (StorageReadWrite, compute).
    struct OccupancyInputs {
        ImageRef depth;
        const GpuBuffer* camera;
        const GpuBuffer* depthRange;
        const GpuBuffer* tileMasks;
        const GpuBuffer* clusterBounds;
        BufferRef bounds;
        const ClusterGrid* grid;
        glm::vec2 projectionScale;
    };
    static VkDeviceSize boundsBytes(const ClusterGrid& grid);
    void recordClearBounds(VkCommandBuffer cmd, const OccupancyInputs& in) const;
    void recordMarkOccupancy(VkCommandBuffer cmd, SceneResources& resources,
                             const OccupancyInputs& in) const;
    void recordMergeOccupancy(VkCommandBuffer cmd, const OccupancyInputs& in) const;

    // After the lighting pass: hdr and motion are ColorAttachments (blended over: a pane's
    // motion weighs by its coverage), depth a DepthRead attachment; the light lists and
    // depthRange are read in the fragment shader.
    // With MSAA: msaaHdr, msaaMotion (ColorAttachment) and msaaDepth (DepthRead) are the
    // multisampled targets recordExpand filled; the draws go there and hdr and motion
    // (ColorAttachment) receive the resolve; depth is only read by recordExpand.
    struct ShadingInputs {
        ImageRef hdr;
        ImageRef motion;
        ImageRef depth;
        ImageRef msaaHdr;
        ImageRef msaaMotion;
        ImageRef msaaDepth;
        LitInputs lit;
        // Froxels (passes/volumetrics), read in the fragment shader; null: no medium.
        bool froxels = false;  // froxelIntegrated holds the frame's grid
        BufferRef froxelIntegrated;
    };
    void recordShading(VkCommandBuffer cmd, SceneResources& resources,
                       const ShadingInputs& in) const;

    // MSAA only: every sample of msaaHdr and msaaMotion (ColorAttachment) and msaaDepth
    // (DepthWrite) gets its pixel's value in hdr, motion and depth (Sampled, fragment).
    void recordExpand(VkCommandBuffer cmd, const ShadingInputs& in) const;
    VkSampleCountFlagBits samples() const { return samples_; }
    // The multisampled targets' descriptions (transients of the frame graph).
    static ImageDesc msaaHdrDesc(uint32_t width, uint32_t height, VkSampleCountFlagBits samples);
    static ImageDesc msaaMotionDesc(uint32_t width, uint32_t height, VkSampleCountFlagBits samples);
    static ImageDesc msaaDepthDesc(uint32_t width, uint32_t height, VkSampleCountFlagBits samples);

private:
    void buildShadingPipeline();
    void buildFixedPipelines();  // occupancy_, merge_, expand_: empty until the first blended frame

    GpuContext& context_;
    VkSampleCountFlagBits samples_;
    std::vector<DrawItem> sorted_;
    std::vector<uint32_t> sortedIndex_;  // each sorted draw's index in FrameScene::draws
    std::vector<uint8_t> sortedLod_;     // and its level of detail
    const GpuBuffer* previousWorlds_ = nullptr;
    std::vector<std::pair<float, uint32_t>> order_;  // (view depth, draw index) scratch
    LightingFeatures features_;
    bool built_ = false;
    Pipeline shading_;
    Pipeline occupancy_;
    Pipeline merge_;
    Pipeline expand_;       // MSAA only
    Sampler pointSampler_;  // G-buffer and depth reads
    // Zeros: an integrated froxel buffer whose header says "no medium", bound when the frame has no
    // froxels.
    GpuBuffer noMedium_;
};

}  // namespace candela::render
