#include <gtest/gtest.h>

#include "candela/content/mip_generation.h"

namespace candela::content {
namespace {

Rgba8Image checker2x2() {
    Rgba8Image image;
    image.width = 2;
    image.height = 2;
    image.rgba = {0, 0, 0, 255, 255, 255, 255, 0, 255, 255, 255, 0, 0, 0, 0, 255};
    return image;
}

TEST(MipGeneration, SrgbAveragesInLinearLightAndLinearAsStored) {
    const auto srgb = generateMipChain(checker2x2(), ColorSpace::Srgb);
    const auto linear = generateMipChain(checker2x2(), ColorSpace::Linear);
    ASSERT_EQ(srgb.size(), 2u);
    ASSERT_EQ(linear.size(), 2u);
    // Half black, half white is 0.5 in linear light, which sRGB encodes as 188 (not 128).
    EXPECT_EQ(srgb[1].rgba[0], 188);
    EXPECT_EQ(linear[1].rgba[0], 128);
    EXPECT_EQ(srgb[1].rgba[3], 128) << "alpha is linear in both";
    EXPECT_EQ(linear[1].rgba[3], 128);
}

TEST(MipGeneration, OddSizesHalveDownToOneTexel) {
    Rgba8Image image;
    image.width = 5;
    image.height = 3;
    image.rgba.assign(5 * 3 * 4, 200);
    const auto chain = generateMipChain(image, ColorSpace::Srgb);
    ASSERT_EQ(chain.size(), 3u);
    EXPECT_EQ(chain[1].width, 2u);
    EXPECT_EQ(chain[1].height, 1u);
    EXPECT_EQ(chain[2].width, 1u);
    EXPECT_EQ(chain[2].height, 1u);
    EXPECT_EQ(chain[2].rgba[0], 200)
        << "a flat colour stays that colour through the sRGB round trip";
}

TEST(MipGeneration, SrgbConversionsRoundTripEveryByte) {
    for (int i = 0; i < 256; ++i) {
        EXPECT_EQ(linearToSrgb(srgbToLinear(static_cast<std::uint8_t>(i))), i);
    }
    EXPECT_TRUE(generateMipChain(Rgba8Image{}, ColorSpace::Linear).empty());
}

}  // namespace
}  // namespace candela::content
