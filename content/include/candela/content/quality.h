#pragma once
// Quality presets (`--quality`, a scene file's top-level "quality"; docs/frame-budget.md): one
// column per level of every technique's settings, so one word scales a frame's cost. An
// explicit flag or scene setting of a technique wins over its preset's value. Vulkan-free: the
// command line, the scene reader and writer and the editor read it; runtime maps it onto the
// renderer's options.
#include <cstdint>
#include <optional>
#include <string_view>

namespace candela::content {

enum class QualityLevel : uint8_t { Low, Medium, High, Ultra };
inline constexpr QualityLevel kQualityLevels[] = {QualityLevel::Low, QualityLevel::Medium,
                                                  QualityLevel::High, QualityLevel::Ultra};

const char* qualityLevelName(QualityLevel level);  // "low", "medium", "high", "ultra"
std::optional<QualityLevel> parseQualityLevel(std::string_view name);

// Where a frame's quality came from (--stats quality_source): the command line, the scene
// file, or the device the renderer runs on (qualityForDevice).
enum class QualitySource : uint8_t { Flag, Scene, Device };
const char* qualitySourceName(QualitySource source);  // "flag", "scene", "device"

// One column of the table. `ultra` is the engine's image before presets (its goldens); the
// reference modes stay separate flags.
struct QualityPreset {
    // The fraction of the output's width and height the scene renders at before the upscale
    // to the output (a scene's cost on a CPU device goes with its pixels).
    float renderScale;
    // Levels of detail: the most pixels (shadow maps: texels) a coarser mesh may stray from
    // the full one where a view draws it (content/mesh_lods.h); 0, every mesh in full.
    float lodPixelError;
    // Shadows: texels per cascade side, cascades per directional light, largest local-light tile,
    // and penumbrae by blocker search for sphere and tube lights (off: hard 3x3-texel PCF).
    uint32_t shadowCascadeSize;
    uint32_t shadowCascades;
    uint32_t shadowMaxTileSize;
    bool softShadows;
    uint32_t shadowHardTapsPerAxis;  // 2: a 3x3-texel tent of 4 compare taps; 1: one tap
    // Ambient occlusion (GTAO unless off) and its screen-space slices and steps per side.
    bool ambientOcclusion;
    uint32_t aoSlices;
    uint32_t aoSteps;
    // Screen-space reflections (Hi-Z unless off) and the most Hi-Z steps per ray.
    bool ssr;
    uint32_t ssrMaxIterations;
    // The froxel grid at 1280x720 (scaled with the image) and its depth slices.
    uint32_t froxelsX, froxelsY, froxelSlices;
    // The most plain lights a froxel cluster lights the medium with (0: every one that reaches
    // it; RendererOptions' VolumetricsSettings::froxelLightCap).
    uint32_t froxelLightCap;
    // Sphere and tube lights by linearly transformed cosines (off: representative point).
    bool areaLightsLtc;
    // A textured rect light by LTC: cells per side of its image (RendererOptions).
    uint32_t areaTextureCells;
    // Antialiasing: 0 off, 1 FXAA, 2 TAA (the renderer's AntiAliasing order).
    uint8_t antiAliasing;
    float bloom;  // fraction of radiance in the glare kernel; 0 off
    // The atmosphere's sky-view table and the sky cube's face.
    uint32_t skyViewWidth, skyViewHeight, skyCubeFaceSize;
    // Light shafts' epipolar slices and samples per slice.
    uint32_t scatteringSlices, scatteringSamples;
    // The air in front of blended surfaces and wires (aerial perspective): view rays per side
    // of its grid (also its depth slices) and shadow lookups per slice.
    uint32_t aerialGrid, aerialStepsPerSlice;
    bool hairSelfShadow;  // hair's depth-map self-shadowing
};

const QualityPreset& qualityPreset(QualityLevel level);

// The level for a device without a flag or scene choice: `medium` on a CPU device (lavapipe,
// whose frame budget it is tuned to), `high` on a GPU.
QualityLevel qualityForDevice(bool cpuDevice);

}  // namespace candela::content
