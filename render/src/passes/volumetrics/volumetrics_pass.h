#pragma once
// Volumetric lighting in the scene's medium (render/README.md "Volumetric lighting", issue 17):
// the per-pixel ray-marched reference; Vos's (2014, GPU Pro 5, "Volumetric Light Effects in
// Killzone: Shadow Fall") per-light volumes (each light's volume marched at half resolution with
// dithered starts, blurred and upsampled bilaterally); and froxels (a view-aligned grid lit per
// froxel, integrated front to back and composited over the lit HDR target by depth).
#include <array>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <span>

#include "candela/content/components/fog.h"
#include "candela/render/frame_scene.h"
#include "candela/render/gpu_buffer.h"
#include "candela/render/pipeline.h"
#include "candela/render/renderer_options.h"
#include "frame_graph/graph_resources.h"
#include "passes/volumetrics/light_proxies.h"
#include "vk/sampler.h"

namespace candela::render {

class GpuContext;
struct ShadowDescriptors;

class VolumetricsPass {
public:
    explicit VolumetricsPass(GpuContext& context);

    // Froxels across and down the image and depth slices: one froxel per 8x8 pixels (160x90
    // at 1280x720) unless the settings give a grid, and settings.froxelSlices slices.
    static glm::uvec3 froxelGrid(uint32_t width, uint32_t height,
                                 const VolumetricsSettings& settings);
    // Bytes of one channel of the froxel buffers (one vec4 per froxel). The medium buffer has
    // one channel, two with the sun's (Inputs::froxelSunChannel).
    static VkDeviceSize froxelBufferBytes(const glm::uvec3& grid);
    // The integrated buffer: its head (common/froxel_grid.glsl: the fog grid's shape, uvec4
    // x, y, slices, 1 (2 with the sun's channel) and vec4 near, far, written by the integration;
    // then the air's aerial-perspective grid, 6 vec4, written by
    // ScatteringPass::recordAerialPerspective), then one vec4 per froxel (two with the sun's
    // channel), then the air's boundaries. All zeros reads as "no medium".
    static constexpr VkDeviceSize kFroxelHeaderBytes = (2 + 6) * sizeof(glm::vec4);
    static VkDeviceSize froxelIntegratedBytes(const glm::uvec3& grid, bool sunChannel = false);
    // The per-light volumes' half-resolution targets (in-scattered radiance, view depth); a
    // colour target too under the rasterised proxies.
    static ImageDesc volumesDesc(uint32_t width, uint32_t height, bool proxies = false);
    // The rasterised proxies' half-resolution depth (the scene's at full-resolution pixel 2q).
    static ImageDesc volumesDepthDesc(uint32_t width, uint32_t height);

    // The pipelines a frame uses (each built when a frame first needs it).
    struct Uses {
        bool reference = false, froxels = false, volumesMarch = false, volumesProxies = false;
    };

    // Each light's volumetric scale, indexed as the light buffer; rewritten every frame (the
    // renderer waits for the previous frame before recording). `shadows`: the variant that
    // reads the shadow maps.
    void prepare(std::span<const LightInstance> lights, bool shadows, const Uses& uses);
    const GpuBuffer& lightScales() const { return lightScales_; }
    // Whether some directional light (the sun) scatters in the medium (volumetric above zero).
    static bool sunInMedium(std::span<const LightInstance> lights);

