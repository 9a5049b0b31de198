// Textured rect lights (issue 15): the emissive image modulates a rect's luminance, scaled to
// average luminance 1 (lights/area_light_textures.h), read by LTC where the lobe's mean
// direction meets the rect and at the representative point in Drobot's mode (2014, GPU Pro 5,
// "Physically Based Area Lights"). One render:
// six rects over a floor, each far enough from the others that their falloff windows never
// overlap, LTC and representative chosen per light ("quality").
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "candela/content/light_texture.h"
#include "test_scene.h"

using namespace candela::render;
using namespace candela::render::test;
using candela::content::AreaLightQuality;
using candela::content::makePlane;
using candela::content::Rgba8Image;

namespace {

// The camera 14 m above the floor, 60 degrees over 96 pixels: a pixel is 2 x 14 x tan 30 / 96 m
// of floor. Rects 24 pixels apart (4.04 m; each light's window reaches 1.9 m), so the same
// offset from each lands on the same place in its pixel.
constexpr uint32_t kPixels = 96;
constexpr float kEyeHeight = 14.0f;
const float kPixelSize = 2.0f * kEyeHeight * std::tan(0.5f * glm::radians(60.0f)) / float(kPixels);
const float kSpacing = 24.0f * kPixelSize;
constexpr float kHeight = 1.2f;

// A 1.6 x 1 m rect kHeight above the floor point `at`, facing down, its +X along world +X.
LightInstance rectOver(glm::vec3 at, std::shared_ptr<const Rgba8Image> image,
                       AreaLightQuality quality) {
    LightInstance rect;
    rect.light.type = candela::content::LightType::Rect;
    rect.light.lumens = 2000.0f;
    rect.light.attenuationRadius = 1.9f;
    rect.light.width = 1.6f;
    rect.light.height = 1.0f;
    rect.light.quality = quality;
    rect.light.texture = image ? candela::content::registerLightTexture("", std::move(image)) : 0;
    rect.position = at + glm::vec3(0.0f, kHeight, 0.0f);
    rect.direction = {0.0f, -1.0f, 0.0f};
    rect.tubeAxis = {1.0f, 0.0f, 0.0f};
    return rect;
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

// The pixel holding the floor point `at` (the camera looks straight down, screen right = +X).
std::pair<uint32_t, uint32_t> pixelAt(const TestScene& scene, glm::vec3 at) {
    glm::vec4 clip = scene.camera.projection * scene.camera.view * glm::vec4(at, 1.0f);
    glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {uint32_t((ndc.x * 0.5f + 0.5f) * float(scene.width)),
            uint32_t((ndc.y * 0.5f + 0.5f) * float(scene.height))};
}

// The pixel `rows` rects further along +Z than (x, y): a whole number of pixels.
std::pair<uint32_t, uint32_t> shifted(const TestScene& scene, std::pair<uint32_t, uint32_t> p,
                                      int rows) {
    auto [x0, y0] = pixelAt(scene, glm::vec3(0.5f * kSpacing, 0.0f, kSpacing));
    auto [x1, y1] = pixelAt(scene, glm::vec3(0.5f * kSpacing, 0.0f, kSpacing * float(1 + rows)));
    return {p.first + (x1 - x0), p.second + (y1 - y0)};
}

}  // namespace

// Columns: LTC, representative. Rows: untextured, a one-colour grey image (the same light: the
// image is normalised to average luminance 1, so lumens stay lumens), an image red on its left
// half and blue on its right. Seen from below (the lit side) the image's left column is along
// the rect's +X edge, so the floor under +X is red and under -X blue: 0.5 m off the centre the
// integral over the light gives 2.08 times more of the nearer half's colour. Required: LTC 1.8
// (its exact integral per cell of the image, area_lights.glsl: 1.88 here, where the pixel's floor
// point lies up to 0.08 m off and the 16-texel image is magnified bilinearly into its tile; the
// one-point read before gave 1.66); representative 1.3 (its one read gives 4.90).
TEST(TexturedRectLight, ImagesModulateTheRectAndKeepItsPower) {
    GpuContext context(requiredValidation());
    const uint8_t grey[3] = {90, 90, 90}, red[3] = {255, 0, 0}, blue[3] = {0, 0, 255};
    const std::shared_ptr<const Rgba8Image> images[3] = {nullptr, halves(8, grey, grey),
                                                         halves(16, red, blue)};
    const AreaLightQuality modes[2] = {AreaLightQuality::Ltc, AreaLightQuality::Representative};
    TestScene scene;
    scene.width = scene.height = kPixels;
    scene.add(makePlane(40.0f), lambertWhite());
    scene.lookAt({0.5f * kSpacing, kEyeHeight, kSpacing}, {0.5f * kSpacing, 0.0f, kSpacing},
                 {0.0f, 0.0f, -1.0f});
    auto centre = [](int mode, int row) {
        return glm::vec3(kSpacing * float(mode), 0.0f, kSpacing * float(row));
    };
    for (int row = 0; row < 3; ++row) {
        for (int mode = 0; mode < 2; ++mode)
            scene.lights.push_back(rectOver(centre(mode, row), images[row], modes[mode]));
    }
    CapturedFrame frame = scene.render(context);
    ASSERT_EQ(frame.nonFiniteHdrValues(), 0u);

    for (int mode = 0; mode < 2; ++mode) {
        const char* name = mode == 0 ? "ltc" : "representative";
        double worst = 0.0;
        for (float dx : {-0.9f, -0.4f, 0.0f, 0.3f, 0.7f}) {
            for (float dz : {-0.6f, 0.0f, 0.5f}) {
                const glm::vec3 offset(dx, 0.0f, dz);
                const auto p = pixelAt(scene, centre(mode, 0) + offset);
                const auto [px, py] = p;
                const auto [qx, qy] = shifted(scene, p, 1);
                const float plain = hdrPixel(frame, px, py)[1];
                ASSERT_GT(plain, 1.0f) << name;
                worst =
                    std::max(worst, double(std::abs(hdrPixel(frame, qx, qy)[1] - plain)) / plain);
            }
        }
        std::printf("%s: one-colour image vs untextured, worst relative difference %.2e\n", name,
                    worst);
        EXPECT_LT(worst, 2e-3) << name;  // the half-float atlas

        for (float dx : {-0.5f, 0.5f}) {
            auto [x, y] = pixelAt(scene, centre(mode, 2) + glm::vec3(dx, 0.0f, 0.0f));
            const float* rgb = hdrPixel(frame, x, y);
            const float nearer = dx > 0.0f ? rgb[0] : rgb[2];
            const float further = dx > 0.0f ? rgb[2] : rgb[0];
            std::printf(
                "%s: %.1f m off the centre, nearer half / further half %.2f (integral 2.08)\n",
                name, dx, nearer / further);
            EXPECT_GT(nearer, (mode == 0 ? 1.8f : 1.3f) * further) << name << " at " << dx;
        }
    }
    EXPECT_EQ(context.validationMessages(), 0u);
}
