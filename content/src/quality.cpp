#include "candela/content/quality.h"

#include <array>

namespace candela::content {

namespace {

// Columns low, medium, high, ultra. Ultra holds the renderer's settings before presets; each
// lower column cuts what the frame benchmark (docs/frame-budget.md) showed to cost the most.
// Low keeps TAA: on lavapipe its resolve costs half of FXAA's (7 against 15 ms at 640x360).
constexpr std::array<QualityPreset, 4> kPresets{{
    // low
    QualityPreset{.renderScale = 0.5f,
                  .lodPixelError = 0.5f,
                  .shadowCascadeSize = 512,
                  .shadowCascades = 2,
                  .shadowMaxTileSize = 128,
                  .softShadows = false,
                  .shadowHardTapsPerAxis = 1,
                  .ambientOcclusion = false,
                  .aoSlices = 2,
                  .aoSteps = 4,
                  .ssr = false,
                  .ssrMaxIterations = 32,
                  .froxelsX = 80,
                  .froxelsY = 45,
                  .froxelSlices = 32,
                  .froxelLightCap = 16,
                  .areaLightsLtc = false,
                  .areaTextureCells = 2,
                  .antiAliasing = 2,
                  .bloom = 0.0f,
                  .skyViewWidth = 96,
                  .skyViewHeight = 54,
                  .skyCubeFaceSize = 32,
                  .scatteringSlices = 128,
                  .scatteringSamples = 64,
                  .aerialGrid = 16,
                  .aerialStepsPerSlice = 4,
                  .hairSelfShadow = false},
    // medium: the CPU device's default
    QualityPreset{.renderScale = 0.5f,
                  .lodPixelError = 0.25f,
                  .shadowCascadeSize = 1024,
                  .shadowCascades = 3,
                  .shadowMaxTileSize = 256,
                  .softShadows = false,
                  .shadowHardTapsPerAxis = 1,
                  .ambientOcclusion = true,
                  .aoSlices = 2,
                  .aoSteps = 4,
                  .ssr = false,
                  .ssrMaxIterations = 64,
                  .froxelsX = 80,
                  .froxelsY = 45,
                  .froxelSlices = 32,
                  .froxelLightCap = 32,
                  .areaLightsLtc = true,
                  .areaTextureCells = 4,
                  .antiAliasing = 2,
                  .bloom = 0.04f,
                  .skyViewWidth = 192,
                  .skyViewHeight = 108,
                  .skyCubeFaceSize = 64,
                  .scatteringSlices = 256,
                  .scatteringSamples = 128,
                  .aerialGrid = 16,
                  .aerialStepsPerSlice = 8,
                  .hairSelfShadow = true},
    // high: a GPU's default
    QualityPreset{.renderScale = 1.0f,
                  .lodPixelError = 0.25f,
                  .shadowCascadeSize = 1024,
                  .shadowCascades = 4,
                  .shadowMaxTileSize = 512,
                  .softShadows = true,
                  .shadowHardTapsPerAxis = 2,
                  .ambientOcclusion = true,
                  .aoSlices = 3,
                  .aoSteps = 6,
                  .ssr = true,
                  .ssrMaxIterations = 96,
                  .froxelsX = 160,
                  .froxelsY = 90,
                  .froxelSlices = 64,
                  .froxelLightCap = 0,
                  .areaLightsLtc = true,
                  .areaTextureCells = 8,
                  .antiAliasing = 2,
                  .bloom = 0.04f,
                  .skyViewWidth = 192,
                  .skyViewHeight = 108,
                  .skyCubeFaceSize = 64,
                  .scatteringSlices = 512,
                  .scatteringSamples = 256,
                  .aerialGrid = 32,
                  .aerialStepsPerSlice = 8,
                  .hairSelfShadow = true},
    // ultra: the engine's image before presets
    QualityPreset{.renderScale = 1.0f,
                  .lodPixelError = 0.0f,
                  .shadowCascadeSize = 1024,
                  .shadowCascades = 4,
                  .shadowMaxTileSize = 1024,
                  .softShadows = true,
                  .shadowHardTapsPerAxis = 2,
                  .ambientOcclusion = true,
                  .aoSlices = 4,
                  .aoSteps = 8,
                  .ssr = true,
                  .ssrMaxIterations = 128,
                  .froxelsX = 160,
                  .froxelsY = 90,
                  .froxelSlices = 64,
                  .froxelLightCap = 0,
                  .areaLightsLtc = true,
                  .areaTextureCells = 8,
                  .antiAliasing = 2,
                  .bloom = 0.04f,
                  .skyViewWidth = 192,
                  .skyViewHeight = 108,
                  .skyCubeFaceSize = 64,
                  .scatteringSlices = 512,
                  .scatteringSamples = 256,
                  .aerialGrid = 32,
                  .aerialStepsPerSlice = 8,
                  .hairSelfShadow = true},
}};

}  // namespace

const char* qualityLevelName(QualityLevel level) {
    switch (level) {
        case QualityLevel::Low:
            return "low";
        case QualityLevel::Medium:
            return "medium";
        case QualityLevel::High:
            return "high";
        case QualityLevel::Ultra:
            return "ultra";
    }
    return "ultra";
}

std::optional<QualityLevel> parseQualityLevel(std::string_view name) {
    for (QualityLevel level : kQualityLevels) {
        if (name == qualityLevelName(level)) return level;
    }
    return std::nullopt;
}

const char* qualitySourceName(QualitySource source) {
    switch (source) {
        case QualitySource::Flag:
            return "flag";
        case QualitySource::Scene:
            return "scene";
        case QualitySource::Device:
            return "device";
    }
    return "device";
}

const QualityPreset& qualityPreset(QualityLevel level) {
    return kPresets[static_cast<size_t>(level)];
}

QualityLevel qualityForDevice(bool cpuDevice) {
    return cpuDevice ? QualityLevel::Medium : QualityLevel::High;
}

}  // namespace candela::content
