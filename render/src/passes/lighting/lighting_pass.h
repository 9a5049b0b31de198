#pragma once
// Full-screen compute lighting over the G-buffer (brute force: every light at every pixel).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "candela/content/light_types.h"
#include "candela/render/gpu_buffer.h"
#include "candela/render/gpu_image.h"
#include "candela/render/pipeline.h"
#include "candela/render/renderer_options.h"
#include "common/specialization_ids.h"
#include "frame_graph/graph_resources.h"
#include "light_loops.h"
#include "lit_inputs.h"
#include "vk/sampler.h"

namespace candela::render {

struct ClusterGrid;
class GpuContext;
struct EnvironmentDescriptors;
struct GBufferTargets;
struct ShadowDescriptors;

// Which shading models and light shapes the shader variant contains.
struct LightingFeatures {
    bool subsurface = false;
    bool legacyDiffuseSpecular = false;
    bool sphereLights = false;
    bool tubeLights = false;
    // The paths the sized lights take (AREA_PATH_* of common/specialization_ids.h).
    uint32_t areaLightPaths = AREA_PATHS_ALL;
    uint32_t areaTextureCells = 8;         // RendererOptions::areaTextureCells
    uint32_t lightLoops = kAllLightLoops;  // the local-light loops the lights reach (light_loops.h)
    // Bit lightTypeIndex(type) per light type present (lights/gpu_light_types.h gives the
    // types whose code a variant can leave out).
    uint32_t lightTypes = 0;
    bool clustered = true;
    bool countLightPairs = false;
    bool shadows = false;  // a light casts this frame (common/shadows.glsl)
    // ... of them a directional light (cascades), a local light (cube faces, spot views): the
    // lighting pass compiles in only the shadow code of the kinds that cast.
    bool directionalShadows = false;
    bool localShadows = false;
    bool softShadows = true;             // penumbrae for sphere and tube lights (RendererOptions)
    uint32_t hardShadowTapsPerAxis = 2;  // RendererOptions::shadowHardTapsPerAxis
    std::optional<IblMode> ibl;          // none without an environment
    BrdfModel brdf = BrdfModel::EnergyConserving;
    AreaLightMode areaLights = AreaLightMode::Ltc;  // how sphere and tube lights integrate
    bool anisotropy = false;  // a drawn opaque material has KHR_materials_anisotropy
    bool clearCoat = false;   // ... KHR_materials_clearcoat
    bool materialExtensions() const { return anisotropy || clearCoat; }
    AoMode ao = AoMode::Off;              // only with ibl
    bool aoSpecularFromHorizons = false;  // GTAO's horizon-slice specular occlusion
    bool skyOcclusion = false;            // the sky's light occluded (only with ibl)

    static constexpr uint32_t bit(content::LightType type) {
        return 1u << content::lightTypeIndex(type);
    }
    bool operator==(const LightingFeatures&) const = default;
    std::vector<std::string> names() const;
};

// The shading models, light shapes and clustering of a variant as specialization constants
// (common/specialization_ids.h): what the deferred and forward pipelines share.
void setShadingConstants(SpecializationConstants& constants, const LightingFeatures& features);
// Anisotropy and clear coat: the deferred pass only (blended surfaces shade without them).
void setMaterialExtensionConstants(SpecializationConstants& constants,
                                   const LightingFeatures& features);

class LightingPass {
public:
    // The counting variant's uints per workgroup (lighting.comp PairCounts): evaluated and lit
    // pairs, evaluations of plain, area and shadowed lights, shadow filter and blocker taps.
    static constexpr uint32_t kCountsPerWorkgroup = 8;
    explicit LightingPass(GpuContext& context);
    ~LightingPass();
    LightingPass(const LightingPass&) = delete;
    LightingPass& operator=(const LightingPass&) = delete;

    // Rebuilds the pipeline when the scene's features change (specialization constants).
    void setFeatures(const LightingFeatures& features);
    const LightingFeatures& features() const { return features_; }

    // Frame graph uses: G-buffer images Sampled, hdr StorageReadWrite. The cluster buffers are read
    // only by the clustered variant, pairCounts only by the counting one
    // (kCountsPerWorkgroup uints per workgroup, see workgroupCount()).
    struct Inputs {
        const GBufferTargets* gbuffer;
        ImageRef hdr;
        LitInputs lit;                // the cluster lists read by the clustered variant only
        const GpuBuffer* pairCounts;  // the counting variant's
        uint32_t lightCount = 0;      // every light in lit.lights (the brute-force variant's loop)
        uint32_t referenceSamples = 0;
        // Sampled; unused (placeholders bound) when the variant has no ambient occlusion.
        std::optional<ImageRef> ambientOcclusion;
        std::optional<ImageRef> specularOcclusion;  // the reference mode's only
        float aoIntensity = 1.0f;
        bool aoMultiBounce = true;
    };
    void record(VkCommandBuffer cmd, const Inputs& inputs) const;
    static uint32_t workgroupCount(uint32_t width, uint32_t height);
    // The brute-force variant's lights per dispatch (record() adds them a batch at a time).
    static constexpr uint32_t kBruteForceLightsPerDispatch = 1024;

private:
    GpuContext& context_;
    LightingFeatures features_;
    bool built_ = false;
    Pipeline pipeline_;
    Sampler pointSampler_;  // G-buffer and depth reads
};

}  // namespace candela::render