    struct Inputs {
        ImageRef depth;  // Sampled
        ImageRef hdr;    // StorageReadWrite
        const GpuBuffer* camera = nullptr;
        const GpuBuffer* lights = nullptr;
        uint32_t lightCount = 0;
        uint32_t lightCapacity = 0;
        const ShadowDescriptors* shadows = nullptr;
        content::Fog fog;
        float nearPlane = 0.05f;
        VolumetricsSettings settings;
        uint32_t froxelLightCap = 0;  // RenderSettings::froxelLightCap (0: every light)
        glm::uvec3 grid{1u};
        // Froxels whose sun is marched per pixel (binLights' sunMarched) in a frame with
        // blended surfaces, wires or hair: the froxels light the sun too, into a channel of its
        // own that only those read (common/froxel_lookup.glsl's throughMediumAndAir), so the
        // opaque frame keeps the march's shafts and the others get the sun's in-scattering.
        bool froxelSunChannel = false;
    };
    // Lists, per workgroup of the per-light volumes' march (`volumes`) or of the froxel lighting
    // (`froxels`), the lights whose volume reaches it (light_bins.h), after prepare(); rewritten
    // every frame like the scales. A frame with blended surfaces and per-light volumes has both.
    // `sunMarched`: froxels with the sun marched per pixel at half resolution (the volumes'
    // march, blur and composite): the march lists only the directional lights and the froxels
    // all others, so each light is counted once (the froxels all of them with
    // in.froxelSunChannel, which keeps the sun apart).
    // The work binLights listed (WorkCounters' froxel and volume-march counts).
    struct BinnedWork {
        uint64_t froxelLightEvaluations = 0;
        uint64_t volumeMarchSteps = 0;
    };
    const BinnedWork& binnedWork() const { return binnedWork_; }
    void binLights(std::span<const LightInstance> lights, const CameraView& camera, uint32_t width,
                   uint32_t height, const Inputs& in, bool volumes, bool froxels,
                   bool sunMarched = false);
    const GpuBuffer& volumeBins() const { return volumeBins_; }
    const GpuBuffer& froxelBins() const { return froxelBins_; }
    // The rasterised per-light volumes' instance list and draws (light_proxies.h), after
    // prepare(); rewritten every frame like the scales. Builds the area-light variant if a draw
    // needs it.
    void buildProxies(std::span<const LightInstance> lights, const CameraView& camera,
                      uint32_t width, uint32_t height);
    const GpuBuffer& proxyInstances() const { return proxyInstances_; }
    const LightProxies& proxies() const { return proxies_; }

    void recordReference(VkCommandBuffer cmd, const Inputs& in) const;
    // Froxels: light into `medium`, integrate into `integrated` (both StorageWrite, the first
    // then StorageRead), composite `integrated` (StorageRead) over in.hdr (without the sun's
    // channel).
    void recordFroxelLight(VkCommandBuffer cmd, const Inputs& in, const BufferRef& medium) const;
    void recordFroxelIntegrate(VkCommandBuffer cmd, const Inputs& in, const BufferRef& medium,
                               const BufferRef& integrated) const;
    void recordComposite(VkCommandBuffer cmd, const Inputs& in, const BufferRef& integrated) const;
    // Per-light volumes: march into `marched`, blur it into `blurred` (each StorageWrite, then
    // StorageRead), upsample and composite `blurred` over in.hdr. `addOnly`: only add the
    // in-scattering, the surface's transmittance having been applied already (the sun marched
    // over the froxels' composite, which attenuates by the whole medium).
    void recordVolumesMarch(VkCommandBuffer cmd, const Inputs& in, const ImageRef& marched) const;
    // Rasterised per-light volumes (Vos 2014) into `marched` (ColorAttachment) with `depth`
    // (DepthWrite, half resolution): the full-screen pass (the sun, the view depths, the depth
    // target), then each proxy draw, added.
    void recordVolumesProxies(VkCommandBuffer cmd, const Inputs& in, const ImageRef& marched,
                              const ImageRef& depth) const;
    void recordVolumesBlur(VkCommandBuffer cmd, const Inputs& in, const ImageRef& marched,
                           const ImageRef& blurred) const;
    void recordVolumesComposite(VkCommandBuffer cmd, const Inputs& in, const ImageRef& blurred,
                                bool addOnly = false) const;

private:
    BinnedWork binnedWork_;
    struct LightingInfos {
        VkDescriptorBufferInfo camera, lights, scales;
    };
    template <size_t N>
    std::array<VkWriteDescriptorSet, 7 + N> lightingWrites(
        const Inputs& in, LightingInfos& infos,
        const std::array<VkWriteDescriptorSet, N>& extra) const;

    GpuContext& context_;
    bool shadows_ = false;
    bool areaLights_ = false;  // the pipelines' SPEC_MEDIUM_AREA_LIGHTS
    Uses built_;
    bool proxyAreaBuilt_ = false;
    Pipeline reference_;
    Pipeline froxelLight_;
    Pipeline froxelIntegrate_;
    Pipeline composite_;
    Pipeline volumesMarch_;
    Pipeline volumesBlur_;
    Pipeline volumesComposite_;
    Pipeline volumesSun_;
    Pipeline volumesProxy_;      // point and spot lights
    Pipeline volumesProxyArea_;  // rect and disk lights (SPEC_MEDIUM_AREA_LIGHTS)
    LightProxies proxies_;
    GpuBuffer proxyInstances_;
    Sampler pointSampler_;
    GpuBuffer lightScales_;
    GpuBuffer volumeBins_;
    GpuBuffer froxelBins_;
};

}  // namespace candela::render
