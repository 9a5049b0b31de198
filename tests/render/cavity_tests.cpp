// Cavity (issue 25, UE4's Cavity): a material scalar in [0, 1] that darkens the sky's light
// only, folded into the occlusion channel by min. A white Lambert sphere under a uniform sky
// with AO off: cavity 0.5 halves its radiance; under a point light alone it changes nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "candela/render/environment.h"
#include "test_scene.h"

using namespace candela::render;
using namespace candela::render::test;

namespace {

// The sphere's disc without its outermost ring (where the pixel straddles the background).
template <class F>
void forDiscPixels(const CapturedFrame& frame, F&& visit) {
    for (uint32_t y = 0; y < frame.height; ++y) {
        for (uint32_t x = 0; x < frame.width; ++x) {
            const float dx = (float(x) + 0.5f) / float(frame.width) - 0.5f;
            const float dy = (float(y) + 0.5f) / float(frame.height) - 0.5f;
            if (std::sqrt(dx * dx + dy * dy) <= 0.27f) visit(x, y);
        }
    }
}

CapturedFrame renderSphere(float cavity, candela::content::AlphaMode alphaMode, bool sky,
                           bool light) {
    TestScene scene;
    scene.width = 64;
    scene.height = 64;
    candela::content::Material m = lambertWhite();
    m.cavity = cavity;
    m.alphaMode = alphaMode;
    scene.add(candela::content::makeSphere(1.0f, 96, 48), m);
    scene.lookAt({0.0f, 0.0f, 3.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
    if (sky) scene.environment = Environment::uniform(sharedContext(), 1.0f);
    if (light) scene.lights.push_back(pointLight({1.0f, 1.0f, 3.0f}, 2000.0f, 20.0f));
    RendererOptions options;
    options.ao = AoMode::Off;
    return scene.render(sharedContext(), options);
}

}  // namespace

// Opaque (G-buffer) and blended (forward) surfaces alike: the sky's light scales by the cavity.
TEST(Cavity, HalvesTheSkyLightAndLeavesAnalyticLightsUnchanged) {
    using candela::content::AlphaMode;
    for (AlphaMode mode : {AlphaMode::Opaque, AlphaMode::Blend}) {
        const char* name = mode == AlphaMode::Opaque ? "opaque" : "blended";
        const CapturedFrame full = renderSphere(1.0f, mode, true, false);
        const CapturedFrame half = renderSphere(0.5f, mode, true, false);
        double lo = 1e30, hi = -1e30, sum = 0.0;
        uint32_t count = 0;
        forDiscPixels(full, [&](uint32_t x, uint32_t y) {
            for (int c = 0; c < 3; ++c) {
                const double ratio = double(hdrPixel(half, x, y)[c]) / hdrPixel(full, x, y)[c];
                lo = std::min(lo, ratio);
                hi = std::max(hi, ratio);
                sum += ratio;
                ++count;
            }
        });
        std::printf("%-7s sky radiance ratio cavity 0.5 / 1: mean %.5f, range %.5f .. %.5f\n", name,
                    sum / count, lo, hi);
        ASSERT_GT(count, 300u);
        EXPECT_NEAR(lo, 0.5, 0.005) << name;
        EXPECT_NEAR(hi, 0.5, 0.005) << name;

        const CapturedFrame lit = renderSphere(1.0f, mode, false, true);
        const CapturedFrame litCavity = renderSphere(0.5f, mode, false, true);
        double maxDifference = 0.0, maxRadiance = 0.0;
        forDiscPixels(lit, [&](uint32_t x, uint32_t y) {
            for (int c = 0; c < 3; ++c) {
                maxRadiance = std::max(maxRadiance, double(hdrPixel(lit, x, y)[c]));
                maxDifference = std::max(
                    maxDifference,
                    double(std::abs(hdrPixel(lit, x, y)[c] - hdrPixel(litCavity, x, y)[c])));
            }
        });
        std::printf("%-7s point light: max radiance %.4f, max |cavity 0.5 - cavity 1| %.3g\n", name,
                    maxRadiance, maxDifference);
        EXPECT_GT(maxRadiance, 0.05) << name << ": the light must reach the sphere";
        EXPECT_EQ(maxDifference, 0.0) << name;
    }
    EXPECT_EQ(sharedContext().validationMessages(), 0u);
}
