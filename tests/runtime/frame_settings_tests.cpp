// The renderer's named choices for a run: the flag wins, else the scene file's field (every
// scene-file name reaches the renderer's matching mode), else the engine's default.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "candela/content/diagnostics.h"
#include "candela/content/render_setting_table.h"
#include "frame_settings.h"

using namespace candela;
using namespace candela::runtime;

namespace {

// A world loaded from a scene file holding `settings` (top-level members) and no entities;
// the file is named after the test, as ctest may run the tests at once.
std::unique_ptr<SceneWorld> worldWith(const std::string& settings) {
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() /
        (std::string("candela_frame_settings_") +
         ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".scene.json");
    std::ofstream(file) << R"({"format": "candela.scene", "version": 1, )" << settings
                        << R"(, "entities": []})";
    auto world = std::make_unique<SceneWorld>();
    content::Diagnostics diagnostics;
    EXPECT_TRUE(world->loadSceneFile(file, diagnostics));
    EXPECT_TRUE(diagnostics.messages.empty()) << diagnostics.toString();
    std::filesystem::remove(file);
    return world;
}

// Every scene-file setting, none at its default.
constexpr const char* kEverySetting =
    R"("brdf": "ue4", "aa": "fxaa", "msaa": 4, "bloom": 0.25, "exposure": "auto",
       "exposure_compensation": -1.5, "ambient_occlusion": {"mode": "reference"},
       "ssr": "reference", "sky_occlusion": "reference", "volumetrics": "froxels",
       "volume_proxies": true, "scattering": "brute-force")";

}  // namespace

TEST(FrameSettings, WithoutFlagsOrSceneTheDefaultsHold) {
    const render::RendererOptions r = rendererOptionsFor(ApplicationOptions{}, nullptr);
    EXPECT_EQ(r.brdf, render::BrdfModel::EnergyConserving);
    EXPECT_EQ(r.aa, render::AntiAliasing::Taa);
    EXPECT_EQ(r.msaaSamples, 1u);
    EXPECT_EQ(r.bloomStrength, 0.04f);
    EXPECT_EQ(r.exposure, render::ExposureMode::Manual);
    EXPECT_EQ(r.exposureCompensation, 0.0f);
    EXPECT_EQ(r.ao, render::AoMode::Gtao);
    EXPECT_EQ(r.ssr, render::SsrMode::Hiz);
    EXPECT_TRUE(r.skyOcclusionWithAtmosphere);
    EXPECT_EQ(r.volumetrics, render::VolumetricsMode::Volumes);
    EXPECT_FALSE(r.volumeProxies);
    EXPECT_EQ(r.scattering, render::ScatteringMode::Epipolar);
}

TEST(FrameSettings, SceneFileFieldsReachTheRenderer) {
    auto world = worldWith(kEverySetting);
    const render::RendererOptions r = rendererOptionsFor(ApplicationOptions{}, world.get());
    EXPECT_EQ(r.brdf, render::BrdfModel::Ue4);
    EXPECT_EQ(r.aa, render::AntiAliasing::Fxaa);
    EXPECT_EQ(r.msaaSamples, 4u);
    EXPECT_EQ(r.bloomStrength, 0.25f);
    EXPECT_EQ(r.exposure, render::ExposureMode::Auto);
    EXPECT_EQ(r.exposureCompensation, -1.5f);
    EXPECT_EQ(r.ao, render::AoMode::Reference);
    EXPECT_EQ(r.ssr, render::SsrMode::Reference);
    EXPECT_FALSE(r.skyOcclusionWithAtmosphere);
    EXPECT_EQ(r.skyOcclusion, render::SkyOcclusionMode::Reference);
    EXPECT_EQ(r.volumetrics, render::VolumetricsMode::Froxels);
    EXPECT_TRUE(r.volumeProxies);
    EXPECT_EQ(r.scattering, render::ScatteringMode::BruteForce);
}

