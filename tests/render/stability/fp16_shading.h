#pragma once
// The shared GLSL terms transliterated operation by operation (same order, same constants) for
// a scalar type T, so they can run in emulated half precision (T = Half) for the fp16 report,
// and in float to check the transliteration against the device. Mirrors
// render/shaders/common/brdf.glsl and lights.glsl; keep in step with them.
#include <algorithm>
#include <cmath>

#include "half_float.h"

namespace candela::stability::emulated {

inline float min(float a, float b) {
    return std::min(a, b);
}
inline float max(float a, float b) {
    return std::max(a, b);
}
inline float saturate(float x) {
    return std::clamp(x, 0.0f, 1.0f);
}
inline float exp2(float x) {
    return std::exp2(x);
}
inline float sqrt(float x) {
    return std::sqrt(x);
}
using stability::exp2;
using stability::max;
using stability::min;
using stability::saturate;
using stability::sqrt;

constexpr float kPi = 3.14159265358979f;

template <class T>
T alphaFromRoughness(T roughness) {
    T r = min(max(roughness, T(0.02f)), T(1.0f));
    return r * r;
}

template <class T>
T distributionGgx(T a2, T NoH) {
    T d = (NoH * a2 - NoH) * NoH + T(1.0f);
    return a2 / (T(kPi) * d * d);
}

template <class T>
T visibilitySmithSchlick(T alpha, T NoV, T NoL) {
    T k = alpha * T(0.5f);
    T gv = NoV * (T(1.0f) - k) + k;
    T gl = NoL * (T(1.0f) - k) + k;
    return T(0.25f) / (gv * gl);
}

template <class T>
T visibilitySmithGgxCorrelated(T alpha, T NoV, T NoL) {
    T a2 = alpha * alpha;
    T lambdaV = NoL * sqrt(NoV * NoV * (T(1.0f) - a2) + a2);
    T lambdaL = NoV * sqrt(NoL * NoL * (T(1.0f) - a2) + a2);
    return T(0.5f) / max(lambdaV + lambdaL, T(1e-12f));
}

template <class T>
T fresnelSchlickSg(T specular, T specularGreen, T VoH) {
    T fc = exp2((T(-5.55473f) * VoH - T(6.98316f)) * VoH);
    return saturate(T(50.0f) * specularGreen) * fc + (T(1.0f) - fc) * specular;
}

template <class T>
T envBrdfApprox(T specular, T roughness, T NoV) {
    T rx = roughness * T(-1.0f) + T(1.0f);
    T ry = roughness * T(-0.0275f) + T(0.0425f);
    T rz = roughness * T(-0.572f) + T(1.04f);
    T rw = roughness * T(0.022f) + T(-0.04f);
    T a004 = min(rx * rx, exp2(T(-9.28f) * NoV)) * rx + ry;
    T scale = T(-1.04f) * a004 + rz;
    T bias = T(1.04f) * a004 + rw;
    return max(specular * scale + bias, T(0.0f));
}

template <class T>
T attenuationWindow(T distanceSq, T invRadius) {
    T ratio2 = distanceSq * invRadius * invRadius;
    T w = saturate(T(1.0f) - ratio2 * ratio2);
    return w * w;
}

template <class T>
T inverseSquare(T distanceSq) {
    return T(1.0f) / (distanceSq + T(1e-4f));
}

}  // namespace candela::stability::emulated
