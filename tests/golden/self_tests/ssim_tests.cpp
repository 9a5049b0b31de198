// SSIM: exact on identical and constant images, symmetric, and what it is for: structure
// (shifts, blur) rather than brightness, which the per-pixel metrics judge.
#include <gtest/gtest.h>

#include <cmath>

#include "golden_comparison.h"
#include "image_perturbations.h"
#include "ssim.h"
#include "synthetic_images.h"

using namespace candela::golden;
using namespace candela::golden::test;

namespace {

LdrImage constant(std::uint32_t size, std::uint8_t value) {
    return LdrImage{size, size, std::vector<std::uint8_t>(std::size_t(size) * size * 3, value)};
}

LdrImage stripes(std::uint32_t size, std::uint32_t period) {
    LdrImage image = constant(size, 0);
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        const std::uint8_t value = (i % size) % period < period / 2 ? 40 : 200;
        image.rgb[i * 3] = image.rgb[i * 3 + 1] = image.rgb[i * 3 + 2] = value;
    }
    return image;
}

}  // namespace

TEST(GoldenSsim, IdenticalImagesScoreExactlyOne) {
    const LdrImage image = tonemapped(syntheticHdr());
    const SsimResult result = ssimOfLuma(image, image);
    EXPECT_EQ(result.mean, 1.0);
    EXPECT_EQ(result.min, 1.0);
    EXPECT_EQ(result.map.size(), image.pixelCount());
}

TEST(GoldenSsim, ConstantImagesGiveTheClosedFormLuminanceTerm) {
    // No variance anywhere: SSIM reduces to (2ab + C1) / (a^2 + b^2 + C1).
    const double c1 = (0.01 * 255) * (0.01 * 255);
    const double expected = (2.0 * 100 * 110 + c1) / (100.0 * 100 + 110.0 * 110 + c1);
    const SsimResult result = ssimOfLuma(constant(20, 100), constant(20, 110));
    EXPECT_NEAR(result.mean, expected, 1e-12);
    EXPECT_NEAR(result.min, expected, 1e-12);
}

TEST(GoldenSsim, IsSymmetric) {
    const LdrImage a = tonemapped(syntheticHdr());
    const LdrImage b = withLevelNoise(a, 0.3, 4, 5);
    EXPECT_DOUBLE_EQ(ssimOfLuma(a, b).mean, ssimOfLuma(b, a).mean);
}

TEST(GoldenSsim, OnePixelShiftOfEdgesScoresBelowTheThreshold) {
    const LdrImage image = stripes(64, 8);
    const SsimResult result = ssimOfLuma(shiftedRight(image, 1), image);
    EXPECT_LT(result.mean, 0.995);
    EXPECT_LT(result.min, 0.8);
}

TEST(GoldenSsim, BrightnessChangeBarelyMovesItButFailsPerPixel) {
    // Why SSIM is not the only metric: 5 levels brighter everywhere passes its threshold...
    const LdrImage image = stripes(64, 8);
    LdrImage brighter = image;
    for (std::uint8_t& v : brighter.rgb) {
        v = std::uint8_t(v + 5);
    }
    const LdrComparison comparison = compareLdrImages(brighter, image, LdrThresholds{});
    EXPECT_GT(comparison.ssim.mean, LdrThresholds{}.minSsim);
    // ...and the per-pixel tolerance catches it.
    EXPECT_FALSE(comparison.passed());
    EXPECT_EQ(comparison.difference.pixelsOverTolerance, image.pixelCount());
}

TEST(GoldenSsim, ImagesSmallerThanTheWindowAreScored) {
    const LdrImage a = stripes(4, 2);
    const SsimResult result = ssimOfLuma(a, shiftedRight(a, 1));
    EXPECT_TRUE(std::isfinite(result.mean));
    EXPECT_LT(result.mean, 1.0);
    EXPECT_EQ(ssimOfLuma(a, a).mean, 1.0);
}
