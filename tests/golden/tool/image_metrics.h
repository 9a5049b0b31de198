#pragma once
// Per-pixel differences between an actual and an expected image, measured in units of the
// tolerance, so HDR (relative + absolute cd/m^2) and LDR (levels) are summarised the same way.
#include <array>
#include <cstdint>
#include <vector>

#include "golden_image.h"
#include "golden_thresholds.h"

namespace candela::golden {

struct DifferenceStats {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::uint64_t pixelsOverTolerance = 0;  // any channel over one tolerance
    std::uint64_t pixelsOverHardLimit = 0;
    double maxErrorInTolerances = 0;  // the worst channel of the worst pixel
    std::uint32_t worstX = 0;
    std::uint32_t worstY = 0;
    std::array<double, 3> actualAtWorst{};
    std::array<double, 3> expectedAtWorst{};
    double maxAbsoluteDifference = 0;  // native units: cd/m^2 or levels
    double maxRelativeDifference = 0;  // |a - b| / max(|a|, |b|), HDR only
    // Per pixel, the largest channel error in tolerances (0: identical, > 1: over tolerance).
    std::vector<float> errorInTolerances;

    std::uint64_t pixelCount() const { return std::uint64_t(width) * height; }
    double fractionOverTolerance() const;
};

// Both images must have the same size (callers check and report a mismatch themselves).
DifferenceStats compareHdr(const HdrImage& actual, const HdrImage& expected,
                           const HdrThresholds& thresholds);
DifferenceStats compareLdr(const LdrImage& actual, const LdrImage& expected,
                           const LdrThresholds& thresholds);

}  // namespace candela::golden
