#include "candela/render/auto_exposure.h"

#include <algorithm>
#include <cmath>

#include "passes/exposure/exposure_bindings.h"

namespace candela::render {

float histogramBinEv100(uint32_t bin) {
    return float(HISTOGRAM_MIN_EV100) + (float(bin) + 0.5f) / float(HISTOGRAM_BINS_PER_EV);
}

std::optional<float> meterEv100(std::span<const uint32_t> bins,
                                const AutoExposureSettings& settings) {
    double total = 0.0;
    for (uint32_t count : bins)
        total += count;
    if (total <= 0.0) return std::nullopt;
    // Walk the bins from dark to bright, weighing each by the part of its pixels that falls
    // between the two fractions of the total.
    const double low = total * settings.lowFraction;
    const double high = total * std::max(settings.highFraction, settings.lowFraction);
    double below = 0.0, weighted = 0.0, weight = 0.0;
    for (uint32_t bin = 0; bin < bins.size(); ++bin) {
        const double from = std::max(below, low);
        const double to = std::min(below + bins[bin], high);
        if (to > from) {
            weighted += (to - from) * histogramBinEv100(bin);
            weight += to - from;
        }
        below += bins[bin];
    }
    if (weight <= 0.0) {  // a single bright bin holds both fractions
        for (uint32_t bin = uint32_t(bins.size()); bin-- > 0;) {
            if (bins[bin] > 0) return histogramBinEv100(bin);
        }
    }
    return float(weighted / weight);
}

float adaptEv100(float current, float metered, float deltaSeconds,
                 const AutoExposureSettings& settings) {
    const float target =
        std::clamp(metered - settings.compensation, settings.minEv100, settings.maxEv100);
    const float rate = target > current ? settings.brighteningRate : settings.darkeningRate;
    const float covered = 1.0f - std::exp(-rate * std::max(deltaSeconds, 0.0f));
    return current + (target - current) * covered;
}

}  // namespace candela::render
