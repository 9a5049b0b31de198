#pragma once
// Quality presets (`--quality`, a scene file's top-level "quality"; docs/frame-budget.md): one
// column per level of every technique's settings, so one word scales a frame's cost. The
// user-facing settings' columns are in their rows (render_setting_table.h), where an explicit
// flag or scene setting wins over the preset's value; this file holds the levels and the
// columns of the parameters no flag names. Vulkan-free: runtime maps them onto the renderer's
// options.
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

// One column of a preset's parameters that no flag or scene key names; the user-facing
// settings' columns are their rows in render_setting_table.h. `ultra` is the engine's image
// before presets (its goldens); the reference modes stay separate flags.
struct QualityPreset {
    // Shadows: texels per cascade side, cascades per directional light, largest local-light tile,
    // and penumbrae by blocker search for sphere and tube lights (off: hard 3x3-texel PCF).
    uint32_t shadowCascadeSize;
    uint32_t shadowCascades;
    uint32_t shadowMaxTileSize;
    bool softShadows;
    uint32_t shadowHardTapsPerAxis;  // 2: a 3x3-texel tent of 4 compare taps; 1: one tap
    // GTAO's screen-space slices and steps per side.
    uint32_t aoSlices;
    uint32_t aoSteps;
    uint32_t ssrMaxIterations;  // the most Hi-Z steps per ray
    // The froxel grid at 1280x720 (scaled with the image) and its depth slices.
    uint32_t froxelsX, froxelsY, froxelSlices;
    // The atmosphere's sky-view table and the sky cube's face.
    uint32_t skyViewWidth, skyViewHeight, skyCubeFaceSize;
    // The air in front of blended surfaces and wires (aerial perspective): view rays per side
    // of its grid (also its depth slices) and shadow lookups per slice.
    uint32_t aerialGrid, aerialStepsPerSlice;
};

const QualityPreset& qualityPreset(QualityLevel level);

// The level for a device without a flag or scene choice: `medium` on a CPU device (lavapipe,
// whose frame budget it is tuned to), `high` on a GPU.
QualityLevel qualityForDevice(bool cpuDevice);

}  // namespace candela::content
