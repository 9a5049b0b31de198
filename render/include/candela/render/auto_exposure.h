#pragma once
// Automatic exposure (eye adaptation): the frame's luminance histogram metered in EV100, and
// the exposure moving towards it at a speed per direction. Pure functions: the renderer feeds
// them the histogram it read back, tests feed them their own.
#include <cstdint>
#include <optional>
#include <span>

namespace candela::render {

struct AutoExposureSettings {
    float compensation = 0.0f;  // EV: positive brightens the image (targets EV100 - this)
    // Exponential adaptation rates, 1/s: the exposure covers 1 - e^(-rate * t) of the way to
    // the metered value in t seconds, so it never overshoots. Eyes adapt to brightness faster
    // than to darkness.
    float brighteningRate = 3.0f;  // the scene got brighter (EV100 rises)
    float darkeningRate = 1.0f;    // the scene got darker
    float minEv100 = -4.0f;
    float maxEv100 = 20.0f;
    // The metered part of the histogram, as fractions of the counted pixels: the brighter
    // half, without the brightest 5% (bulbs, the sun's highlights).
    float lowFraction = 0.5f;
    float highFraction = 0.95f;
};

// The mean EV100 of the pixels between lowFraction and highFraction of the histogram
// (luminance_histogram.comp's bins); empty when no pixel was counted (a black frame).
std::optional<float> meterEv100(std::span<const uint32_t> bins,
                                const AutoExposureSettings& settings);

// One frame of adaptation from `current` towards `metered` (compensated, clamped).
float adaptEv100(float current, float metered, float deltaSeconds,
                 const AutoExposureSettings& settings);

// The EV100 a histogram bin stands for (its centre).
float histogramBinEv100(uint32_t bin);

}  // namespace candela::render
