#include "frame_settings.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <utility>

#include "candela/content/components/light.h"

namespace candela::runtime {

namespace {

// A scene file's name for a choice and the renderer's, one row per scene-file value.
template <typename Scene, typename Render, std::size_t N>
using EnumMapping = std::array<std::pair<Scene, Render>, N>;

// Every row's scene value is the enumerator at its index, so a table lists each value once.
template <typename Scene, typename Render, std::size_t N>
constexpr bool inDeclarationOrder(const EnumMapping<Scene, Render, N>& table) {
    for (std::size_t i = 0; i < N; ++i) {
        if (table[i].first != static_cast<Scene>(i)) return false;
    }
    return true;
}

// The flag if given, else the scene's value mapped to the renderer's, else unset (a value
// missing from the table counts as unset, as a switch without its case did).
template <typename Scene, typename Render, std::size_t N>
std::optional<Render> chosen(const std::optional<Render>& flag, const std::optional<Scene>& scene,
                             const EnumMapping<Scene, Render, N>& table) {
    if (flag) return flag;
    if (!scene) return std::nullopt;
    for (const auto& [sceneValue, renderValue] : table) {
        if (sceneValue == *scene) return renderValue;
    }
    return std::nullopt;
}

// A scene world's optional setting, unset when there is no world.
template <typename Value>
std::optional<Value> sceneSetting(const SceneWorld* world,
                                  std::optional<Value> (SceneWorld::*setting)() const) {
    return world ? (world->*setting)() : std::nullopt;
}

constexpr EnumMapping<content::SceneBrdf, render::BrdfModel, 2> kBrdf{{
    {content::SceneBrdf::Ue4, render::BrdfModel::Ue4},
    {content::SceneBrdf::EnergyConserving, render::BrdfModel::EnergyConserving},
}};
constexpr EnumMapping<content::SceneAntiAliasing, render::AntiAliasing, 4> kAntiAliasing{{
    {content::SceneAntiAliasing::Off, render::AntiAliasing::Off},
    {content::SceneAntiAliasing::Fxaa, render::AntiAliasing::Fxaa},
    {content::SceneAntiAliasing::Taa, render::AntiAliasing::Taa},
    {content::SceneAntiAliasing::Gbaa, render::AntiAliasing::Gbaa},
}};
constexpr EnumMapping<content::SceneExposure, render::ExposureMode, 2> kExposure{{
    {content::SceneExposure::Manual, render::ExposureMode::Manual},
    {content::SceneExposure::Auto, render::ExposureMode::Auto},
}};
constexpr EnumMapping<content::SceneAoMode, render::AoMode, 3> kAo{{
    {content::SceneAoMode::Off, render::AoMode::Off},
    {content::SceneAoMode::Gtao, render::AoMode::Gtao},
    {content::SceneAoMode::Reference, render::AoMode::Reference},
}};
constexpr EnumMapping<content::SceneSsrMode, render::SsrMode, 3> kSsr{{
    {content::SceneSsrMode::Off, render::SsrMode::Off},
    {content::SceneSsrMode::Hiz, render::SsrMode::Hiz},
    {content::SceneSsrMode::Reference, render::SsrMode::Reference},
}};
constexpr EnumMapping<content::SceneSkyOcclusionMode, render::SkyOcclusionMode, 3> kSkyOcclusion{{
    {content::SceneSkyOcclusionMode::Off, render::SkyOcclusionMode::Off},
    {content::SceneSkyOcclusionMode::On, render::SkyOcclusionMode::On},
    {content::SceneSkyOcclusionMode::Reference, render::SkyOcclusionMode::Reference},
}};
constexpr EnumMapping<content::SceneVolumetricsMode, render::VolumetricsMode, 4> kVolumetrics{{
    {content::SceneVolumetricsMode::Off, render::VolumetricsMode::Off},
    {content::SceneVolumetricsMode::Volumes, render::VolumetricsMode::Volumes},
    {content::SceneVolumetricsMode::Froxels, render::VolumetricsMode::Froxels},
    {content::SceneVolumetricsMode::Reference, render::VolumetricsMode::Reference},
}};
constexpr EnumMapping<content::SceneScatteringMode, render::ScatteringMode, 3> kScattering{{
    {content::SceneScatteringMode::Off, render::ScatteringMode::Off},
    {content::SceneScatteringMode::Epipolar, render::ScatteringMode::Epipolar},
    {content::SceneScatteringMode::BruteForce, render::ScatteringMode::BruteForce},
}};
static_assert(inDeclarationOrder(kBrdf) && inDeclarationOrder(kAntiAliasing) &&
              inDeclarationOrder(kExposure) && inDeclarationOrder(kAo) &&
              inDeclarationOrder(kSsr) && inDeclarationOrder(kSkyOcclusion) &&
              inDeclarationOrder(kVolumetrics) && inDeclarationOrder(kScattering));

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
    if (auto scene = sceneSetting(world, &SceneWorld::sceneQuality)) {
        return {*scene, content::QualitySource::Scene};
    }
    return {content::qualityForDevice(cpuDevice), content::QualitySource::Device};
}

render::RendererOptions rendererOptionsFor(const ApplicationOptions& options,
                                           const SceneWorld* world, QualityChoice quality) {
    const content::QualityPreset& preset = content::qualityPreset(quality.level);
    render::RendererOptions r;
    // The preset's settings that no flag or scene field names (content/quality.h).
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
    r.volumetricsSettings.froxelLightCap = options.froxelLightCap.value_or(preset.froxelLightCap);
    r.atmosphere.skyViewWidth = preset.skyViewWidth;
    r.atmosphere.skyViewHeight = preset.skyViewHeight;
    r.atmosphere.cubeFaceSize = preset.skyCubeFaceSize;
    r.renderScale = options.renderScale.value_or(preset.renderScale);
    r.culling = options.culling;
    r.lodPixelError = options.lodPixelError.value_or(preset.lodPixelError);
    r.areaTextureCells = options.areaTextureCells.value_or(preset.areaTextureCells);
    r.lightCulling = options.lightCulling;
    r.lightAssignment = options.lightAssignment;
    // --stats reports the frame's work counts (every game's, not only `candela run`'s).
    r.countLightPairs = options.countLightPairs || options.stats.has_value();
    r.ibl = options.ibl;
    r.areaLights = options.areaLights.value_or(
        preset.areaLightsLtc ? render::AreaLightMode::Ltc : render::AreaLightMode::Representative);
    r.hairSelfShadow = options.hairSelfShadow.value_or(
        preset.hairSelfShadow ? render::HairSelfShadow::DepthMap : render::HairSelfShadow::Off);
    r.scatteringSettings = options.scatteringSettings;
    r.scatteringSettings.slices = options.scatteringSlices.value_or(preset.scatteringSlices);
    r.scatteringSettings.samplesPerSlice =
        options.scatteringSamples.value_or(preset.scatteringSamples);
    r.scatteringSettings.aerialColumns = preset.aerialGrid;
    r.scatteringSettings.aerialRows = preset.aerialGrid;
    r.scatteringSettings.aerialSlices = preset.aerialGrid;
    r.scatteringSettings.aerialStepsPerSlice = preset.aerialStepsPerSlice;

    // Default energy-conserving.
    r.brdf = chosen(options.brdf, sceneSetting(world, &SceneWorld::sceneBrdf), kBrdf)
                 .value_or(render::BrdfModel::EnergyConserving);
    // Default the preset's: TAA from medium up, it cut edge error the most for its cost
    // (render/README.md "Antialiasing").
    constexpr render::AntiAliasing kPresetAa[] = {
        render::AntiAliasing::Off, render::AntiAliasing::Fxaa, render::AntiAliasing::Taa};
    r.aa = chosen(options.aa, sceneSetting(world, &SceneWorld::sceneAntiAliasing), kAntiAliasing)
               .value_or(kPresetAa[std::min<std::size_t>(preset.antiAliasing, 2)]);
    r.msaaSamples = options.msaa.value_or(sceneSetting(world, &SceneWorld::sceneMsaa).value_or(1u));
    r.bloomStrength =
        options.bloom.value_or(sceneSetting(world, &SceneWorld::sceneBloom).value_or(preset.bloom));
    r.exposure =
        chosen(options.exposure, sceneSetting(world, &SceneWorld::sceneExposure), kExposure)
            .value_or(render::ExposureMode::Manual);
    r.autoExposure.compensation = options.exposureCompensation.value_or(
        sceneSetting(world, &SceneWorld::sceneExposureCompensation).value_or(0.0f));
    // The scene file's "ambient_occlusion" mode; default GTAO (render/README.md "Ambient
    // occlusion" gives the measurements behind the default).
    const auto sceneAo = world ? world->sceneAmbientOcclusion() : std::nullopt;
    r.ao = chosen(options.ao, sceneAo ? sceneAo->mode : std::nullopt, kAo)
               .value_or(preset.ambientOcclusion ? render::AoMode::Gtao : render::AoMode::Off);
    // Default hiz: the renderer declares no SSR pass in a frame without a surface under the
    // roughness cut-off, so only frames with a glossy surface pay (render/README.md
    // "Screen-space reflections").
    r.ssr = chosen(options.ssr, sceneSetting(world, &SceneWorld::sceneSsr), kSsr)
                .value_or(preset.ssr ? render::SsrMode::Hiz : render::SsrMode::Off);
    // Unset: the renderer's default, on in frames with an atmosphere (the demo; other scenes'
    // images stay as they were): render/README.md "Sky occlusion".
    if (auto mode = chosen(options.skyOcclusion,
                           sceneSetting(world, &SceneWorld::sceneSkyOcclusion), kSkyOcclusion)) {
        r.skyOcclusion = *mode;
    } else {
        r.skyOcclusionWithAtmosphere = true;
    }
    // Default by the scene's lights at start: per-light volumes below kFroxelsFromLights
    // (cheaper there, and closer to the reference at every count), froxels from it
    // (render/README.md "Volumetric lighting"). Either draws only in frames with a medium;
    // `off` is only ever chosen explicitly.
    r.volumetrics = chosen(options.volumetrics, sceneSetting(world, &SceneWorld::sceneVolumetrics),
                           kVolumetrics)
                        .value_or(world && lightsInMedium(*world) >= kFroxelsFromLights
                                      ? render::VolumetricsMode::Froxels
                                      : render::VolumetricsMode::Volumes);
    // Default off, the tile lists: cheaper on lavapipe (render/README.md "Volumetric
    // lighting").
    r.volumetricsSettings.volumeProxies = options.volumeProxies.value_or(
        sceneSetting(world, &SceneWorld::sceneVolumeProxies).value_or(false));
    // Default epipolar: it stays within 0.22 % of brute force at a 35th of the rays
    // (render/README.md "Light shafts"); the passes draw only in frames whose scene has an
    // atmosphere.
    r.scattering =
        chosen(options.scattering, sceneSetting(world, &SceneWorld::sceneScattering), kScattering)
            .value_or(render::ScatteringMode::Epipolar);
    return r;
}

}  // namespace candela::runtime
