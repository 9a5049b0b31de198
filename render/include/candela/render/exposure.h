#pragma once
// Camera exposure (SPEC "Units and conventions"): EV100 from aperture, shutter and ISO, or a
// manual EV, minus exposure compensation.
#include <cmath>

#include "candela/content/components/camera.h"

namespace candela::render {

// EV100 = log2(N^2 / t) - log2(S / 100). Non-positive or non-finite settings fall back to the
// "sunny 16" exposure (f/16, 1/100 s, ISO 100, EV100 ~ 14.6) instead of producing NaN.
inline float ev100FromCamera(const content::Camera& camera) {
    float ev100;
    if (camera.exposureMode == content::ExposureMode::Manual) {
        ev100 = camera.manualEv100;
    } else {
        float n = camera.aperture, t = camera.shutterSeconds, s = camera.iso;
        bool valid = n > 0.0f && t > 0.0f && s > 0.0f && std::isfinite(n * n / t * s);
        if (!valid) {
            n = 16.0f;
            t = 0.01f;
            s = 100.0f;
        }
        ev100 = std::log2(n * n / t) - std::log2(s / 100.0f);
    }
    ev100 -= camera.exposureCompensation;
    return std::isfinite(ev100) ? ev100 : 14.6f;
}

}  // namespace candela::render
