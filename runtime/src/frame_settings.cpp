#include "frame_settings.h"

#include <cstddef>

#include "candela/content/components/light.h"
#include "candela/content/render_setting_table.h"

namespace candela::runtime {

namespace {

// The count of lights lighting the medium from which froxels are the default: the smallest
// count measured at which they cost less than the per-light volumes (docs/speed-vs-error.md,
// the volumetrics cross-over at 320x180: 1 light 19.1 ms against 23.4, 16 lights 66.3 against
// 34.7, 4,096 lights 540 against 357).
constexpr std::size_t kFroxelsFromLights = 16;

// The scene's lights that light a medium (volumetric scale above zero).
std::size_t lightsInMedium(const SceneWorld& world) {
    std::size_t count = 0;
    world.registry.view<const content::Light>().each(
        [&](ecs::Entity, const content::Light& light) { count += light.volumetric > 0.0f; });
    return count;
}

}  // namespace

QualityChoice qualityFor(const ApplicationOptions& options, const SceneWorld* world,
                         bool cpuDevice) {
    if (options.quality) return {*options.quality, content::QualitySource::Flag};
    if (auto scene = world ? world->sceneQuality() : std::nullopt) {
        return {*scene, content::QualitySource::Scene};
    }
    return {content::qualityForDevice(cpuDevice), content::QualitySource::Device};
}

render::RendererOptions rendererOptionsFor(const ApplicationOptions& options,
                                           const SceneWorld* world, QualityChoice quality) {
    render::RendererOptions r;
    // The user-facing settings: the flag's, else the scene file's, else the preset's.
    const content::RenderSettingChoices* scene = world ? &world->sceneSettings() : nullptr;
    static_cast<content::RenderSettings&>(r) =
        content::resolveRenderSettings(quality.level, {&options.settings, scene});
    auto chosen = [&](auto content::RenderSettingChoices::*setting) {
        return (options.settings.*setting).has_value() || (scene && (scene->*setting));
    };
    // Unchosen, sky occlusion is on in frames whose scene has an atmosphere (the demo; other
    // scenes' images stay as they were): render/README.md "Sky occlusion".
    r.skyOcclusionWithAtmosphere = !chosen(&content::RenderSettingChoices::skyOcclusion);
    // Unchosen, the medium is lit by per-light volumes below kFroxelsFromLights lights at start
    // (cheaper there, and closer to the reference at every count), by froxels from it
    // (render/README.md "Volumetric lighting").
    if (!chosen(&content::RenderSettingChoices::volumetrics) && world &&
        lightsInMedium(*world) >= kFroxelsFromLights) {
        r.volumetrics = content::VolumetricsMode::Froxels;
    }

    // The preset's parameters that no flag or scene key names (content/quality.h).
    const content::QualityPreset& preset = content::qualityPreset(quality.level);
    r.shadowCascadeSize = preset.shadowCascadeSize;
    r.shadowCascades = preset.shadowCascades;
    r.shadowMaxTileSize = preset.shadowMaxTileSize;
    r.softShadows = preset.softShadows;
    r.shadowHardTapsPerAxis = preset.shadowHardTapsPerAxis;
    r.aoSettings.slices = preset.aoSlices;
    r.aoSettings.steps = preset.aoSteps;
    r.ssrSettings.maxIterations = preset.ssrMaxIterations;
    r.volumetricsSettings.froxelsX = preset.froxelsX;
    r.volumetricsSettings.froxelsY = preset.froxelsY;
    r.volumetricsSettings.froxelSlices = preset.froxelSlices;
    r.atmosphere.skyViewWidth = preset.skyViewWidth;
    r.atmosphere.skyViewHeight = preset.skyViewHeight;
    r.atmosphere.cubeFaceSize = preset.skyCubeFaceSize;
    r.scatteringSettings = options.scatteringSettings;
    r.scatteringSettings.aerialColumns = preset.aerialGrid;
    r.scatteringSettings.aerialRows = preset.aerialGrid;
    r.scatteringSettings.aerialSlices = preset.aerialGrid;
    r.scatteringSettings.aerialStepsPerSlice = preset.aerialStepsPerSlice;

    // The reference switches (command line only).
    r.culling = options.culling;
    r.lightCulling = options.lightCulling;
    r.lightAssignment = options.lightAssignment;
    r.ibl = options.ibl;
    // --stats reports the frame's work counts (every game's, not only `candela run`'s).
    r.countLightPairs = options.countLightPairs || options.stats.has_value();
    return r;
}

}  // namespace candela::runtime
