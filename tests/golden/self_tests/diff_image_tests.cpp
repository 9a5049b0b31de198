// The false-colour diff: each class of error gets its colour, at the right pixel.
#include <gtest/gtest.h>

#include <array>

#include "diff_image.h"

using namespace candela::golden;

namespace {

std::array<int, 3> pixel(const LdrImage& image, std::size_t i) {
    return {image.rgb[i * 3], image.rgb[i * 3 + 1], image.rgb[i * 3 + 2]};
}

}  // namespace

TEST(GoldenDiffImage, ColoursFollowTheErrorClass) {
    // identical, within tolerance, over tolerance, near the limit, over the limit
    const std::vector<float> errors = {0.0f, 0.5f, 1.5f, 9.5f, 40.0f};
    const std::vector<float> backdrop = {200, 200, 200, 200, 200};
    const LdrImage diff = falseColourDiff(errors, backdrop, 5, 1, 10.0);
    ASSERT_EQ(diff.width, 5u);
    ASSERT_EQ(diff.rgb.size(), 15u);

    const auto grey = pixel(diff, 0);
    EXPECT_EQ(grey[0], grey[1]);
    EXPECT_EQ(grey[1], grey[2]);
    EXPECT_LT(grey[0], 100);  // dimmed backdrop

    const auto blue = pixel(diff, 1);
    EXPECT_EQ(blue[0], 0);
    EXPECT_GT(blue[2], 150);

    const auto yellow = pixel(diff, 2), orange = pixel(diff, 3);
    EXPECT_EQ(yellow[0], 255);
    EXPECT_EQ(yellow[2], 0);
    EXPECT_GT(yellow[1], 200);
    EXPECT_EQ(orange[0], 255);
    EXPECT_LT(orange[1], 140);

    EXPECT_EQ(pixel(diff, 4), (std::array<int, 3>{255, 0, 0}));
}

TEST(GoldenDiffImage, HdrBackdropPutsTheMeanAtMidGrey) {
    HdrImage image{2, 1, {1, 1, 1, 3, 3, 3}};  // mean luminance 2
    const std::vector<float> grey = backdropFromHdr(image);
    ASSERT_EQ(grey.size(), 2u);
    EXPECT_NEAR(grey[0], 255.0 * (0.5 / 1.5), 1e-3);
    EXPECT_NEAR(grey[1], 255.0 * (1.5 / 2.5), 1e-3);
}
