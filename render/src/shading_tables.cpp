#include "shading_tables.h"

#include <cstdio>
#include <string>
#include <vector>

#include "candela/render/environment.h"
#include "candela/render/scene_resources.h"
#include "ibl/environment_brdf_lut.h"
#include "ibl/environment_sampling_table.h"
#include "lights/area_light_textures.h"
#include "lights/ltc_table_texture.h"
#include "passes/lighting/lighting_pass.h"

namespace candela::render {

ShadingTables::ShadingTables(GpuContext& context)
    : context_(context),
      placeholders_(std::make_unique<EnvironmentPlaceholders>(context)),
      ltcTable_(std::make_unique<LtcTableTexture>(context)),
      areaLightTextures_(std::make_unique<AreaLightTextures>(context)) {}

ShadingTables::~ShadingTables() = default;

void ShadingTables::prepare(const LightingFeatures& features, const SceneResources& resources,
                            RendererStats& stats) {
    // The environment BRDF LUT is the same for every sky: built once, when first needed (the
    // energy-conserving BRDF reads its directional albedo for every light, sky or not).
    const bool needsLut =
        features.ibl || features.brdf == BrdfModel::EnergyConserving || features.clearCoat;
    // Its texels come from the environment cache folder after the first run (390 ms of
    // lavapipe otherwise); a cache problem is a warning and a rebuild.
    if (needsLut && !brdfLut_) {
        std::vector<std::string> warnings;
        brdfLut_ =
            EnvironmentBrdfLut::loadOrBuild(context_, defaultEnvironmentCacheDirectory(), warnings);
        for (const std::string& w : warnings)
            std::fprintf(stderr, "warning: %s\n", w.c_str());
        stats.brdfLutSource = brdfLut_->sourceName();
        stats.brdfLutMs = brdfLut_->buildMs();
    }
    // The reference mode also samples the sky by luminance: a table per environment.
    if (features.ibl == IblMode::Reference &&
        (!samplingTable_ || samplingTable_->source() != resources.environment())) {
        samplingTable_ =
            std::make_unique<EnvironmentSamplingTable>(context_, *resources.environment());
    }
}

EnvironmentDescriptors ShadingTables::describe(const LightingFeatures& features,
                                               const SceneResources& resources) const {
    EnvironmentDescriptors environment = placeholders_->describe(
        features.ibl ? resources.environment() : nullptr, brdfLut_.get(),
        samplingTable_ && features.ibl == IblMode::Reference ? &samplingTable_->buffer() : nullptr);
    environment.ltcMatrix = ltcTable_->matrix();
    environment.ltcMagnitude = ltcTable_->magnitude();
    environment.areaLightTextures = areaLightTextures_->descriptor();
    return environment;
}

}  // namespace candela::render
