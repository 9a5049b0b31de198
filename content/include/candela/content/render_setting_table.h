#pragma once
// One row per user-facing render setting (render_settings.h): its command-line flag, its
// scene-file key, the names of its values or its range, its value in each quality preset, the
// editor's widget for it and its name under --stats "settings". The command-line parser, the
// scene reader and writer, the editor's scene panel and --stats iterate these rows
// (forEachRenderSetting); none of them names a setting. Adding a setting: its members in
// render_settings.h and a row here.
//
//   content::forEachRenderSetting([&](const auto& row) {
//       if (auto value = parseRenderSetting(row, text)) choices.*row.choice = *value;
//   });
#include <array>
#include <charconv>
#include <cmath>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>

#include "candela/content/quality.h"
#include "candela/content/render_settings.h"

namespace candela::content {

// How the editor shows a setting.
enum class SettingWidget : uint8_t {
    Choice,  // a combo of the value names
    Toggle,  // a check box (off / on)
    Slider,  // a number between least and most
    Counts,  // a combo of the powers of two between least and most
    Count,   // an integer between least and most
};

template <typename T>
struct NamedValue {
    T value;
    std::string_view name;
};

template <typename T>
struct RenderSettingRow {
    std::string_view flag;       // "--ssr"
    std::string_view sceneKey;   // top-level key, or "object/member" for a member of one
    std::string_view statsName;  // key under --stats "settings"
    std::string_view help;       // the usage line after the flag and its values
    T RenderSettings::*value;
    std::optional<T> RenderSettingChoices::*choice;
    SettingWidget widget;
    // The value of each quality preset, low to ultra (QualityLevel's order): what a frame
    // renders with when neither the command line nor the scene file chooses.
    std::array<T, 4> presets;
    std::span<const NamedValue<T>> names = {};  // enums and switches: every value's name
    // Numbers: the range, a placeholder for the usage text and how a message names the range.
    T least{}, most{};
    std::string_view placeholder = {};
    std::string_view expects = {};
};

namespace setting_names {
inline constexpr NamedValue<BrdfModel> kBrdf[] = {
    {BrdfModel::Ue4, "ue4"}, {BrdfModel::EnergyConserving, "energy-conserving"}};
inline constexpr NamedValue<AntiAliasing> kAa[] = {{AntiAliasing::Off, "off"},
                                                   {AntiAliasing::Fxaa, "fxaa"},
                                                   {AntiAliasing::Taa, "taa"},
                                                   {AntiAliasing::Gbaa, "gbaa"}};
inline constexpr NamedValue<FrameExposure> kExposure[] = {{FrameExposure::Manual, "manual"},
                                                          {FrameExposure::Auto, "auto"}};
inline constexpr NamedValue<AoMode> kAo[] = {
    {AoMode::Off, "off"}, {AoMode::Gtao, "gtao"}, {AoMode::Reference, "reference"}};
inline constexpr NamedValue<SsrMode> kSsr[] = {
    {SsrMode::Off, "off"}, {SsrMode::Hiz, "hiz"}, {SsrMode::Reference, "reference"}};
inline constexpr NamedValue<SkyOcclusionMode> kSkyOcclusion[] = {
    {SkyOcclusionMode::Off, "off"},
    {SkyOcclusionMode::On, "on"},
    {SkyOcclusionMode::Reference, "reference"}};
inline constexpr NamedValue<VolumetricsMode> kVolumetrics[] = {
    {VolumetricsMode::Off, "off"},
    {VolumetricsMode::Volumes, "volumes"},
    {VolumetricsMode::Froxels, "froxels"},
    {VolumetricsMode::Reference, "reference"}};
inline constexpr NamedValue<ScatteringMode> kScattering[] = {
    {ScatteringMode::Off, "off"},
    {ScatteringMode::Epipolar, "epipolar"},
    {ScatteringMode::BruteForce, "brute-force"}};
inline constexpr NamedValue<AreaLightMode> kAreaLights[] = {
    {AreaLightMode::Representative, "representative"}, {AreaLightMode::Ltc, "ltc"}};
inline constexpr NamedValue<HairSelfShadow> kHairSelfShadow[] = {
    {HairSelfShadow::Off, "off"},
    {HairSelfShadow::DepthMap, "map"},
    {HairSelfShadow::Reference, "reference"}};
inline constexpr NamedValue<bool> kSwitch[] = {{false, "off"}, {true, "on"}};
}  // namespace setting_names

// The rows, in the order of the usage text. Preset columns: docs/frame-budget.md gives what
// each lower column saves; `ultra` is the engine's image before presets.
inline constexpr auto kRenderSettingTable = std::tuple{
    RenderSettingRow<BrdfModel>{
        .flag = "--brdf",
        .sceneKey = "brdf",
        .statsName = "brdf",
        .help = "the specular BRDF",
        .value = &RenderSettings::brdf,
        .choice = &RenderSettingChoices::brdf,
        .widget = SettingWidget::Choice,
        .presets = {BrdfModel::EnergyConserving, BrdfModel::EnergyConserving,
                    BrdfModel::EnergyConserving, BrdfModel::EnergyConserving},
        .names = setting_names::kBrdf},
    RenderSettingRow<AreaLightMode>{.flag = "--area-lights",
                                    .sceneKey = "area_lights",
                                    .statsName = "area_lights",
                                    .help = "sphere and tube lights' integration",
                                    .value = &RenderSettings::areaLights,
                                    .choice = &RenderSettingChoices::areaLights,
                                    .widget = SettingWidget::Choice,
                                    .presets = {AreaLightMode::Representative, AreaLightMode::Ltc,
                                                AreaLightMode::Ltc, AreaLightMode::Ltc},
                                    .names = setting_names::kAreaLights},
    // Low keeps TAA: on lavapipe its resolve costs half of FXAA's (7 against 15 ms at 640x360).
    RenderSettingRow<AntiAliasing>{
        .flag = "--aa",
        .sceneKey = "aa",
        .statsName = "aa",
        .help = "antialiasing",
        .value = &RenderSettings::aa,
        .choice = &RenderSettingChoices::aa,
        .widget = SettingWidget::Choice,
        .presets = {AntiAliasing::Taa, AntiAliasing::Taa, AntiAliasing::Taa, AntiAliasing::Taa},
        .names = setting_names::kAa},
    RenderSettingRow<uint32_t>{.flag = "--msaa",
                               .sceneKey = "msaa",
                               .statsName = "msaa",
                               .help = "samples per pixel of the forward (blended) pass, with --aa",
                               .value = &RenderSettings::msaaSamples,
                               .choice = &RenderSettingChoices::msaaSamples,
                               .widget = SettingWidget::Counts,
                               .presets = {1, 1, 1, 1},
                               .least = 1,
                               .most = 8,
                               .placeholder = "1|2|4|8",
                               .expects = "1, 2, 4 or 8 samples per pixel"},
    RenderSettingRow<float>{.flag = "--bloom",
                            .sceneKey = "bloom",
                            .statsName = "bloom",
                            .help = "radiance scattered into glare, 0 (off) to 1",
                            .value = &RenderSettings::bloomStrength,
                            .choice = &RenderSettingChoices::bloomStrength,
                            .widget = SettingWidget::Slider,
                            .presets = {0.0f, 0.04f, 0.04f, 0.04f},
                            .least = 0.0f,
                            .most = 1.0f,
                            .placeholder = "FRACTION",
                            .expects = "a fraction from 0 (off) to 1"},
    RenderSettingRow<float>{.flag = "--render-scale",
                            .sceneKey = "render_scale",
                            .statsName = "render_scale",
                            .help = "width and height the scene renders at, upscaled to the output",
                            .value = &RenderSettings::renderScale,
                            .choice = &RenderSettingChoices::renderScale,
                            .widget = SettingWidget::Slider,
                            .presets = {0.5f, 0.5f, 1.0f, 1.0f},
                            .least = 0.25f,
                            .most = 1.0f,
                            .placeholder = "FRACTION",
                            .expects = "a fraction of the output's size from 0.25 to 1"},
    RenderSettingRow<float>{
        .flag = "--lod-error",
        .sceneKey = "lod_error",
        .statsName = "lod_error",
        .help = "levels of detail: a coarser mesh strays at most this far (0: full meshes)",
        .value = &RenderSettings::lodPixelError,
        .choice = &RenderSettingChoices::lodPixelError,
        .widget = SettingWidget::Slider,
        .presets = {0.5f, 0.25f, 0.25f, 0.0f},
        .least = 0.0f,
        .most = 8.0f,
        .placeholder = "PIXELS",
        .expects = "pixels from 0 (full meshes) to 8"},
    RenderSettingRow<uint32_t>{.flag = "--area-texture-cells",
                               .sceneKey = "area_texture_cells",
                               .statsName = "area_texture_cells",
                               .help = "textured rect lights by LTC: cells per side of the image",
                               .value = &RenderSettings::areaTextureCells,
                               .choice = &RenderSettingChoices::areaTextureCells,
                               .widget = SettingWidget::Counts,
                               .presets = {2, 4, 8, 8},
                               .least = 1,
                               .most = 16,
                               .placeholder = "N",
                               .expects = "1, 2, 4, 8 or 16"},
    RenderSettingRow<uint32_t>{
        .flag = "--froxel-light-cap",
        .sceneKey = "froxel_light_cap",
        .statsName = "froxel_light_cap",
        .help = "most plain lights per froxel cluster lighting the medium (0: all)",
        .value = &RenderSettings::froxelLightCap,
        .choice = &RenderSettingChoices::froxelLightCap,
        .widget = SettingWidget::Count,
        .presets = {16, 32, 0, 0},
        .least = 0,
        .most = 4096,
        .placeholder = "N",
        .expects = "a count from 0 (every light) to 4096"},
    RenderSettingRow<FrameExposure>{.flag = "--exposure",
                                    .sceneKey = "exposure",
                                    .statsName = "exposure",
                                    .help = "the camera's EV100, or metered and adapted",
                                    .value = &RenderSettings::exposure,
                                    .choice = &RenderSettingChoices::exposure,
                                    .widget = SettingWidget::Choice,
                                    .presets = {FrameExposure::Manual, FrameExposure::Manual,
                                                FrameExposure::Manual, FrameExposure::Manual},
                                    .names = setting_names::kExposure},
    RenderSettingRow<float>{.flag = "--exposure-compensation",
                            .sceneKey = "exposure_compensation",
                            .statsName = "exposure_compensation",
                            .help = "auto exposure's bias (+ brightens)",
                            .value = &RenderSettings::exposureCompensation,
                            .choice = &RenderSettingChoices::exposureCompensation,
                            .widget = SettingWidget::Slider,
                            .presets = {0.0f, 0.0f, 0.0f, 0.0f},
                            .least = -16.0f,
                            .most = 16.0f,
                            .placeholder = "EV",
                            .expects = "EV from -16 to 16"},
    RenderSettingRow<AoMode>{.flag = "--ao",
                             .sceneKey = "ambient_occlusion/mode",
                             .statsName = "ambient_occlusion",
                             .help = "sky light occlusion",
                             .value = &RenderSettings::ao,
                             .choice = &RenderSettingChoices::ao,
                             .widget = SettingWidget::Choice,
                             .presets = {AoMode::Off, AoMode::Gtao, AoMode::Gtao, AoMode::Gtao},
                             .names = setting_names::kAo},
    RenderSettingRow<HairSelfShadow>{
        .flag = "--hair-self-shadow",
        .sceneKey = "hair_self_shadow",
        .statsName = "hair_self_shadow",
        .help = "hair's shadow on itself: none, the hair depth map's estimate or every fibre",
        .value = &RenderSettings::hairSelfShadow,
        .choice = &RenderSettingChoices::hairSelfShadow,
        .widget = SettingWidget::Choice,
        .presets = {HairSelfShadow::Off, HairSelfShadow::DepthMap, HairSelfShadow::DepthMap,
                    HairSelfShadow::DepthMap},
        .names = setting_names::kHairSelfShadow},
    // Frames without a surface under SSR's roughness cut-off declare no pass, so only frames
    // with a glossy surface pay (render/README.md "Screen-space reflections").
    RenderSettingRow<SsrMode>{.flag = "--ssr",
                              .sceneKey = "ssr",
                              .statsName = "ssr",
                              .help = "screen-space reflections on glossy surfaces",
                              .value = &RenderSettings::ssr,
                              .choice = &RenderSettingChoices::ssr,
                              .widget = SettingWidget::Choice,
                              .presets = {SsrMode::Off, SsrMode::Off, SsrMode::Hiz, SsrMode::Hiz},
                              .names = setting_names::kSsr},
    // Unchosen, the application turns it on for frames with an atmosphere (frame_settings.cpp).
    RenderSettingRow<SkyOcclusionMode>{
        .flag = "--sky-occlusion",
        .sceneKey = "sky_occlusion",
        .statsName = "sky_occlusion",
        .help = "the scene's geometry blocking the sky's light (default: on with an atmosphere)",
        .value = &RenderSettings::skyOcclusion,
        .choice = &RenderSettingChoices::skyOcclusion,
        .widget = SettingWidget::Choice,
        .presets = {SkyOcclusionMode::Off, SkyOcclusionMode::Off, SkyOcclusionMode::Off,
                    SkyOcclusionMode::Off},
        .names = setting_names::kSkyOcclusion},
    // Unchosen, froxels from 16 lights in the medium (frame_settings.cpp); either draws only
    // in frames with a medium.
    RenderSettingRow<VolumetricsMode>{
        .flag = "--volumetrics",
        .sceneKey = "volumetrics",
        .statsName = "volumetrics",
        .help = "light scattered in the medium (default: volumes, froxels from 16 lights)",
        .value = &RenderSettings::volumetrics,
        .choice = &RenderSettingChoices::volumetrics,
        .widget = SettingWidget::Choice,
        .presets = {VolumetricsMode::Volumes, VolumetricsMode::Volumes, VolumetricsMode::Volumes,
                    VolumetricsMode::Volumes},
        .names = setting_names::kVolumetrics},
    RenderSettingRow<bool>{.flag = "--volume-proxies",
                           .sceneKey = "volume_proxies",
                           .statsName = "volume_proxies",
                           .help = "volumes: each light's proxy mesh rasterised, or tile lists",
                           .value = &RenderSettings::volumeProxies,
                           .choice = &RenderSettingChoices::volumeProxies,
                           .widget = SettingWidget::Toggle,
                           .presets = {false, false, false, false},
                           .names = setting_names::kSwitch},
    // Epipolar stays within 0.22 % of brute force at a 35th of the rays (render/README.md
    // "Light shafts"); the passes draw only in frames whose scene has an atmosphere.
    RenderSettingRow<ScatteringMode>{
        .flag = "--scattering",
        .sceneKey = "scattering",
        .statsName = "scattering",
        .help = "light shafts in the atmosphere's air",
        .value = &RenderSettings::scattering,
        .choice = &RenderSettingChoices::scattering,
        .widget = SettingWidget::Choice,
        .presets = {ScatteringMode::Epipolar, ScatteringMode::Epipolar, ScatteringMode::Epipolar,
                    ScatteringMode::Epipolar},
        .names = setting_names::kScattering},
    RenderSettingRow<uint32_t>{.flag = "--scattering-slices",
                               .sceneKey = "scattering_slices",
                               .statsName = "scattering_slices",
                               .help = "epipolar slices",
                               .value = &RenderSettings::scatteringSlices,
                               .choice = &RenderSettingChoices::scatteringSlices,
                               .widget = SettingWidget::Count,
                               .presets = {128, 256, 512, 512},
                               .least = 1,
                               .most = 4096,
                               .placeholder = "N",
                               .expects = "a count from 1 to 4096"},
    RenderSettingRow<uint32_t>{.flag = "--scattering-samples",
                               .sceneKey = "scattering_samples",
                               .statsName = "scattering_samples",
                               .help = "samples per epipolar slice",
                               .value = &RenderSettings::scatteringSamples,
                               .choice = &RenderSettingChoices::scatteringSamples,
                               .widget = SettingWidget::Count,
                               .presets = {64, 128, 256, 256},
                               .least = 2,
                               .most = 4096,
                               .placeholder = "N",
                               .expects = "a count from 2 to 4096"},
};

// Calls visit(row) for every row, in the table's order.
template <typename Visit>
constexpr void forEachRenderSetting(Visit&& visit) {
    std::apply([&](const auto&... row) { (visit(row), ...); }, kRenderSettingTable);
}

// Where a row's scene key points: a top-level key ("ssr": object empty), or a member of a
// top-level object ("ambient_occlusion/mode").
struct SceneKeyPath {
    std::string_view object;
    std::string_view member;
};
constexpr SceneKeyPath sceneKeyPath(std::string_view key) {
    const std::size_t slash = key.find('/');
    if (slash == std::string_view::npos) return {{}, key};
    return {key.substr(0, slash), key.substr(slash + 1)};
}

// Whether `value` is one the row allows: a named value, or a number in its range (a power of
// two for SettingWidget::Counts; NaN never).
template <typename T>
constexpr bool renderSettingAllows(const RenderSettingRow<T>& row, T value) {
    if (!row.names.empty()) {
        for (const NamedValue<T>& named : row.names) {
            if (named.value == value) return true;
        }
        return false;
    }
    if (!(value >= row.least && value <= row.most)) return false;
    if constexpr (std::is_integral_v<T>) {
        if (row.widget == SettingWidget::Counts) return value != 0 && (value & (value - 1)) == 0;
    }
    return true;
}

// The value's spelling: its name, or the shortest decimal that reads back as the same number.
template <typename T>
std::string renderSettingText(const RenderSettingRow<T>& row, T value) {
    for (const NamedValue<T>& named : row.names) {
        if (named.value == value) return std::string(named.name);
    }
    if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
        char text[32];
        const auto result = std::to_chars(text, text + sizeof text, value);
        return std::string(text, result.ptr);
    }
    return {};
}

