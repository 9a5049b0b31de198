#pragma once
// What "the same image" means for a golden test. README.md "Golden tests" gives the reasoning
// with measured values; the short version is next to each number.
#include <cstdint>

namespace candela::golden {

struct HdrThresholds {
    // Per channel: |a - b| <= relative * max(|a|, |b|) + absolute. The relative part is ~8000
    // float ulps, far above the few ulps a changed driver or FMA contraction moves a value,
    // and far below the ~1e-2 a visible change makes (a 5% brighter light is 50x over).
    double relative = 1e-3;
    double absolute = 1e-4;  // cd/m^2; keeps near-black pixels from failing on noise
    // Isolated pixels may exceed the tolerance (a rounding flip at a triangle edge), but no
    // more than this fraction of the image...
    double maxFractionOverTolerance = 1e-3;
    // ...and none by more than this many tolerances, so a small local change (a 3x3 block
    // 5% brighter) fails even though it touches far fewer pixels than the fraction allows.
    double hardLimitInTolerances = 10.0;
};

struct LdrThresholds {
    // Per channel, in 8-bit sRGB levels: one level is a rounding flip of the final
    // quantisation; two allow a different pow()/exp2() in the tonemapper on another driver.
    int levels = 2;           // at least 1
    int hardLimitLevels = 8;  // ~3% of the display range: visible side by side on flat areas
    double maxFractionOverTolerance = 1e-3;
    // Mean SSIM of the sRGB luma (Rec. 709 weights, 11x11 Gaussian window, sigma 1.5).
    double minSsim = 0.995;

    // Levels are whole numbers; a tolerance below one level would make every change count.
    int toleranceLevels() const { return levels < 1 ? 1 : levels; }
    double hardLimitInTolerances() const { return double(hardLimitLevels) / toleranceLevels(); }
};

struct GoldenThresholds {
    HdrThresholds hdr;
    LdrThresholds ldr;
};

}  // namespace candela::golden
