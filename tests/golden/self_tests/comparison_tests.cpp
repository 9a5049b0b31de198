// The golden comparison on synthetic images: what must pass (identical, rounding noise,
// sparse small errors) and what must fail (a small local change, a shift, NaN, wrong size).
#include <gtest/gtest.h>

#include <filesystem>
#include <limits>

#include "engine_runner.h"
#include "golden_comparison.h"
#include "image_perturbations.h"
#include "synthetic_images.h"

using namespace candela::golden;
using namespace candela::golden::test;

namespace {

const GoldenThresholds kThresholds;

HdrComparison compareHdr(const HdrImage& actual, const HdrImage& expected) {
    return compareHdrImages({actual, 0}, {expected, 0}, kThresholds.hdr);
}

LdrComparison compareLdr(const LdrImage& actual, const LdrImage& expected) {
    return compareLdrImages(actual, expected, kThresholds.ldr);
}

bool mentions(const std::vector<std::string>& failures, const std::string& needle) {
    for (const std::string& failure : failures) {
        if (failure.find(needle) != std::string::npos) return true;
    }
    return false;
}

// Sets every channel of `count` pixels spread over the image to `toleranceMultiple` times
// the HDR tolerance away from the expected value.
HdrImage withSparseErrors(HdrImage image, std::size_t count, double toleranceMultiple) {
    const std::size_t step = image.pixelCount() / count;
    for (std::size_t n = 0; n < count; ++n) {
        for (std::size_t c = 0; c < 3; ++c) {
            float& value = image.rgb[n * step * 3 + c];
            const double allowed = kThresholds.hdr.relative * value + kThresholds.hdr.absolute;
            // The tolerance uses max(|a|, |b|); solve so the error is the multiple of it.
            const double delta =
                toleranceMultiple * allowed / (1.0 - toleranceMultiple * kThresholds.hdr.relative);
            value = float(value + delta);
        }
    }
    return image;
}

}  // namespace

TEST(GoldenComparison, IdenticalImagesPassWithZeroError) {
    const HdrImage hdr = syntheticHdr();
    const HdrComparison h = compareHdr(hdr, hdr);
    const LdrComparison l = compareLdr(tonemapped(hdr), tonemapped(hdr));
    EXPECT_TRUE(h.passed());
    EXPECT_TRUE(l.passed());
    EXPECT_EQ(h.difference.maxErrorInTolerances, 0.0);
    EXPECT_EQ(l.difference.maxAbsoluteDifference, 0.0);
    EXPECT_EQ(l.ssim.mean, 1.0);
}

TEST(GoldenComparison, OneUlpNoiseOnEveryChannelPasses) {
    const HdrImage expected = syntheticHdr();
    const HdrComparison h = compareHdr(withUlpNoise(expected, 7), expected);
    EXPECT_TRUE(h.passed()) << describe(h, kThresholds.hdr);
    EXPECT_EQ(h.difference.pixelsOverTolerance, 0u);
    EXPECT_GT(h.difference.maxAbsoluteDifference, 0.0);  // the noise is really there
    EXPECT_LT(h.difference.maxErrorInTolerances, 1e-3);
}

TEST(GoldenComparison, ThreeByThreeBlockFivePercentBrighterFails) {
    const HdrImage expected = syntheticHdr();
    const HdrImage actual = scaleBlock(expected, 20, 100, 3, 1.05);
    const HdrComparison h = compareHdr(actual, expected);
    EXPECT_FALSE(h.passed());
    EXPECT_EQ(h.difference.pixelsOverTolerance, 9u);
    // 9 of 16384 pixels is under the 0.1% the fraction allows: the hard limit catches it.
    EXPECT_LT(h.difference.fractionOverTolerance(), kThresholds.hdr.maxFractionOverTolerance);
    EXPECT_EQ(h.difference.pixelsOverHardLimit, 9u);
    EXPECT_TRUE(mentions(h.failures, "more than 10 tolerances")) << describe(h, kThresholds.hdr);
    EXPECT_EQ(h.difference.worstX, 20u);
    EXPECT_GE(h.difference.worstY, 100u);
}

TEST(GoldenComparison, ImageShiftedByOnePixelFails) {
    const HdrImage expected = syntheticHdr();
    const HdrComparison h = compareHdr(shiftedRight(expected, 1), expected);
    const LdrComparison l = compareLdr(shiftedRight(tonemapped(expected), 1), tonemapped(expected));
    EXPECT_FALSE(h.passed());
    EXPECT_FALSE(l.passed());
    EXPECT_GT(h.difference.fractionOverTolerance(), kThresholds.hdr.maxFractionOverTolerance);
}

TEST(GoldenComparison, SparseErrorsJustOverToleranceFailOnlyAboveTheFraction) {
    const HdrImage expected = syntheticHdr();  // 16384 pixels: 0.1% is 16.4
    const HdrComparison few = compareHdr(withSparseErrors(expected, 8, 3.0), expected);
    const HdrComparison many = compareHdr(withSparseErrors(expected, 33, 3.0), expected);
    EXPECT_TRUE(few.passed()) << describe(few, kThresholds.hdr);
    EXPECT_EQ(few.difference.pixelsOverTolerance, 8u);
    EXPECT_FALSE(many.passed());
    EXPECT_EQ(many.difference.pixelsOverTolerance, 33u);
    EXPECT_TRUE(mentions(many.failures, "of pixels over tolerance"));
}

