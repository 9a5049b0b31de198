#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <vector>

#include "candela/content/exr_image.h"
#include "test_paths.h"

namespace candela::content {
namespace {

std::filesystem::path envAsset(const char* name) {
    return std::filesystem::path(CANDELA_SHARED_ASSETS) / "env" / name;
}

TEST(ExrImage, WriteThenReadRoundTripsFloatRgbExactly) {
    const std::uint32_t width = 7, height = 3;
    std::vector<float> rgb(width * height * 3);
    for (std::size_t i = 0; i < rgb.size(); ++i)
        rgb[i] = 0.001f * static_cast<float>(i * i) + 1e-7f;
    const auto path = testing::tempPath("roundtrip.exr");
    ASSERT_EQ(writeExrRgbFloat(path, width, height, rgb.data()), "");

    Diagnostics diagnostics;
    auto image = readExrImage(path, diagnostics);
    ASSERT_TRUE(image) << diagnostics.toString();
    EXPECT_EQ(image->image.width, width);
    EXPECT_EQ(image->image.height, height);
    for (std::uint32_t y = 0; y < height; ++y) {
        for (std::uint32_t x = 0; x < width; ++x) {
            const float* t = image->image.texel(x, y);
            const std::size_t i = (y * width + x) * 3;
            EXPECT_EQ(t[0], rgb[i]);
            EXPECT_EQ(t[1], rgb[i + 1]);
            EXPECT_EQ(t[2], rgb[i + 2]);
            EXPECT_EQ(t[3], 1.0f) << "missing alpha must read as opaque";
        }
    }
    EXPECT_TRUE(diagnostics.messages.empty());
}

TEST(ExrImage, WriterRejectsBadArguments) {
    EXPECT_NE(writeExrRgbFloat(testing::tempPath("zero.exr"), 0, 4, nullptr), "");
    const float pixel[3] = {1, 2, 3};
    EXPECT_NE(writeExrRgbFloat("/nonexistent-dir/x.exr", 1, 1, pixel), "");
}

TEST(ExrImage, NonFiniteTexelsAreReplacedAndReported) {
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::vector<float> rgb = {1, 2, 3, nan, 0, 0, 0, inf, -inf, 4, 5, 6};
    const auto path = testing::tempPath("nonfinite.exr");
    ASSERT_EQ(writeExrRgbFloat(path, 2, 2, rgb.data()), "");
    Diagnostics diagnostics;
    auto image = readExrImage(path, diagnostics);
    ASSERT_TRUE(image);
    EXPECT_EQ(image->replacedNonFiniteTexels, 2u);
    EXPECT_TRUE(diagnostics.mentions("NaN or Inf"));
    EXPECT_EQ(image->image.texel(1, 0)[0], 0.0f);
    EXPECT_EQ(image->image.texel(0, 1)[1], 65504.0f) << "+Inf (an overflowed sun) stays bright";
    EXPECT_EQ(image->image.texel(0, 1)[2], 0.0f);
    EXPECT_EQ(image->image.texel(1, 1)[2], 6.0f);
    for (float v : image->image.rgba)
        EXPECT_TRUE(std::isfinite(v));
}

TEST(ExrImage, ReadsHalfFloatLatLongAsset) {
    Diagnostics diagnostics;
    auto image = readExrImage(envAsset("studio_small_03_1k.exr"), diagnostics);
    ASSERT_TRUE(image) << diagnostics.toString();
    EXPECT_EQ(image->image.width, 1024u);
    EXPECT_EQ(image->image.height, 512u);
    double sum = 0;
    for (std::size_t i = 0; i < image->image.rgba.size(); i += 4)
        sum += image->image.rgba[i];
    EXPECT_GT(sum, 0.0) << "a studio environment is not black";
}

TEST(ExrImage, ReadsEnvmapAttributeOfOpenExrSamples) {
    Diagnostics diagnostics;
    auto cube = readExrImage(envAsset("StageEnvCube.exr"), diagnostics);
    ASSERT_TRUE(cube) << diagnostics.toString();
    EXPECT_EQ(cube->envmap, ExrEnvmapAttribute::Cube);
    EXPECT_EQ(cube->image.height, cube->image.width * 6);
    auto latLong = readExrImage(envAsset("StageEnvLatLong.exr"), diagnostics);
    ASSERT_TRUE(latLong) << diagnostics.toString();
    EXPECT_EQ(latLong->envmap, ExrEnvmapAttribute::LatLong);
}

TEST(ExrImage, MissingFileIsAnErrorNamingTheFile) {
    Diagnostics diagnostics;
    EXPECT_FALSE(readExrImage("/no/such/file.exr", diagnostics));
    EXPECT_TRUE(diagnostics.mentions("/no/such/file.exr"));
    EXPECT_TRUE(diagnostics.hasErrors());
}

TEST(ExrImage, TruncatedFilesAreErrorsAtEveryLength) {
    std::ifstream in(envAsset("WavyLinesLatLong.exr"), std::ios::binary);
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_GT(bytes.size(), 1000u);
    for (std::size_t length : {std::size_t{0}, std::size_t{4}, std::size_t{20}, std::size_t{300},
                               bytes.size() / 4, bytes.size() / 2}) {
        Diagnostics diagnostics;
        auto image = readExrImageFromMemory(
            std::span(reinterpret_cast<const std::byte*>(bytes.data()), length), "cut.exr",
            diagnostics);
        EXPECT_FALSE(image) << "length " << length;
        EXPECT_TRUE(diagnostics.hasErrors()) << "length " << length;
    }
}

TEST(ExrImage, EveryDamagedFileInBadExrGivesAnError) {
    const auto folder = std::filesystem::path(CANDELA_SHARED_ASSETS) / "bad" / "exr";
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        if (entry.path().extension() != ".exr") continue;
        ++files;
        Diagnostics diagnostics;
        auto image = readExrImage(entry.path(), diagnostics);
        // A damaged file may still decode to something; what matters is no crash, no hang, and
        // an error whenever there is no image.
        if (!image) {
            EXPECT_TRUE(diagnostics.hasErrors()) << entry.path();
            EXPECT_TRUE(diagnostics.mentions(entry.path().filename().string())) << entry.path();
        }
    }
    EXPECT_GT(files, 80u);
}

}  // namespace
}  // namespace candela::content
