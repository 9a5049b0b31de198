#pragma once
// Sky occlusion (render/README.md "Sky occlusion"): depth maps of the static scene seen from
// directions spread over the sky hemisphere, tiles of one atlas, rendered only when the
// casters change (a frame computes only what its scene needs). The lighting pass tests each
// pixel against every map (common/sky_occlusion.glsl): the cosine-weighted share of
// directions that see the sky scales the sky's diffuse light, the lobe-weighted share its
// specular light, and the unblocked directions bend the normal.
#include <cstdint>
#include <glm/glm.hpp>

#include "candela/render/frame_scene.h"
#include "candela/render/gpu_image.h"
#include "candela/render/pipeline.h"
#include "candela/render/renderer_options.h"
#include "vk/sampler.h"

namespace candela::render {

class GpuContext;
class SceneResources;

// Directions and tile size of a mode (On: 32 of 256 texels; Reference: 256 of 256).
uint32_t skyOcclusionDirectionCount(SkyOcclusionMode mode);
uint32_t skyOcclusionTileSize(SkyOcclusionMode mode);

class SkyOcclusionPass {
public:
    explicit SkyOcclusionPass(GpuContext& context);
    ~SkyOcclusionPass();
    SkyOcclusionPass(const SkyOcclusionPass&) = delete;
    SkyOcclusionPass& operator=(const SkyOcclusionPass&) = delete;

    // Fits the sphere to the frame's static opaque casters and decides whether the maps must
    // be rendered (the casters or the mode changed). False when there is nothing to occlude.
    bool prepare(const FrameScene& scene, const SceneResources& resources, SkyOcclusionMode mode);
    bool rendersThisFrame() const { return rendersThisFrame_; }
    // Frame graph use: the atlas DepthWrite.
    void record(VkCommandBuffer cmd, const FrameScene& scene, const SceneResources& resources);

    const GpuImage& atlas() const { return atlas_; }
    bool atlasHoldsMaps() const { return atlasHoldsMaps_; }
    VkDescriptorImageInfo descriptor(bool enabled) const;
    // GpuCamera::skyOcclusionSphere and skyOcclusionLayout.
    glm::vec4 sphere() const { return sphere_; }
    glm::uvec4 layout() const;
    uint32_t rebuilds() const { return rebuilds_; }

private:
    GpuContext& context_;
    Pipeline pipeline_;
    Sampler compareSampler_;
    GpuImage atlas_;
    GpuImage placeholder_;
    uint32_t directions_ = 0;
    uint32_t tileSize_ = 0;
    uint32_t tilesPerRow_ = 0;
    glm::vec4 sphere_{0.0f};
    uint64_t key_ = 0;
    bool atlasHoldsMaps_ = false;
    bool rendersThisFrame_ = false;
    uint32_t rebuilds_ = 0;
    std::vector<uint32_t> casters_;
};

}  // namespace candela::render