TEST(GoldenComparison, ErrorsWithinToleranceEverywherePass) {
    const HdrImage expected = syntheticHdr();
    const HdrComparison h = compareHdr(withSparseErrors(expected, 16384, 0.9), expected);
    EXPECT_TRUE(h.passed()) << describe(h, kThresholds.hdr);
    EXPECT_GT(h.difference.maxErrorInTolerances, 0.85);
}

TEST(GoldenComparison, AbsoluteToleranceCoversNearBlackOnly) {
    HdrImage black{16, 16, std::vector<float>(16 * 16 * 3, 0.0f)};
    HdrImage faint = black, visible = black;
    for (float& v : faint.rgb)
        v = 5e-5f;  // half the absolute tolerance
    for (float& v : visible.rgb)
        v = 2e-3f;  // 20x it
    EXPECT_TRUE(compareHdr(faint, black).passed());
    EXPECT_FALSE(compareHdr(visible, black).passed());
}

TEST(GoldenComparison, NonFiniteActualOrExpectedFails) {
    const HdrImage image = syntheticHdr();
    EXPECT_TRUE(mentions(compareHdrImages({image, 1}, {image, 0}, kThresholds.hdr).failures,
                         "actual image holds NaN/Inf in 1 texels"));
    EXPECT_TRUE(mentions(compareHdrImages({image, 0}, {image, 2}, kThresholds.hdr).failures,
                         "expected image holds NaN/Inf"));
}

TEST(GoldenComparison, NanWrittenToAnExrIsCaughtWhenReadBack) {
    HdrImage image = syntheticHdr(16, 16);
    image.rgb[40] = std::numeric_limits<float>::quiet_NaN();
    image.rgb[41] = std::numeric_limits<float>::infinity();  // same texel
    image.rgb[90] = -std::numeric_limits<float>::infinity();
    const std::filesystem::path dir = testDirectory();
    const std::filesystem::path path = dir / "nan.exr";
    ASSERT_EQ(writeHdrExr(path, image), "");
    std::string error;
    std::optional<LoadedHdr> loaded = readHdrExr(path, error);
    ASSERT_TRUE(loaded) << error;
    EXPECT_EQ(loaded->nonFiniteTexels, 2u);
    const HdrComparison h = compareHdrImages(*loaded, {syntheticHdr(16, 16), 0}, kThresholds.hdr);
    EXPECT_FALSE(h.passed());
    EXPECT_TRUE(mentions(h.failures, "NaN/Inf in 2 texels"));
    removeIfPassed(dir);
}

TEST(GoldenComparison, SizeMismatchFails) {
    const HdrImage big = syntheticHdr(64, 64), small = syntheticHdr(64, 32);
    const HdrComparison h = compareHdr(big, small);
    const LdrComparison l = compareLdr(tonemapped(big), tonemapped(small));
    EXPECT_FALSE(h.sameSize);
    EXPECT_TRUE(mentions(h.failures, "actual 64x64, expected 64x32"));
    EXPECT_FALSE(l.passed());
}

TEST(GoldenComparison, PngTwoLevelsOffInEveryLitPixelPasses) {
    // Black is left alone: SSIM's luminance term is steep there (C1 = 6.5 levels^2), so a
    // black level lifted by 2 over a large area fails on SSIM (README.md "Golden tests").
    const LdrImage expected = tonemapped(syntheticHdr());
    LdrImage actual = expected;
    for (std::uint8_t& v : actual.rgb) {
        if (v >= 16) v = std::uint8_t(v <= 253 ? v + 2 : v - 2);
    }
    const LdrComparison l = compareLdr(actual, expected);
    EXPECT_TRUE(l.passed()) << describe(l, kThresholds.ldr);
    EXPECT_EQ(l.difference.maxAbsoluteDifference, 2.0);
}

TEST(GoldenComparison, PngThreeLevelsOnOnePercentOfPixelsFails) {
    const LdrImage expected = tonemapped(syntheticHdr());
    const LdrComparison l = compareLdr(withLevelNoise(expected, 0.01, 3, 11), expected);
    EXPECT_FALSE(l.passed());
    EXPECT_TRUE(mentions(l.failures, "of pixels over tolerance")) << describe(l, kThresholds.ldr);
}

TEST(GoldenComparison, PngOnePixelNineLevelsOffFails) {
    const LdrImage expected = tonemapped(syntheticHdr());
    LdrImage actual = expected;
    actual.rgb[3 * (120 * 128 + 10) + 1] = std::uint8_t(expected.rgb[3 * (120 * 128 + 10) + 1] + 9);
    const LdrComparison l = compareLdr(actual, expected);
    EXPECT_FALSE(l.passed());
    EXPECT_EQ(l.difference.pixelsOverHardLimit, 1u);
    EXPECT_EQ(l.difference.worstX, 10u);
    EXPECT_EQ(l.difference.worstY, 120u);
}
