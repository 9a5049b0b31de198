// The comparison on real captures of builtin:triangle rendered by `candela run`: the capture
// matches itself and a copy with rounding noise, and fails against a locally changed or a
// shifted copy; the candela-golden CLI reports it and writes the diff images.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "captures.h"
#include "image_perturbations.h"

using namespace candela::golden;
using namespace candela::golden::test;
namespace fs = std::filesystem;

namespace {

std::string fileBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class RealCapture : public testing::Test {
protected:
    void SetUp() override {
        dir_ = testDirectory();
        std::optional<Capture> capture =
            renderAndLoad("builtin:triangle", "256x256", dir_, "triangle");
        ASSERT_TRUE(capture);
        capture_ = *capture;
        ASSERT_EQ(capture_.hdr.image.width, 256u);
        ASSERT_EQ(capture_.ldr.height, 256u);
    }

    void TearDown() override { removeIfPassed(dir_); }

    fs::path dir_;
    Capture capture_;
};

}  // namespace

TEST_F(RealCapture, SameSceneSameFrameGivesIdenticalFiles) {
    ASSERT_TRUE(renderAndLoad("builtin:triangle", "256x256", dir_, "again"));
    EXPECT_EQ(fileBytes(dir_ / "triangle.exr"), fileBytes(dir_ / "again.exr"));
    EXPECT_EQ(fileBytes(dir_ / "triangle.png"), fileBytes(dir_ / "again.png"));
}

TEST_F(RealCapture, MatchesItself) {
    const CaptureComparison c = compareCaptures(capture_, capture_);
    report("triangle vs itself", c);
    EXPECT_TRUE(c.passed());
    EXPECT_EQ(c.hdr.difference.maxErrorInTolerances, 0.0);
    EXPECT_EQ(capture_.hdr.nonFiniteTexels, 0u);
}

TEST_F(RealCapture, OneUlpNoisePasses) {
    Capture noisy = capture_;
    noisy.hdr.image = withUlpNoise(capture_.hdr.image, 3);
    const CaptureComparison c = compareCaptures(noisy, capture_);
    report("triangle with 1-ulp noise on every HDR channel", c);
    EXPECT_TRUE(c.passed());
    EXPECT_GT(c.hdr.difference.maxRelativeDifference, 0.0);
}

TEST_F(RealCapture, SparseOneLevelPngNoisePasses) {
    Capture noisy = capture_;
    noisy.ldr = withLevelNoise(capture_.ldr, 0.01, 1, 4);
    const CaptureComparison c = compareCaptures(noisy, capture_);
    report("triangle PNG with +-1 level on 1% of pixels", c);
    EXPECT_TRUE(c.passed());
    EXPECT_EQ(c.ldr.difference.maxAbsoluteDifference, 1.0);
}

TEST_F(RealCapture, ThreeByThreeBlockFivePercentBrighterFails) {
    // The block sits at the image centre, inside the triangle.
    Capture changed = capture_;
    changed.hdr.image = scaleBlock(capture_.hdr.image, 127, 127, 3, 1.05);
    changed.ldr = scaleBlock(capture_.ldr, 127, 127, 3, 1.05);
    const CaptureComparison c = compareCaptures(changed, capture_);
    report("triangle with a 3x3 block 5% brighter", c);
    EXPECT_FALSE(c.hdr.passed());
    EXPECT_EQ(c.hdr.difference.pixelsOverHardLimit, 9u);
}

TEST_F(RealCapture, ShiftedByOnePixelFails) {
    Capture shifted = capture_;
    shifted.hdr.image = shiftedRight(capture_.hdr.image, 1);
    shifted.ldr = shiftedRight(capture_.ldr, 1);
    const CaptureComparison c = compareCaptures(shifted, capture_);
    report("triangle shifted right by 1 pixel", c);
    EXPECT_FALSE(c.hdr.passed());
    EXPECT_FALSE(c.ldr.passed());
}

