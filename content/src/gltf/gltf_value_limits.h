#pragma once
// How large a number a glTF file's transforms, deformations and keyframes may hold. Past a
// billion (metres, or a weight) single-precision products overflow once composed: a skin whose
// inverse bind matrix held 3e38, or a morph delta or weight of 3e38, made its mesh vanish.
#include <algorithm>
#include <cmath>
#include <span>

namespace candela::content::gltf {

inline constexpr float kMaxGltfMagnitude = 1e9f;

inline bool usableMagnitude(float value) {
    return std::isfinite(value) && std::fabs(value) <= kMaxGltfMagnitude;
}

inline bool allUsableMagnitudes(std::span<const float> values) {
    return std::all_of(values.begin(), values.end(), usableMagnitude);
}

}  // namespace candela::content::gltf
