// Sky occlusion (render/README.md "Sky occlusion"): a closed room lit by the sky only through a
// skylight, against a CPU ray trace of the floor's sky visibility; open ground unchanged; the
// maps rendered once and reused while the casters stay; a blended pane occluded as an opaque
// one.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "candela/content/render_setting_table.h"
#include "passes/sky_occlusion/sky_occlusion_directions.h"
#include "passes/sky_occlusion/sky_occlusion_pass.h"
#include "sky_occlusion_scene.h"

using namespace candela::render;
using namespace candela::render::test;

// Without sky occlusion the room's floor is as bright as open ground (visibility 1); with it,
// the floor sees the sky only through the skylight: within 0.03 of the ray trace on average
// (on) and 0.02 (reference).
TEST(SkyOcclusion, ClosedRoomSeesTheSkyOnlyThroughItsSkylight) {
    SkyRoom room(sharedContext(), true);
    for (SkyOcclusionMode mode :
         {SkyOcclusionMode::Off, SkyOcclusionMode::On, SkyOcclusionMode::Reference}) {
        RendererStats stats;
        const SkyRoomError e = room.compareInside(room.render(mode, &stats));
        std::printf(
            "%-9s floor %u px: ray traced %.4f, rendered %.4f, mean |error| %.4f, %.2f ms\n",
            candela::content::renderSettingName(mode).c_str(), e.pixels, e.meanTruth,
            e.meanRendered, e.meanAbs, stats.skyOcclusionMs);
        ASSERT_GT(e.pixels, 300u);
        ASSERT_LT(e.meanTruth, 0.2) << "the room must be nearly closed";
        if (mode == SkyOcclusionMode::Off) {
            EXPECT_GT(e.meanRendered, 0.95) << "unoccluded: the whole sky";
        } else {
            EXPECT_LE(e.meanAbs, mode == SkyOcclusionMode::On ? 0.03 : 0.02);
            EXPECT_NEAR(e.meanRendered, e.meanTruth, 0.02);
        }
    }
}

// Ground whose every sky direction is open gets the unoccluded light: no bias darkens it. (The
// walls are grown by 0.1 m, about 4 texels of the maps, for the compare filter's footprint.)
TEST(SkyOcclusion, OpenGroundIsUnchanged) {
    SkyRoom room(sharedContext(), false);
    const CapturedFrame off = room.render(SkyOcclusionMode::Off);
    const CapturedFrame on = room.render(SkyOcclusionMode::On);
    uint32_t openPixels = 0;
    double worst = 0.0;
    const TestScene& scene = room.scene();
    for (uint32_t y = 0; y < scene.height; y += 2) {
        for (uint32_t x = 0; x < scene.width; x += 2) {
            const auto p = scene.pixelOnPlane(x, y);
            if (!p) continue;
            bool open = true;
            const uint32_t n = skyOcclusionDirectionCount(SkyOcclusionMode::On);
            for (uint32_t i = 0; i < n && open; ++i)
                open = !room.blocked(*p, skyOcclusionDirection(i, n), 0.1f);
            if (!open) continue;
            ++openPixels;
            worst =
                std::max(worst, double(std::abs(hdrPixel(on, x, y)[1] - hdrPixel(off, x, y)[1])));
        }
    }
    std::printf("open ground: %u px, largest change %.5f\n", openPixels, worst);
    ASSERT_GT(openPixels, 300u);
    EXPECT_LT(worst, 0.005);
}

// The maps are rendered in the first frame and reused while the casters stay.
TEST(SkyOcclusion, MapsAreBuiltOnceForStaticCasters) {
    SkyRoom room(sharedContext(), true, 32);
    RendererOptions options;
    options.skyOcclusion = SkyOcclusionMode::On;
    SceneResources resources(sharedContext());
    TestScene scene = room.scene();
    resources.setEnvironment(scene.environment);
    FrameInputs inputs = scene.prepare(resources);
    FrameSequence frames(sharedContext(), scene.width, scene.height, options);
    RendererStats stats;
    frames.render(inputs, resources, &stats);
    EXPECT_TRUE(stats.skyOcclusionRebuilt);
    frames.render(inputs, resources, &stats);
    EXPECT_FALSE(stats.skyOcclusionRebuilt);
    scene.draws[1].world = glm::translate(scene.draws[1].world, glm::vec3(0.0f, 0.0f, -1.0f));
    frames.render(inputs, resources, &stats);
    EXPECT_TRUE(stats.skyOcclusionRebuilt) << "a moved wall rebuilds the maps";
}

