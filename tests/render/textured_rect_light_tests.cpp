// Textured rect lights (issue 15): the emissive image modulates a rect's luminance, scaled to
// average luminance 1 (lights/area_light_textures.h), read by LTC where the lobe's mean
// direction meets the rect and at the representative point in seed 004's mode.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "candela/content/light_texture.h"
#include "test_scene.h"

using namespace candela::render;
using namespace candela::render::test;
using candela::content::makePlane;
using candela::content::Rgba8Image;

namespace {

// A white Lambert floor seen from 5 m above (screen right = world +X), under a 1.6 x 1 m rect
// 1.2 m up, facing down: its +X along world +X.
TestScene rectOverFloor(std::shared_ptr<const Rgba8Image> image) {
    TestScene scene;
    scene.width = scene.height = 64;
    scene.add(makePlane(20.0f), lambertWhite());
    scene.lookAt({0.0f, 5.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f});
    LightInstance rect;
    rect.light.type = candela::content::LightType::Rect;
    rect.light.lumens = 2000.0f;
    rect.light.attenuationRadius = 30.0f;
    rect.light.width = 1.6f;
    rect.light.height = 1.0f;
    rect.light.texture = image ? candela::content::registerLightTexture("", std::move(image)) : 0;
    rect.position = {0.0f, 1.2f, 0.0f};
    rect.direction = {0.0f, -1.0f, 0.0f};
    rect.tubeAxis = {1.0f, 0.0f, 0.0f};
    scene.lights = {rect};
    return scene;
}

// `width` x 2 texels: the left half `left`, the right half `right` (sRGB bytes).
std::shared_ptr<const Rgba8Image> halves(uint32_t width, const uint8_t left[3],
                                         const uint8_t right[3]) {
    auto image = std::make_shared<Rgba8Image>();
    image->width = width;
    image->height = 2;
    for (uint32_t y = 0; y < 2; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            const uint8_t* c = x < width / 2 ? left : right;
            image->rgba.insert(image->rgba.end(), {c[0], c[1], c[2], 255});
        }
    }
    return image;
}

RendererOptions withAreaLights(AreaLightMode mode) {
    RendererOptions options;
    options.areaLights = mode;
    return options;
}

}  // namespace

// Any one-colour grey image is the untextured rect: the image is normalised to average
// luminance 1, so lumens stay lumens. By LTC and by the representative point.
TEST(TexturedRectLight, UniformGreyImageShadesAsUntextured) {
    GpuContext context(requiredValidation());
    const uint8_t grey[3] = {90, 90, 90};
    for (AreaLightMode mode : {AreaLightMode::Ltc, AreaLightMode::Representative}) {
        CapturedFrame plain = rectOverFloor(nullptr).render(context, withAreaLights(mode));
        CapturedFrame textured =
            rectOverFloor(halves(8, grey, grey)).render(context, withAreaLights(mode));
        ASSERT_EQ(textured.nonFiniteHdrValues(), 0u);
        double worst = 0.0, lit = 0.0;
        for (size_t i = 0; i < plain.hdrRgb.size(); ++i) {
            lit = std::max(lit, double(plain.hdrRgb[i]));
            worst = std::max(worst, double(std::abs(textured.hdrRgb[i] - plain.hdrRgb[i])) /
                                        std::max(double(plain.hdrRgb[i]), 1e-3));
        }
        std::printf("%s: uniform image vs untextured, worst relative difference %.2e\n",
                    mode == AreaLightMode::Ltc ? "ltc" : "representative", worst);
        EXPECT_GT(lit, 1.0);
        EXPECT_LT(worst, 2e-3);  // the half-float atlas
    }
    EXPECT_EQ(context.validationMessages(), 0u);
}

// An image red on its left half, blue on its right: seen from below (the lit side), the left
// column is along the rect's +X edge, so the floor under +X is red and under -X blue.
TEST(TexturedRectLight, ImageHalvesColourTheFloorBelowThem) {
    GpuContext context(requiredValidation());
    const uint8_t red[3] = {255, 0, 0}, blue[3] = {0, 0, 255};
    for (AreaLightMode mode : {AreaLightMode::Ltc, AreaLightMode::Representative}) {
        TestScene scene = rectOverFloor(halves(16, red, blue));
        CapturedFrame frame = scene.render(context, withAreaLights(mode));
        ASSERT_EQ(frame.nonFiniteHdrValues(), 0u);
        const uint32_t y = scene.height / 2;
        for (uint32_t x : {scene.width / 2 - 6, scene.width / 2 + 6}) {
            const auto point = scene.pixelOnPlane(x, y);
            ASSERT_TRUE(point.has_value());
            const float* rgb = hdrPixel(frame, x, y);
            const bool underPlusX = point->x > 0.0f;
            EXPECT_GT(underPlusX ? rgb[0] : rgb[2], 2.0f * (underPlusX ? rgb[2] : rgb[0]))
                << "pixel " << x << " at world x " << point->x << ": " << rgb[0] << " " << rgb[1]
                << " " << rgb[2];
        }
    }
    EXPECT_EQ(context.validationMessages(), 0u);
}
