#include "candela/content/quality.h"

#include <array>

namespace candela::content {

namespace {

// Columns low, medium, high, ultra. Ultra holds the renderer's settings before presets; each
// lower column cuts what the frame benchmark (docs/frame-budget.md) showed to cost the most.
constexpr std::array<QualityPreset, 4> kPresets{{
    // low
    QualityPreset{.shadowCascadeSize = 512,
                  .shadowCascades = 2,
                  .shadowMaxTileSize = 128,
                  .softShadows = false,
                  .shadowHardTapsPerAxis = 1,
                  .aoSlices = 2,
                  .aoSteps = 4,
                  .ssrMaxIterations = 32,
                  .froxelsX = 80,
                  .froxelsY = 45,
                  .froxelSlices = 32,
                  .skyViewWidth = 96,
                  .skyViewHeight = 54,
                  .skyCubeFaceSize = 32,
                  .aerialGrid = 16,
                  .aerialStepsPerSlice = 4},
    // medium: the CPU device's default
    QualityPreset{.shadowCascadeSize = 1024,
                  .shadowCascades = 3,
                  .shadowMaxTileSize = 256,
                  .softShadows = false,
                  .shadowHardTapsPerAxis = 1,
                  .aoSlices = 2,
                  .aoSteps = 4,
                  .ssrMaxIterations = 64,
                  .froxelsX = 80,
                  .froxelsY = 45,
                  .froxelSlices = 32,
                  .skyViewWidth = 192,
                  .skyViewHeight = 108,
                  .skyCubeFaceSize = 64,
                  .aerialGrid = 16,
                  .aerialStepsPerSlice = 8},
    // high: a GPU's default
    QualityPreset{.shadowCascadeSize = 1024,
                  .shadowCascades = 4,
                  .shadowMaxTileSize = 512,
                  .softShadows = true,
                  .shadowHardTapsPerAxis = 2,
                  .aoSlices = 3,
                  .aoSteps = 6,
                  .ssrMaxIterations = 96,
                  .froxelsX = 160,
                  .froxelsY = 90,
                  .froxelSlices = 64,
                  .skyViewWidth = 192,
                  .skyViewHeight = 108,
                  .skyCubeFaceSize = 64,
                  .aerialGrid = 32,
                  .aerialStepsPerSlice = 8},
    // ultra: the engine's image before presets
    QualityPreset{.shadowCascadeSize = 1024,
                  .shadowCascades = 4,
                  .shadowMaxTileSize = 1024,
                  .softShadows = true,
                  .shadowHardTapsPerAxis = 2,
                  .aoSlices = 4,
                  .aoSteps = 8,
                  .ssrMaxIterations = 128,
                  .froxelsX = 160,
                  .froxelsY = 90,
                  .froxelSlices = 64,
                  .skyViewWidth = 192,
                  .skyViewHeight = 108,
                  .skyCubeFaceSize = 64,
                  .aerialGrid = 32,
                  .aerialStepsPerSlice = 8},
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