TEST_F(RealCapture, CheckCommandFailsAndWritesDiffImages) {
    const fs::path expectedDir = dir_ / "expected";
    fs::create_directories(expectedDir);
    ASSERT_EQ(writeHdrExr(expectedDir / "triangle.exr",
                          scaleBlock(capture_.hdr.image, 127, 127, 3, 1.05)),
              "");
    ASSERT_EQ(writeLdrPng(expectedDir / "triangle.png", shiftedRight(capture_.ldr, 1)), "");

    const CommandResult check =
        runGoldenTool("check triangle --actual-dir " + quoted(dir_.string()) + " --expected-dir " +
                          quoted(expectedDir.string()),
                      dir_ / "check.log");
    EXPECT_EQ(check.exitCode, 1) << check.output;
    EXPECT_NE(check.output.find("golden triangle: FAIL"), std::string::npos) << check.output;
    for (const char* file : {"triangle.expected.exr", "triangle.expected.png",
                             "triangle.diff-hdr.png", "triangle.diff-png.png"}) {
        const fs::path path = dir_ / file;
        EXPECT_TRUE(fs::exists(path)) << file;
        EXPECT_NE(check.output.find(path.string()), std::string::npos) << check.output;
    }
    std::string error;
    std::optional<LdrImage> diff = readLdrPng(dir_ / "triangle.diff-hdr.png", error);
    ASSERT_TRUE(diff) << error;
    const std::uint8_t* centre = &diff->rgb[(128 * 256 + 128) * 3];
    EXPECT_EQ(centre[0], 255);  // the changed block is red: over the hard limit
    EXPECT_EQ(centre[1], 0);
}

TEST_F(RealCapture, CheckCommandPassesAndClearsOldFailureImages) {
    const fs::path expectedDir = dir_ / "expected";
    fs::create_directories(expectedDir);
    fs::copy_file(dir_ / "triangle.exr", expectedDir / "triangle.exr");
    fs::copy_file(dir_ / "triangle.png", expectedDir / "triangle.png");
    std::ofstream(dir_ / "triangle.diff-hdr.png") << "left by an earlier failure";

    const CommandResult check =
        runGoldenTool("check triangle --actual-dir " + quoted(dir_.string()) + " --expected-dir " +
                          quoted(expectedDir.string()),
                      dir_ / "check.log");
    EXPECT_EQ(check.exitCode, 0) << check.output;
    EXPECT_NE(check.output.find("golden triangle: PASS"), std::string::npos);
    EXPECT_NE(check.output.find("SSIM mean 1.000000"), std::string::npos) << check.output;
    EXPECT_FALSE(fs::exists(dir_ / "triangle.diff-hdr.png"));
}

TEST_F(RealCapture, MissingGoldenFailsAndSaysHowToCreateIt) {
    const CommandResult check =
        runGoldenTool("check triangle --actual-dir " + quoted(dir_.string()) + " --expected-dir " +
                          quoted((dir_ / "none").string()),
                      dir_ / "check.log");
    EXPECT_EQ(check.exitCode, 1);
    EXPECT_NE(check.output.find("scripts/update-goldens triangle"), std::string::npos)
        << check.output;
}

TEST_F(RealCapture, CompareCommandOnFiles) {
    const fs::path shifted = dir_ / "shifted.exr";
    ASSERT_EQ(writeHdrExr(shifted, shiftedRight(capture_.hdr.image, 1)), "");
    const std::string self = quoted((dir_ / "triangle.exr").string());
    EXPECT_EQ(runGoldenTool("compare " + self + " " + self, dir_ / "same.log").exitCode, 0);
    const CommandResult differs =
        runGoldenTool("compare " + quoted(shifted.string()) + " " + self + " --diff " +
                          quoted((dir_ / "shift-diff.png").string()),
                      dir_ / "differs.log");
    EXPECT_EQ(differs.exitCode, 1) << differs.output;
    EXPECT_TRUE(fs::exists(dir_ / "shift-diff.png"));
    EXPECT_EQ(runGoldenTool("compare " + self + " " + quoted((dir_ / "triangle.png").string()),
                            dir_ / "mixed.log")
                  .exitCode,
              2);
}
