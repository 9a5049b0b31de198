#include "image_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace candela::golden {

double DifferenceStats::fractionOverTolerance() const {
    return pixelCount() == 0 ? 0.0 : double(pixelsOverTolerance) / double(pixelCount());
}

namespace {

// Fills everything but the per-channel errors, which `channelError(pixel, channel)` gives in
// tolerances; `actualValue`/`expectedValue` report the worst pixel.
template <typename ChannelError, typename Value>
DifferenceStats summarise(std::uint32_t width, std::uint32_t height, double hardLimit,
                          ChannelError channelError, Value actualValue, Value expectedValue) {
    DifferenceStats stats;
    stats.width = width;
    stats.height = height;
    stats.errorInTolerances.resize(stats.pixelCount());
    for (std::size_t i = 0; i < stats.pixelCount(); ++i) {
        double pixelError = 0;
        for (std::size_t c = 0; c < 3; ++c)
            pixelError = std::max(pixelError, channelError(i, c));
        stats.errorInTolerances[i] = float(pixelError);
        if (pixelError > 1.0) ++stats.pixelsOverTolerance;
        if (pixelError > hardLimit) ++stats.pixelsOverHardLimit;
        if (pixelError > stats.maxErrorInTolerances) {
            stats.maxErrorInTolerances = pixelError;
            stats.worstX = std::uint32_t(i % width);
            stats.worstY = std::uint32_t(i / width);
        }
        for (std::size_t c = 0; c < 3; ++c) {
            double a = actualValue(i, c), b = expectedValue(i, c);
            double difference = std::abs(a - b);
            double magnitude = std::max(std::abs(a), std::abs(b));
            stats.maxAbsoluteDifference = std::max(stats.maxAbsoluteDifference, difference);
            if (magnitude > 0) {
                stats.maxRelativeDifference =
                    std::max(stats.maxRelativeDifference, difference / magnitude);
            }
        }
    }
    std::size_t worst = std::size_t(stats.worstY) * width + stats.worstX;
    for (std::size_t c = 0; c < 3; ++c) {
        stats.actualAtWorst[c] = actualValue(worst, c);
        stats.expectedAtWorst[c] = expectedValue(worst, c);
    }
    return stats;
}

}  // namespace

DifferenceStats compareHdr(const HdrImage& actual, const HdrImage& expected,
                           const HdrThresholds& thresholds) {
    auto value = [](const HdrImage& image) {
        return [&image](std::size_t i, std::size_t c) { return double(image.rgb[i * 3 + c]); };
    };
    auto channelError = [&](std::size_t i, std::size_t c) {
        double a = actual.rgb[i * 3 + c], b = expected.rgb[i * 3 + c];
        if (!std::isfinite(a) || !std::isfinite(b)) {
            return std::numeric_limits<double>::infinity();
        }
        double allowed =
            thresholds.relative * std::max(std::abs(a), std::abs(b)) + thresholds.absolute;
        return std::abs(a - b) / allowed;
    };
    return summarise(actual.width, actual.height, thresholds.hardLimitInTolerances, channelError,
                     value(actual), value(expected));
}

DifferenceStats compareLdr(const LdrImage& actual, const LdrImage& expected,
                           const LdrThresholds& thresholds) {
    const double tolerance = thresholds.toleranceLevels();
    auto value = [](const LdrImage& image) {
        return [&image](std::size_t i, std::size_t c) { return double(image.rgb[i * 3 + c]); };
    };
    auto channelError = [&](std::size_t i, std::size_t c) {
        double difference = std::abs(double(actual.rgb[i * 3 + c]) - expected.rgb[i * 3 + c]);
        return difference / tolerance;
    };
    return summarise(actual.width, actual.height, thresholds.hardLimitInTolerances(), channelError,
                     value(actual), value(expected));
}

}  // namespace candela::golden
