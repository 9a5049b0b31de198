#pragma once
// Photometric conversions between glTF KHR_lights_punctual and the engine Light component.
#include <algorithm>
#include <cmath>
#include <numbers>

namespace candela::content {

// A light without a glTF `range` reaches as far as its illuminance stays at or above this
// value. 0.05 lux is about a quarter of full-moon light: below what daylight or interior
// exposures can show, while an 800 lm bulb still gets a compact 36 m radius for clustering.
inline constexpr float kNoRangeIlluminanceThresholdLux = 0.05f;
inline constexpr float kMinAttenuationRadius = 0.01f;      // metres
inline constexpr float kMaxAttenuationRadius = 100000.0f;  // metres

// Point and spot lights: luminous intensity I (candela) over the full sphere, I = lm / (4 pi),
// spot lights included so the cone angle does not change brightness (SPEC.md).
inline float lumensFromCandela(float candela) {
    return candela * 4.0f * std::numbers::pi_v<float>;
}
inline float candelaFromLumens(float lumens) {
    return lumens / (4.0f * std::numbers::pi_v<float>);
}

// Distance at which I / d^2 (times the brightest colour channel) falls to the threshold,
// clamped to [kMinAttenuationRadius, kMaxAttenuationRadius].
inline float attenuationRadiusForIntensity(float candela, float maxColorChannel,
                                           float thresholdLux = kNoRangeIlluminanceThresholdLux) {
    const float intensity = std::max(candela * maxColorChannel, 0.0f);
    const float radius = std::sqrt(intensity / thresholdLux);
    if (!std::isfinite(radius)) return kMaxAttenuationRadius;
    return std::clamp(radius, kMinAttenuationRadius, kMaxAttenuationRadius);
}

}  // namespace candela::content
