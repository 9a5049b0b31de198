// Bloom (issue 24): energy-conserving, so it moves radiance around the bright bulbs without
// changing the frame's total.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "test_scene.h"

namespace candela::render::test {
namespace {

TestScene bulbsOverAFloor() {
    TestScene scene;
    scene.width = 128;
    scene.height = 96;
    content::Material floor = lambertWhite();
    floor.baseColorFactor = {0.5f, 0.5f, 0.5f, 1.0f};
    scene.add(content::makePlane(6.0f), floor);
    content::Material bulb = lambertWhite();
    bulb.baseColorFactor = {0.0f, 0.0f, 0.0f, 1.0f};
    bulb.emissiveFactor = {1.0f, 0.8f, 0.6f};
    bulb.emissiveStrength = 400.0f;
    for (int i = -1; i <= 1; ++i) {
        scene.add(content::makeSphere(0.08f, 16, 8), bulb,
                  glm::translate(glm::mat4(1.0f), glm::vec3(0.8f * float(i), 0.6f, 0.0f)));
    }
    LightInstance sun;
    sun.light.type = content::LightType::Directional;
    sun.light.lux = 2.0f;
    sun.direction = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.2f));
    scene.lights.push_back(sun);
    scene.lookAt({0.0f, 1.0f, 3.0f}, {0.0f, 0.4f, 0.0f}, {0.0f, 1.0f, 0.0f}, glm::radians(50.0f));
    return scene;
}

double totalRadiance(const CapturedFrame& frame) {
    double sum = 0.0;
    for (float v : frame.hdrRgb)
        sum += v;
    return sum;
}

TEST(Bloom, RedistributesRadianceWithoutAddingAny) {
    GpuContext context(requiredValidation());
    TestScene scene = bulbsOverAFloor();
    RendererStats stats;
    const CapturedFrame plain = scene.render(context, {}, &stats);
    RendererOptions options;
    options.bloomStrength = 0.04f;
    const CapturedFrame bloomed = scene.render(context, options, &stats);
    const double before = totalRadiance(plain);
    const double after = totalRadiance(bloomed);
    // Where radiance went: pixels that were dim and are now brighter (the glow around bulbs).
    uint32_t brightened = 0;
    double brightestBefore = 0.0, brightestAfter = 0.0;
    for (size_t i = 0; i < plain.hdrRgb.size(); ++i) {
        brightestBefore = std::max(brightestBefore, double(plain.hdrRgb[i]));
        brightestAfter = std::max(brightestAfter, double(bloomed.hdrRgb[i]));
        brightened += bloomed.hdrRgb[i] > plain.hdrRgb[i] * 1.5f + 0.05f;
    }
    std::printf(
        "total radiance %.6g -> %.6g (%.4f%%), %u values brightened, peak %.4g -> %.4g, "
        "bloom %.3f ms\n",
        before, after, 100.0 * (after - before) / before, brightened, brightestBefore,
        brightestAfter, stats.bloomMs);
    EXPECT_NEAR(after / before, 1.0, 0.005);
    EXPECT_GT(brightened, 500u);                        // a visible glow around the bulbs
    EXPECT_LT(brightestAfter, brightestBefore * 0.99);  // ... taken from the bulbs themselves
    EXPECT_GT(stats.bloomMs, 0.0);
}

TEST(Bloom, StrengthZeroLeavesTheFrameAlone) {
    GpuContext context(requiredValidation());
    TestScene scene = bulbsOverAFloor();
    const CapturedFrame plain = scene.render(context);
    RendererOptions options;
    options.bloomStrength = 0.0f;
    const CapturedFrame off = scene.render(context, options);
    EXPECT_EQ(plain.hdrRgb, off.hdrRgb);
}

}  // namespace
}  // namespace candela::render::test
