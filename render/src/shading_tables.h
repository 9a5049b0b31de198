#pragma once
// The tables every lit pass samples beside the lights: the environment BRDF LUT (built once,
// when first needed, and cached on disk), the sky's luminance sampling table (the reference IBL
// mode, one per sky), the area lights' LTC table, textured rects' image atlas, and placeholders
// standing in for a frame without a sky.
#include <memory>

#include "candela/render/renderer_options.h"
#include "ibl/environment_descriptors.h"

namespace candela::render {

class AreaLightTextures;
class EnvironmentBrdfLut;
class EnvironmentSamplingTable;
class GpuContext;
class LtcTableTexture;
class SceneResources;
struct LightingFeatures;

class ShadingTables {
public:
    explicit ShadingTables(GpuContext& context);
    ~ShadingTables();
    ShadingTables(const ShadingTables&) = delete;
    ShadingTables& operator=(const ShadingTables&) = delete;

    // Before a frame with `features`: builds (or loads) what it needs and does not have yet;
    // the LUT's source and build time go to `stats`, a cache problem to stderr as a warning.
    void prepare(const LightingFeatures& features, const SceneResources& resources,
                 RendererStats& stats);
    // The frame's environment descriptors: the sky's (or placeholders), the LUT, the sampling
    // table (reference mode), the LTC table and the textured rects' atlas.
    EnvironmentDescriptors describe(const LightingFeatures& features,
                                    const SceneResources& resources) const;
    const EnvironmentBrdfLut* brdfLut() const { return brdfLut_.get(); }
    AreaLightTextures& areaLightTextures() { return *areaLightTextures_; }

private:
    GpuContext& context_;
    std::unique_ptr<EnvironmentPlaceholders> placeholders_;
    std::unique_ptr<LtcTableTexture> ltcTable_;
    std::unique_ptr<AreaLightTextures> areaLightTextures_;
    std::unique_ptr<EnvironmentBrdfLut> brdfLut_;
    std::unique_ptr<EnvironmentSamplingTable> samplingTable_;
};

}  // namespace candela::render
