// The irradiance of a uniformly emitting sphere, horizon included: shared by the sphere lights
// of lights.glsl and by the LTC disk integral (ltc_disk.glsl), whose equivalent sphere it clips.
#ifndef CANDELA_SPHERE_IRRADIANCE_GLSL
#define CANDELA_SPHERE_IRRADIANCE_GLSL

#include "common/math.glsl"

// Exact irradiance factor of a uniformly emitting sphere seen at angle theta from the normal
// (cosTheta) with angular radius sigma (sinSigmaSq), including the part below the horizon
// (Snyder 1996). Multiply by the sphere's luminance. Reduces to pi sin^2(sigma) cos(theta)
// when the sphere is fully above the horizon.
float sphereIrradianceFactor(float cosTheta, float sinSigmaSq) {
    sinSigmaSq = min(sinSigmaSq, 1.0);
    if (sinSigmaSq >= 1.0) {
        // On (or in) the sphere it fills the half space toward its centre: pi (1 + cos) / 2,
        // the limit of the formula below as sin(sigma) -> 1. pi * saturate(cosTheta) here
        // jumped by up to pi / 2 at the sphere's surface (found by tests/render/stability).
        return PI * 0.5 * (1.0 + cosTheta);
    }
    if (cosTheta * cosTheta > sinSigmaSq) {
        return PI * sinSigmaSq * saturate(cosTheta);
    }
    float sinTheta = sqrt(max(1.0 - cosTheta * cosTheta, 0.0));
    float x = sqrt(max(1.0 / sinSigmaSq - 1.0, 0.0));
    float y = clamp(-x * cosTheta / max(sinTheta, 1e-12), -1.0, 1.0);
    float sinThetaSqrtY = sinTheta * sqrt(max(1.0 - y * y, 0.0));
    float e = (cosTheta * acos(y) - x * sinThetaSqrtY) * sinSigmaSq +
              atan(sinThetaSqrtY, max(x, 1e-12));
    return max(e, 0.0);
}

#endif