TEST(FrameSettings, FlagsOverrideTheSceneFile) {
    auto world = worldWith(kEverySetting);
    ApplicationOptions options;
    options.settings.brdf = render::BrdfModel::EnergyConserving;
    options.settings.aa = render::AntiAliasing::Off;
    options.settings.msaaSamples = 2u;
    options.settings.bloomStrength = 0.0f;
    options.settings.exposure = render::ExposureMode::Manual;
    options.settings.exposureCompensation = 2.0f;
    options.settings.ao = render::AoMode::Off;
    options.settings.ssr = render::SsrMode::Off;
    options.settings.skyOcclusion = render::SkyOcclusionMode::Off;
    options.settings.volumetrics = render::VolumetricsMode::Off;
    options.settings.volumeProxies = false;
    options.settings.scattering = render::ScatteringMode::Off;
    const render::RendererOptions r = rendererOptionsFor(options, world.get());
    EXPECT_EQ(r.brdf, render::BrdfModel::EnergyConserving);
    EXPECT_EQ(r.aa, render::AntiAliasing::Off);
    EXPECT_EQ(r.msaaSamples, 2u);
    EXPECT_EQ(r.bloomStrength, 0.0f);
    EXPECT_EQ(r.exposure, render::ExposureMode::Manual);
    EXPECT_EQ(r.exposureCompensation, 2.0f);
    EXPECT_EQ(r.ao, render::AoMode::Off);
    EXPECT_EQ(r.ssr, render::SsrMode::Off);
    EXPECT_FALSE(r.skyOcclusionWithAtmosphere);
    EXPECT_EQ(r.skyOcclusion, render::SkyOcclusionMode::Off);
    EXPECT_EQ(r.volumetrics, render::VolumetricsMode::Off);
    EXPECT_FALSE(r.volumeProxies);
    EXPECT_EQ(r.scattering, render::ScatteringMode::Off);
}

TEST(FrameSettings, AnAmbientOcclusionBlockWithoutAModeKeepsTheDefault) {
    auto world = worldWith(R"("ambient_occlusion": {"radius": 2.0})");
    EXPECT_EQ(rendererOptionsFor(ApplicationOptions{}, world.get()).ao, render::AoMode::Gtao);
}

// GBAA (issue 24, added later): the scene file's "aa": "gbaa" reaches the renderer.
TEST(FrameSettings, TheSceneFileCanAskForGbaa) {
    auto world = worldWith(R"("aa": "gbaa")");
    EXPECT_EQ(rendererOptionsFor(ApplicationOptions{}, world.get()).aa, render::AntiAliasing::Gbaa);
}

// Issue 41: one word chooses every technique's settings. Ultra is the engine before presets:
// the renderer's own defaults for what no flag names, the application's for the rest.
TEST(FrameSettings, UltraIsTheEngineBeforePresets) {
    const render::RendererOptions r =
        rendererOptionsFor({}, nullptr, {content::QualityLevel::Ultra});
    const render::RendererOptions engine;
    EXPECT_EQ(r.shadowCascadeSize, engine.shadowCascadeSize);
    EXPECT_EQ(r.shadowCascades, engine.shadowCascades);
    EXPECT_EQ(r.shadowMaxTileSize, engine.shadowMaxTileSize);
    EXPECT_EQ(r.softShadows, engine.softShadows);
    EXPECT_EQ(r.shadowHardTapsPerAxis, engine.shadowHardTapsPerAxis);
    EXPECT_EQ(r.aoSettings.slices, engine.aoSettings.slices);
    EXPECT_EQ(r.aoSettings.steps, engine.aoSettings.steps);
    EXPECT_EQ(r.ssrSettings.maxIterations, engine.ssrSettings.maxIterations);
    EXPECT_EQ(r.volumetricsSettings.froxelsX, engine.volumetricsSettings.froxelsX);
    EXPECT_EQ(r.volumetricsSettings.froxelsY, engine.volumetricsSettings.froxelsY);
    EXPECT_EQ(r.volumetricsSettings.froxelSlices, engine.volumetricsSettings.froxelSlices);
    EXPECT_EQ(r.areaLights, engine.areaLights);
    EXPECT_EQ(r.hairSelfShadow, engine.hairSelfShadow);
    EXPECT_EQ(r.atmosphere.skyViewWidth, engine.atmosphere.skyViewWidth);
    EXPECT_EQ(r.atmosphere.skyViewHeight, engine.atmosphere.skyViewHeight);
    EXPECT_EQ(r.atmosphere.cubeFaceSize, engine.atmosphere.cubeFaceSize);
    EXPECT_EQ(r.scatteringSlices, engine.scatteringSlices);
    EXPECT_EQ(r.scatteringSamples, engine.scatteringSamples);
    EXPECT_EQ(r.renderScale, engine.renderScale);
    EXPECT_EQ(r.lodPixelError, engine.lodPixelError);
    EXPECT_EQ(r.areaTextureCells, engine.areaTextureCells);
    EXPECT_EQ(r.froxelLightCap, engine.froxelLightCap);
    EXPECT_EQ(r.aa, render::AntiAliasing::Taa);
    EXPECT_EQ(r.bloomStrength, 0.04f);
    EXPECT_EQ(r.ao, render::AoMode::Gtao);
    EXPECT_EQ(r.ssr, render::SsrMode::Hiz);
}