// A value from its spelling (a name, or a number as the command line writes it); nothing when
// the text names no value the row allows.
template <typename T>
std::optional<T> parseRenderSetting(const RenderSettingRow<T>& row, std::string_view text) {
    for (const NamedValue<T>& named : row.names) {
        if (named.name == text) return named.value;
    }
    if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
        T value{};
        const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
        if (result.ec == std::errc() && result.ptr == text.data() + text.size() &&
            renderSettingAllows(row, value)) {
            return value;
        }
    }
    return std::nullopt;
}

// The row's value names joined by `separator` ("off|hiz|reference"), or its placeholder.
template <typename T>
std::string renderSettingNames(const RenderSettingRow<T>& row, std::string_view separator = ", ") {
    if (row.names.empty()) return std::string(row.placeholder);
    std::string names;
    for (const NamedValue<T>& named : row.names) {
        if (!names.empty()) names += separator;
        names += named.name;
    }
    return names;
}

// What the row takes, for a message: "off, hiz or reference", or its range's words.
template <typename T>
std::string renderSettingExpects(const RenderSettingRow<T>& row) {
    if (row.names.empty()) return std::string(row.expects);
    std::string names;
    for (std::size_t i = 0; i < row.names.size(); ++i) {
        if (i > 0) names += i + 1 == row.names.size() ? " or " : ", ";
        names += row.names[i].name;
    }
    return names;
}

// The row of an enum setting's type, for its value names.
template <typename E>
std::string renderSettingName(E value) {
    std::string name;
    forEachRenderSetting([&](const auto& row) {
        using T = std::remove_cvref_t<decltype(row.presets[0])>;
        if constexpr (std::is_same_v<T, E>) name = renderSettingText(row, value);
    });
    return name;
}

// Each setting from the first source that chooses it (in `choices`' order: the command line,
// then the scene file), else the preset's column for `level`.
RenderSettings resolveRenderSettings(QualityLevel level,
                                     std::initializer_list<const RenderSettingChoices*> choices);

}  // namespace candela::content
