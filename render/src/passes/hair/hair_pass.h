#pragma once
// Hair (Martin et al. 2014, GPU Pro 5, "TressFX: Advanced Real-Time Hair Rendering", TressFX-style
// strands; render/README.md "Hair"): strand segments (content/hair.h) drawn as camera-facing quads
// into a per-pixel linked list (an A-buffer: hair_fill.*), then resolved per pixel
// (hair_resolve.frag: sorted, the nearest fully shaded with Kajiya-Kay, the rest blended cheaply)
// over the lit frame, and finally written into the depth buffer where the hair is at least half
// opaque (hair_depth.frag). The node pool holds RendererOptions::hairNodesPerPixel nodes per pixel;
// fragments beyond it are dropped and counted (--stats hair_nodes_dropped).
#include <array>
#include <glm/glm.hpp>
#include <span>

#include "candela/render/frame_scene.h"
#include "candela/render/gpu_buffer.h"
#include "candela/render/pipeline.h"
#include "candela/render/renderer_options.h"
#include "culling/draw_bounds.h"
#include "frame_graph/graph_resources.h"
#include "lit_inputs.h"
#include "passes/lighting/lighting_pass.h"
#include "passes/shadows/shadow_pass.h"

namespace candela::render {

class GpuContext;
struct ClusterGrid;
struct EnvironmentDescriptors;
struct ShadowDescriptors;

class HairPass {
public:
    explicit HairPass(GpuContext& context);
    ~HairPass();
    HairPass(const HairPass&) = delete;
    HairPass& operator=(const HairPass&) = delete;

    // Writes the frame's segments in world space (one frame is in flight at a time, so the
    // buffer is free) and selects the shader variants. False when there is no segment: the
    // frame then records nothing of this pass.
    bool prepare(const FrameScene& scene, const LightingFeatures& features, HairShading shading,
                 HairSelfShadow selfShadow);
    uint32_t segmentCount() const { return segmentCount_; }

    // The A-buffer's sizes for a target of width x height.
    static VkDeviceSize headBytes(uint32_t width, uint32_t height);
    static VkDeviceSize nodeBytes(uint32_t nodeCapacity);
    // The most segments a frame draws (two storage bindings' reach, hair_segment.glsl) and
    // the most A-buffer nodes one binding reaches on this device.
    static size_t maxSegments(const GpuContext& context);
    static uint32_t maxNodes(const GpuContext& context);
    // The counter buffer the fill pass allocates nodes with; read back after the frame.
    GpuBuffer& counters() { return counters_; }
    // Nodes the last recorded frame asked for (beyond `capacity`: dropped).
    uint32_t requestedNodes() const;

    struct Inputs {
        ImageRef hdr;
        ImageRef depth;
        BufferRef heads;
        BufferRef nodes;
        uint32_t nodeCapacity;
        LitInputs lit;  // the camera block for every hair pass; the rest for the resolve
        float pixelRadiusPerDepth;  // 1 / (projection[1][1] x target height)
        float nearPlane;
        // The hair depth map (hairShadowDepthDesc), or none: self-shadowing off this frame.
        ImageRef hairShadow;
        bool selfShadow = false;
        // The integrated froxel buffer (fog and air in front of the hair), read by the resolve;
        // false: none this frame.
        bool froxels = false;
        BufferRef froxelIntegrated;
    };
    // The hair depth map laid out as a shadow atlas of `atlasSize` texels square.
    static ImageDesc hairShadowDepthDesc(uint32_t atlasSize);
    // hairShadow: DepthWrite, cleared, then every segment drawn into each view's tile (the
    // views as in.shadows' buffer holds them).
    void recordShadowDepth(VkCommandBuffer cmd, const Inputs& in,
                           std::span<const GpuShadowView> views);
    // heads <- HAIR_LIST_END, counters <- 0 (transfers).
    void recordClear(VkCommandBuffer cmd, const Inputs& in) const;
    // depth: DepthRead; heads, nodes, counters: read and written in the fragment stage.
    void recordFill(VkCommandBuffer cmd, const Inputs& in) const;
    // hdr: ColorAttachment (blended over); heads, nodes, lights read.
    void recordResolve(VkCommandBuffer cmd, const Inputs& in) const;
    // depth: DepthWrite; heads, nodes read.
    void recordDepth(VkCommandBuffer cmd, const Inputs& in) const;

private:
    void buildPipelines();
    void pushCommon(VkCommandBuffer cmd, const Pipeline& pipeline, const Inputs& in) const;

    GpuContext& context_;
    GpuBuffer segments_;
    GpuBuffer counters_;
    // Zeros: an integrated froxel buffer whose header says "no medium", bound when the frame
    // has no froxels.
    GpuBuffer noMedium_;
    static size_t segmentsPerRange(const GpuContext& context);
    // The two ranges of segments_ the shaders bind (HAIR_BINDING_SEGMENTS and _HIGH).
    std::array<VkDescriptorBufferInfo, 2> segmentRanges() const;

    uint32_t segmentCount_ = 0;
    size_t segmentsWarnedAbout_ = 0;  // the count last warned about as too many to bind
    WorldBounds bounds_;              // the strands' world box this frame (prepare)
    HairShading shading_ = HairShading::Lit;
    HairSelfShadow selfShadow_ = HairSelfShadow::DepthMap;
    LightingFeatures features_;
    bool built_ = false;
    Pipeline fill_;
    Pipeline resolve_;
    Pipeline depth_;
    Pipeline shadowDepth_;  // built when a frame first draws the hair depth map
};

}  // namespace candela::render
