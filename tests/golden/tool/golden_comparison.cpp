#include "golden_comparison.h"

#include <cstdarg>
#include <cstdio>

namespace candela::golden {

namespace {

#if defined(__GNUC__)
__attribute__((format(printf, 1, 2)))
#endif
std::string
format(const char* pattern, ...) {
    char buffer[512];
    va_list args;
    va_start(args, pattern);
    std::vsnprintf(buffer, sizeof buffer, pattern, args);
    va_end(args);
    return buffer;
}

template <typename Image>
std::string sizeMismatch(const Image& actual, const Image& expected) {
    return format("size differs: actual %ux%u, expected %ux%u", actual.width, actual.height,
                  expected.width, expected.height);
}

std::string overToleranceFailure(const DifferenceStats& d, double maxFraction) {
    return format("%.4f%% of pixels over tolerance (%llu of %llu), more than %.4f%%",
                  100.0 * d.fractionOverTolerance(), (unsigned long long)d.pixelsOverTolerance,
                  (unsigned long long)d.pixelCount(), 100.0 * maxFraction);
}

}  // namespace

HdrComparison compareHdrImages(const LoadedHdr& actual, const LoadedHdr& expected,
                               const HdrThresholds& thresholds) {
    HdrComparison result;
    result.actualNonFiniteTexels = actual.nonFiniteTexels;
    result.expectedNonFiniteTexels = expected.nonFiniteTexels;
    if (actual.nonFiniteTexels > 0) {
        result.failures.push_back(format("the actual image holds NaN/Inf in %llu texels",
                                         (unsigned long long)actual.nonFiniteTexels));
    }
    if (expected.nonFiniteTexels > 0) {
        result.failures.push_back(format("the expected image holds NaN/Inf in %llu texels",
                                         (unsigned long long)expected.nonFiniteTexels));
    }
    result.sameSize =
        actual.image.width == expected.image.width && actual.image.height == expected.image.height;
    if (!result.sameSize) {
        result.failures.push_back(sizeMismatch(actual.image, expected.image));
        return result;
    }
    result.difference = compareHdr(actual.image, expected.image, thresholds);
    const DifferenceStats& d = result.difference;
    if (d.fractionOverTolerance() > thresholds.maxFractionOverTolerance) {
        result.failures.push_back(overToleranceFailure(d, thresholds.maxFractionOverTolerance));
    }
    if (d.pixelsOverHardLimit > 0) {
        result.failures.push_back(
            format("%llu pixels differ by more than %.0f tolerances (worst %.1f at %u,%u)",
                   (unsigned long long)d.pixelsOverHardLimit, thresholds.hardLimitInTolerances,
                   d.maxErrorInTolerances, d.worstX, d.worstY));
    }
    return result;
}

LdrComparison compareLdrImages(const LdrImage& actual, const LdrImage& expected,
                               const LdrThresholds& thresholds) {
    LdrComparison result;
    result.sameSize = actual.width == expected.width && actual.height == expected.height;
    if (!result.sameSize) {
        result.failures.push_back(sizeMismatch(actual, expected));
        return result;
    }
    result.difference = compareLdr(actual, expected, thresholds);
    result.ssim = ssimOfLuma(actual, expected);
    const DifferenceStats& d = result.difference;
    if (d.fractionOverTolerance() > thresholds.maxFractionOverTolerance) {
        result.failures.push_back(overToleranceFailure(d, thresholds.maxFractionOverTolerance));
    }
    if (d.pixelsOverHardLimit > 0) {
        result.failures.push_back(
            format("%llu pixels differ by more than %d levels (worst %.0f "
                   "at %u,%u)",
                   (unsigned long long)d.pixelsOverHardLimit, thresholds.hardLimitLevels,
                   d.maxAbsoluteDifference, d.worstX, d.worstY));
    }
    if (result.ssim.mean < thresholds.minSsim) {
        result.failures.push_back(
            format("mean SSIM %.6f is below %.6f", result.ssim.mean, thresholds.minSsim));
    }
    return result;
}

std::string describe(const HdrComparison& c, const HdrThresholds& t) {
    const std::string nonFinite =
        format("NaN/Inf texels %llu", (unsigned long long)c.actualNonFiniteTexels);
    if (!c.sameSize) return "HDR: not compared (" + nonFinite + ")";
    const DifferenceStats& d = c.difference;
    return format(
               "HDR: over tolerance %llu of %llu px = %.4f%% (fails above %.4f%%); worst %.2f "
               "tolerances at %u,%u (fails above %.0f): actual %.6g %.6g %.6g, expected %.6g "
               "%.6g %.6g cd/m^2; max |a-b| %.3g cd/m^2, max relative %.3g; ",
               (unsigned long long)d.pixelsOverTolerance, (unsigned long long)d.pixelCount(),
               100.0 * d.fractionOverTolerance(), 100.0 * t.maxFractionOverTolerance,
               d.maxErrorInTolerances, d.worstX, d.worstY, t.hardLimitInTolerances,
               d.actualAtWorst[0], d.actualAtWorst[1], d.actualAtWorst[2], d.expectedAtWorst[0],
               d.expectedAtWorst[1], d.expectedAtWorst[2], d.maxAbsoluteDifference,
               d.maxRelativeDifference) +
           nonFinite;
}

std::string describe(const LdrComparison& c, const LdrThresholds& t) {
    if (!c.sameSize) return "PNG: not compared";
    const DifferenceStats& d = c.difference;
    return format(
        "PNG: over %d levels %llu of %llu px = %.4f%% (fails above %.4f%%); worst %.0f levels "
        "at %u,%u (fails above %d); SSIM mean %.6f (fails below %.4f), min %.4f",
        t.levels, (unsigned long long)d.pixelsOverTolerance, (unsigned long long)d.pixelCount(),
        100.0 * d.fractionOverTolerance(), 100.0 * t.maxFractionOverTolerance,
        d.maxAbsoluteDifference, d.worstX, d.worstY, t.hardLimitLevels, c.ssim.mean, t.minSsim,
        c.ssim.min);
}

}  // namespace candela::golden