// Each lower preset does no more of any counted thing than the one above it: the parameters
// no flag names (content/quality.h) and the settings' preset columns (render_setting_table.h).
TEST(FrameSettings, LowerPresetsNeverCostMore) {
    for (size_t i = 1; i < std::size(content::kQualityLevels); ++i) {
        const content::QualityPreset& lower =
            content::qualityPreset(content::kQualityLevels[i - 1]);
        const content::QualityPreset& higher = content::qualityPreset(content::kQualityLevels[i]);
        const char* name = content::qualityLevelName(content::kQualityLevels[i - 1]);
        EXPECT_LE(lower.shadowCascadeSize, higher.shadowCascadeSize) << name;
        EXPECT_LE(lower.shadowCascades, higher.shadowCascades) << name;
        EXPECT_LE(lower.shadowMaxTileSize, higher.shadowMaxTileSize) << name;
        EXPECT_LE(lower.softShadows, higher.softShadows) << name;
        EXPECT_LE(lower.shadowHardTapsPerAxis, higher.shadowHardTapsPerAxis) << name;
        EXPECT_LE(lower.aoSlices * lower.aoSteps, higher.aoSlices * higher.aoSteps) << name;
        EXPECT_LE(lower.ssrMaxIterations, higher.ssrMaxIterations) << name;
        EXPECT_LE(lower.froxelsX * lower.froxelsY * lower.froxelSlices,
                  higher.froxelsX * higher.froxelsY * higher.froxelSlices)
            << name;
        EXPECT_LE(lower.aerialGrid * lower.aerialStepsPerSlice,
                  higher.aerialGrid * higher.aerialStepsPerSlice)
            << name;

        const content::RenderSettings low =
            content::resolveRenderSettings(content::kQualityLevels[i - 1], {});
        const content::RenderSettings high =
            content::resolveRenderSettings(content::kQualityLevels[i], {});
        // Modes in the order off, the technique, its reference.
        EXPECT_LE(low.ao, high.ao) << name;
        EXPECT_LE(low.ssr, high.ssr) << name;
        EXPECT_LE(low.areaLights, high.areaLights) << name;
        EXPECT_LE(low.hairSelfShadow, high.hairSelfShadow) << name;
        EXPECT_LE(low.bloomStrength > 0, high.bloomStrength > 0) << name;
        EXPECT_LE(low.scatteringSlices * low.scatteringSamples,
                  high.scatteringSlices * high.scatteringSamples)
            << name;
        // Levels of detail: a higher preset strays no further from the full meshes (0: full).
        EXPECT_GE(low.lodPixelError, high.lodPixelError) << name;
        EXPECT_LE(low.renderScale, high.renderScale) << name;
        EXPECT_LE(low.areaTextureCells, high.areaTextureCells) << name;
        // The froxel light cap: 0 is none, the most.
        EXPECT_TRUE(high.froxelLightCap == 0 ||
                    (low.froxelLightCap != 0 && low.froxelLightCap <= high.froxelLightCap))
            << name;
    }
}

// The flag wins over the scene file's "quality", which wins over the device's level; a
// technique's own flag or scene field wins over the preset's value.
TEST(FrameSettings, QualityComesFromFlagSceneOrDevice) {
    auto world = worldWith(R"("quality": "low", "ssr": "hiz")");
    ApplicationOptions options;
    QualityChoice q = qualityFor(options, world.get(), true);
    EXPECT_EQ(q.level, content::QualityLevel::Low);
    EXPECT_EQ(q.source, content::QualitySource::Scene);
    const render::RendererOptions low = rendererOptionsFor(options, world.get(), q);
    EXPECT_EQ(low.ssr, render::SsrMode::Hiz);  // the scene's own "ssr" wins
    EXPECT_EQ(low.ao, render::AoMode::Off);
    EXPECT_FALSE(low.softShadows);
    EXPECT_EQ(low.areaLights, render::AreaLightMode::Representative);

    options.quality = content::QualityLevel::High;
    options.settings.areaLights = render::AreaLightMode::Representative;
    q = qualityFor(options, world.get(), true);
    EXPECT_EQ(q.level, content::QualityLevel::High);
    EXPECT_EQ(q.source, content::QualitySource::Flag);
    const render::RendererOptions high = rendererOptionsFor(options, world.get(), q);
    EXPECT_EQ(high.areaLights, render::AreaLightMode::Representative);  // the flag wins
    EXPECT_TRUE(high.softShadows);
    EXPECT_EQ(high.areaTextureCells, 8u);
    options.settings.areaTextureCells = 2;
    EXPECT_EQ(rendererOptionsFor(options, world.get(), q).areaTextureCells, 2u);
    EXPECT_EQ(high.froxelLightCap, 0u);  // high: every light
    options.settings.froxelLightCap = 12;
    EXPECT_EQ(rendererOptionsFor(options, world.get(), q).froxelLightCap, 12u);

    const QualityChoice cpu = qualityFor({}, nullptr, true);
    EXPECT_EQ(cpu.level, content::QualityLevel::Medium);
    EXPECT_EQ(cpu.source, content::QualitySource::Device);
    EXPECT_EQ(qualityFor({}, nullptr, false).level, content::QualityLevel::High);
}
