#include <gtest/gtest.h>

#include <OpenEXR/ImfEnvmap.h>

#include <cmath>
#include <filesystem>

#include "candela/content/environment_map.h"

namespace candela::content {
namespace {

std::filesystem::path env(const char* name) {
    return std::filesystem::path(CANDELA_SHARED_ASSETS) / "env" / name;
}

// Bilinear lat-long lookup with horizontal wrap, for comparing layouts.
std::array<float, 3> sampleLatLong(const FloatImage& image, const std::array<float, 3>& d) {
    auto p = latLongTexelPosition(d, image.width, image.height);
    const float x = p[0] - 0.5f;
    const float y = std::clamp(p[1] - 0.5f, 0.0f, static_cast<float>(image.height - 1));
    const int x0 = static_cast<int>(std::floor(x));
    const int y0 = static_cast<int>(std::floor(y));
    const float fx = x - static_cast<float>(x0);
    const float fy = y - static_cast<float>(y0);
    auto at = [&](int px, int py) {
        const int w = static_cast<int>(image.width);
        px = ((px % w) + w) % w;
        py = std::clamp(py, 0, static_cast<int>(image.height) - 1);
        return image.texel(static_cast<std::uint32_t>(px), static_cast<std::uint32_t>(py));
    };
    std::array<float, 3> out{};
    for (int c = 0; c < 3; ++c) {
        out[c] = (at(x0, y0)[c] * (1 - fx) + at(x0 + 1, y0)[c] * fx) * (1 - fy) +
                 (at(x0, y0 + 1)[c] * (1 - fx) + at(x0 + 1, y0 + 1)[c] * fx) * fy;
    }
    return out;
}

TEST(EnvironmentMap, LatLongConventionMatchesOpenExr) {
    const std::uint32_t w = 1024, h = 512;
    const Imath::Box2i window(Imath::V2i(0, 0), Imath::V2i(w - 1, h - 1));
    for (const auto& d : std::vector<std::array<float, 3>>{
             {0, 0, 1}, {1, 0, 0}, {-1, 0, 0}, {0.3f, 0.5f, -0.8f}, {-0.2f, -0.9f, 0.1f}}) {
        const auto mine = latLongTexelPosition(d, w, h);
        const Imath::V2f theirs =
            Imf::LatLongMap::pixelPosition(window, Imath::V3f(d[0], d[1], d[2]));
        // OpenEXR puts texel centres at 0 .. w-1, we at 0.5 .. w-0.5: compare normalised.
        EXPECT_NEAR(mine[0] / w, theirs.x / (w - 1), 2e-3) << d[0] << " " << d[1] << " " << d[2];
        EXPECT_NEAR(mine[1] / h, theirs.y / (h - 1), 2e-3);
        const auto back = latLongDirection(mine[0], mine[1], w, h);
        const float length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(back[c], d[c] / length, 1e-4f);
    }
}

TEST(EnvironmentMap, OpenExrCubeResampledToVulkanFacesMatchesTheLatLongOfTheSameScene) {
    Diagnostics diagnostics;
    auto cube = loadEnvironmentExr(env("StageEnvCube.exr"), diagnostics);
    auto latLong = loadEnvironmentExr(env("StageEnvLatLong.exr"), diagnostics);
    ASSERT_TRUE(cube && latLong) << diagnostics.toString();
    ASSERT_EQ(cube->layout, EnvironmentLayout::Cube);
    EXPECT_EQ(cube->source, EnvironmentSource::CubeEnvmap);
    ASSERT_EQ(latLong->layout, EnvironmentLayout::LatLong);
    // Compare along each face's texels; a mirrored or rotated face would disagree strongly.
    double difference = 0, mirroredDifference = 0, magnitude = 0;
    for (int f = 0; f < 6; ++f) {
        const FloatImage& face = cube->cubeFaces[static_cast<std::size_t>(f)];
        ASSERT_EQ(face.width, 256u);
        for (std::uint32_t j = 8; j < face.height; j += 16) {
            for (std::uint32_t i = 8; i < face.width; i += 16) {
                const float s = (static_cast<float>(i) + 0.5f) / static_cast<float>(face.width);
                const float t = (static_cast<float>(j) + 0.5f) / static_cast<float>(face.height);
                const auto d = cubeFaceDirection(static_cast<CubeFace>(f), s, t);
                const auto expected = sampleLatLong(latLong->latLong, d);
                const auto mirrored = sampleLatLong(latLong->latLong, {-d[0], d[1], d[2]});
                for (int c = 0; c < 3; ++c) {
                    difference += std::fabs(face.texel(i, j)[c] - expected[c]);
                    mirroredDifference += std::fabs(face.texel(i, j)[c] - mirrored[c]);
                    magnitude += std::fabs(expected[c]);
                }
            }
        }
    }
    EXPECT_LT(difference / magnitude, 0.15) << "cube and lat-long disagree";
    EXPECT_GT(mirroredDifference, 2 * difference) << "the comparison must be able to fail";
}

TEST(EnvironmentMap, StripAndCrossLayoutsWithoutAttributeAreCut) {
    // Horizontal strip 6N x N: face f filled with value f.
    const std::uint32_t n = 4;
    ExrImage strip;
    strip.image.width = 6 * n;
    strip.image.height = n;
    strip.image.rgba.resize(6 * n * n * 4);
    for (std::uint32_t y = 0; y < n; ++y) {
        for (std::uint32_t x = 0; x < 6 * n; ++x) {
            float* t = strip.image.texel(x, y);
            t[0] = static_cast<float>(x / n);
            t[1] = static_cast<float>(y);
            t[2] = static_cast<float>(x % n);
            t[3] = 1;
        }
    }
    Diagnostics diagnostics;
    auto fromStrip = environmentFromExr(strip, "strip.exr", diagnostics);
    ASSERT_TRUE(fromStrip);
    EXPECT_EQ(fromStrip->source, EnvironmentSource::HorizontalStrip);
    for (int f = 0; f < 6; ++f) {
        EXPECT_EQ(fromStrip->cubeFaces[static_cast<std::size_t>(f)].texel(1, 2)[0],
                  static_cast<float>(f));
    }

    // Vertical cross 3N x 4N: -Z sits at the bottom, rotated 180 degrees.
    ExrImage cross;
    cross.image.width = 3 * n;
    cross.image.height = 4 * n;
    cross.image.rgba.assign(std::size_t{3 * n} * 4 * n * 4, 0.0f);
    for (std::uint32_t y = 3 * n; y < 4 * n; ++y) {
        for (std::uint32_t x = n; x < 2 * n; ++x) {
            cross.image.texel(x, y)[0] = static_cast<float>((x - n) + 10 * (y - 3 * n));
        }
    }
    auto fromCross = environmentFromExr(cross, "cross.exr", diagnostics);
    ASSERT_TRUE(fromCross);
    EXPECT_EQ(fromCross->source, EnvironmentSource::VerticalCross);
    const FloatImage& negZ = fromCross->cubeFaces[static_cast<std::size_t>(CubeFace::NegativeZ)];
    EXPECT_EQ(negZ.texel(0, 0)[0], static_cast<float>((n - 1) + 10 * (n - 1)));
    EXPECT_EQ(negZ.texel(n - 1, n - 1)[0], 0.0f);
}

TEST(EnvironmentMap, CubeAttributeWithWrongShapeIsAnError) {
    ExrImage bad;
    bad.envmap = ExrEnvmapAttribute::Cube;
    bad.image.width = 4;
    bad.image.height = 4;
    bad.image.rgba.assign(64, 1.0f);
    Diagnostics diagnostics;
    EXPECT_FALSE(environmentFromExr(bad, "bad-cube.exr", diagnostics));
    EXPECT_TRUE(diagnostics.mentions("bad-cube.exr"));
}

TEST(EnvironmentMap, CubeFaceDirectionsFollowTheVulkanTable) {
    // Face centres point along their axis; +X face's s grows towards -Z, t towards -Y.
    EXPECT_EQ(cubeFaceDirection(CubeFace::PositiveX, 0.5f, 0.5f), (std::array<float, 3>{1, 0, 0}));
    EXPECT_EQ(cubeFaceDirection(CubeFace::NegativeZ, 0.5f, 0.5f), (std::array<float, 3>{0, 0, -1}));
    const auto d = cubeFaceDirection(CubeFace::PositiveX, 1.0f, 1.0f);
    EXPECT_LT(d[2], 0.0f);
    EXPECT_LT(d[1], 0.0f);
    const auto top = cubeFaceDirection(CubeFace::PositiveY, 0.5f, 1.0f);
    EXPECT_GT(top[2], 0.0f) << "+Y face: t grows towards +Z";
}

}  // namespace
}  // namespace candela::content