namespace {

// The room's scene with a white Lambert pane of `alphaMode` (coverage 1, so a blended pane's
// pixels hold its own radiance) of half extent `half` at height kPaneHeight, centred at
// (0, kPaneHeight, z).
constexpr float kPaneHeight = 0.4f;

CapturedFrame renderWithPane(const SkyRoom& room, candela::content::AlphaMode alphaMode, float z,
                             float half, SkyOcclusionMode mode) {
    TestScene scene = room.scene();
    candela::content::Material pane = lambertWhite();
    pane.alphaMode = alphaMode;
    scene.add(candela::content::makePlane(half), pane,
              glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, kPaneHeight, z)));
    RendererOptions options;
    options.skyOcclusion = mode;
    return scene.render(sharedContext(), options);
}

}  // namespace

// A blended pane inside the room sees the sky through the skylight only, as an opaque
// surface of the same material at the same place does (the forward pass applies the lighting
// pass's sky occlusion); in the open it keeps the whole sky.
TEST(SkyOcclusion, BlendedPaneIsOccludedLikeAnOpaqueOne) {
    const SkyRoom inside(sharedContext(), true);
    const float half = 1.2f;
    const CapturedFrame blended = renderWithPane(inside, candela::content::AlphaMode::Blend, 0.0f,
                                                 half, SkyOcclusionMode::On);
    const CapturedFrame opaque = renderWithPane(inside, candela::content::AlphaMode::Opaque, 0.0f,
                                                half, SkyOcclusionMode::On);
    uint32_t panePixels = 0;
    double meanBlended = 0.0, meanOpaque = 0.0, meanAbs = 0.0;
    for (uint32_t y = 0; y < inside.scene().height; ++y) {
        for (uint32_t x = 0; x < inside.scene().width; ++x) {
            const auto p = inside.scene().pixelOnPlane(x, y, kPaneHeight);
            // Away from the pane's edges (the compare filter's footprint).
            if (!p || std::abs(p->x) > half - 0.1f || std::abs(p->z) > half - 0.1f) continue;
            const double b = hdrPixel(blended, x, y)[1], o = hdrPixel(opaque, x, y)[1];
            ++panePixels;
            meanBlended += b;
            meanOpaque += o;
            meanAbs += std::abs(b - o);
        }
    }
    ASSERT_GT(panePixels, 300u);
    meanBlended /= panePixels;
    meanOpaque /= panePixels;
    meanAbs /= panePixels;
    std::printf("pane inside: %u px, blended %.4f, opaque %.4f, mean |difference| %.5f\n",
                panePixels, meanBlended, meanOpaque, meanAbs);
    EXPECT_LT(meanOpaque, 0.3) << "the room must occlude the pane's sky";
    EXPECT_LT(meanAbs, 0.005);

    // Outside: the pane's pixels that see every direction open are unchanged by the occlusion.
    const SkyRoom outside(sharedContext(), false);
    const float z = 12.0f, outsideHalf = 6.0f;
    const CapturedFrame on = renderWithPane(outside, candela::content::AlphaMode::Blend, z,
                                            outsideHalf, SkyOcclusionMode::On);
    const CapturedFrame off = renderWithPane(outside, candela::content::AlphaMode::Blend, z,
                                             outsideHalf, SkyOcclusionMode::Off);
    const uint32_t n = skyOcclusionDirectionCount(SkyOcclusionMode::On);
    uint32_t openPixels = 0;
    double worst = 0.0;
    for (uint32_t y = 0; y < outside.scene().height; ++y) {
        for (uint32_t x = 0; x < outside.scene().width; ++x) {
            const auto p = outside.scene().pixelOnPlane(x, y, kPaneHeight);
            if (!p || std::abs(p->x) > outsideHalf - 0.1f ||
                std::abs(p->z - z) > outsideHalf - 0.1f) {
                continue;
            }
            bool open = true;
            for (uint32_t i = 0; i < n && open; ++i)
                open = !outside.blocked(*p, skyOcclusionDirection(i, n), 0.1f);
            if (!open) continue;
            ++openPixels;
            worst =
                std::max(worst, double(std::abs(hdrPixel(on, x, y)[1] - hdrPixel(off, x, y)[1])));
        }
    }
    std::printf("pane outside: %u open px, largest change %.5f\n", openPixels, worst);
    ASSERT_GT(openPixels, 300u);
    EXPECT_LT(worst, 0.005);
}
