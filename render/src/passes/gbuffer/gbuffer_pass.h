#pragma once
// Rasterises the scene's meshes into the G-buffer, depth and the HDR target (emissive).
#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

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
    // Whether this frame's opaque draws include a layered material (the variants that blend
    // material layers), write the extended targets (anisotropy, clear coat) and GBAA's edge
    // target (`edges`: the variants with gbuffer_edges.geom, --aa gbaa only): picks the
    // pipeline, built on first use, so a run compiles only the variants its frames draw with.
    // With both the extended targets and the edges, the edge target is written by a pass of
    // its own (recordEdges): nine colour attachments are more than devices guarantee.
    // Each draw takes the variant compiled for its material's texture slots (untextured
    // materials skip every lookup), built here for the draws of `scene` the camera sees
    // (`visible`: per draw, kDrawCulled or the level of detail it is drawn at; drawsInView),
    // recorded in `order` (culling/draw_order.h: nearest first).
    void prepare(const FrameScene& scene, const SceneResources& resources,
                 std::span<const uint8_t> visible, bool materialLayers, bool extended, bool edges,
                 std::span<const uint32_t> order);
    // Whether prepare() chose the separate edge pass (recordEdges) for this frame.
    static bool separateEdges(bool extended, bool edges) { return edges && extended; }
    bool materialLayers() const { return materialLayers_; }
    // Colour, motion, HDR and depth in attachment-optimal layouts (frame graph:
    // ColorAttachment, DepthWrite); all are cleared. `previousWorlds`: one mat4 per scene draw
    // (the draw's world matrix in the previous frame), for the motion vectors.
    // targets.extended picks gbuffer_extended.frag (anisotropy and clear-coat targets too),
    // targets.hasEdges the edge variant (targets.edges after them; prepare()'s `edges`).
    void record(VkCommandBuffer cmd, const GBufferTargets& targets, const ImageRef& hdr,
                const std::array<float, 4>& clearRadiance, const FrameScene& scene,
                SceneResources& resources, const GpuBuffer& cameraBuffer,
                const GpuBuffer& previousWorlds) const;
    // GBAA's edge target alone (gbuffer_edges_only.frag): the opaque draws again after
    // record(), depth test equal against its depth (DepthRead), into `edges`
    // (ColorAttachment, cleared).
    void recordEdges(VkCommandBuffer cmd, const ImageRef& edges, const ImageRef& depth,
                     const FrameScene& scene, SceneResources& resources,
                     const GpuBuffer& cameraBuffer, const GpuBuffer& previousWorlds) const;

private:
    GpuContext& context_;
    // By variantIndex() (plain, extended (also writes targets.anisotropy and
    // targets.clearCoat), layered (gbuffer_layered.frag), extended and layered; then the same
    // four with GBAA's edges) and texture slots (variantKey). Built when prepare() first
    // meets the pair.
    std::unordered_map<uint64_t, Pipeline> variants_;
    static uint64_t variantKey(size_t index, uint32_t textureSlots) {
        return uint64_t(index) << 32 | textureSlots;
    }
    // Per scene draw, prepare()'s pipeline (null for draws the pass skips: blended, empty or
    // out of view).
    std::vector<const Pipeline*> drawPipelines_;
    std::vector<uint32_t> order_;    // the draws in recording order
    std::vector<uint8_t> drawLods_;  // per scene draw, prepare()'s level of detail
    Pipeline edgesOnly_;             // recordEdges; empty until a frame needs it
    static size_t variantIndex(bool materialLayers, bool extended, bool edges) {
        return (edges ? 4 : 0) + (materialLayers ? 2 : 0) + (extended ? 1 : 0);
    }
    bool materialLayers_ = false;
};

}  // namespace candela::render
