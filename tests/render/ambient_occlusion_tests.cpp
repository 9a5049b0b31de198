// Ambient occlusion (issue 25): GTAO's sky visibility on a floor around a black box against a
// CPU ray trace of the same geometry, and the white furnace with no occluders unchanged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

#include "ambient_occlusion_scene.h"
#include "candela/content/render_setting_table.h"

using namespace candela::render;
using namespace candela::render::test;

// Floor radiance / albedo under a uniform white sky is the floor's cosine-weighted sky
// visibility (black box: no bounce; no specular; multi-bounce off, since its fit assumes
// occluders as bright as the floor). Goal of the issue: mean absolute error <= 0.07 where the
// true visibility is under 0.9, and open floor darkened by <= 0.05.
TEST(AmbientOcclusion, GtaoMatchesRayTracedSkyVisibilityAroundABoxOnAFloor) {
    BoxOnFloor scene(sharedContext());
    for (AoMode mode : {AoMode::Gtao, AoMode::Reference}) {
        const VisibilityError e = scene.compare(mode, {});
        std::printf(
            "%-9s occluded floor (true < 0.9): %u px, mean |error| %.4f, mean signed %.4f;"
            " open floor (true > 0.97): %u px, mean darkening %.4f, max %.4f\n",
            candela::content::renderSettingName(mode).c_str(), e.occludedPixels, e.occludedMeanAbs,
            e.occludedMeanSigned, e.openPixels, e.openMeanDarkening, e.openMaxDarkening);
        ASSERT_GT(e.occludedPixels, 50u) << "the box must occlude part of the visible floor";
        ASSERT_GT(e.openPixels, 200u);
        EXPECT_LE(e.occludedMeanAbs, 0.07) << candela::content::renderSettingName(mode).c_str();
        EXPECT_LE(e.openMeanDarkening, 0.05) << candela::content::renderSettingName(mode).c_str();
    }
    // Off: the floor is as bright as open floor everywhere, so the error is large (this also
    // proves the comparison can fail).
    const VisibilityError off = scene.compare(AoMode::Off, {});
    std::printf("off       occluded floor: mean |error| %.4f\n", off.occludedMeanAbs);
    EXPECT_GT(off.occludedMeanAbs, 0.15);
    EXPECT_EQ(sharedContext().validationMessages(), 0u);
}

// No occluders, no change: a white Lambert sphere in a uniform white sky reflects radiance 1
// with AO on as with it off (multi-bounce on, as by default).
TEST(AmbientOcclusion, WhiteFurnaceWithoutOccludersIsUnchanged) {
    std::shared_ptr<const Environment> sky = Environment::uniform(sharedContext(), 1.0f);
    for (AoMode mode : {AoMode::Off, AoMode::Gtao, AoMode::Reference}) {
        TestScene scene;
        scene.width = 64;
        scene.height = 64;
        scene.add(candela::content::makeSphere(1.0f, 96, 48), lambertWhite());
        scene.lookAt({0.0f, 0.0f, 3.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
        scene.environment = sky;
        RendererOptions options;
        options.ao = mode;
        options.aoSettings.referenceRays = 64;
        const CapturedFrame frame = scene.render(sharedContext(), options);
        float lo = 1e30f, hi = -1e30f;
        // The sphere's disc without its outermost ring (where the pixel straddles the sky).
        for (uint32_t y = 0; y < frame.height; ++y) {
            for (uint32_t x = 0; x < frame.width; ++x) {
                const float dx = (float(x) + 0.5f) / float(frame.width) - 0.5f;
                const float dy = (float(y) + 0.5f) / float(frame.height) - 0.5f;
                if (std::sqrt(dx * dx + dy * dy) > 0.27f) continue;
                for (int c = 0; c < 3; ++c) {
                    lo = std::min(lo, hdrPixel(frame, x, y)[c]);
                    hi = std::max(hi, hdrPixel(frame, x, y)[c]);
                }
            }
        }
        std::printf("%-9s furnace sphere: radiance %.5f .. %.5f\n",
                    candela::content::renderSettingName(mode).c_str(), lo, hi);
        // The reference marches rays in screen space: a grazing ray that passes behind the
        // sphere's nearer bulge counts as blocked (1% at the rim with 64 rays).
        const float tolerance = mode == AoMode::Reference ? 0.02f : 0.01f;
        EXPECT_NEAR(lo, 1.0f, tolerance) << candela::content::renderSettingName(mode).c_str();
        EXPECT_LE(hi, 1.0f + 0.002f)
            << candela::content::renderSettingName(mode).c_str();  // never brighter than no AO
    }
    EXPECT_EQ(sharedContext().validationMessages(), 0u);
}

// The intensity scales the occlusion: 0 renders as AO off.
TEST(AmbientOcclusion, ZeroIntensityMatchesOff) {
    BoxOnFloor scene(sharedContext());
    BoxOnFloor::Settings none;
    none.intensity = 0.0f;
    const VisibilityError zero = scene.compare(AoMode::Gtao, none);
    const VisibilityError off = scene.compare(AoMode::Off, {});
    EXPECT_NEAR(zero.occludedMeanAbs, off.occludedMeanAbs, 1e-4);
    EXPECT_EQ(sharedContext().validationMessages(), 0u);
}

namespace {

// Mean |a - b| of the floor's radiance (= its visibility) over the pixels `use` keeps.
template <typename Keep>
double meanFloorChange(const CapturedFrame& a, const CapturedFrame& b, Keep use) {
    double sum = 0.0;
    uint32_t pixels = 0;
    for (uint32_t y = 0; y < a.height; ++y) {
        for (uint32_t x = 0; x < a.width; ++x) {
            if (!use(x, y)) continue;
            sum += std::abs(double(hdrPixel(a, x, y)[1]) - double(hdrPixel(b, x, y)[1]));
            ++pixels;
        }
    }
    return pixels ? sum / pixels : 0.0;
}

RendererOptions accumulating() {
    RendererOptions options = BoxOnFloor::optionsFor(AoMode::Gtao, {});
    // With --aa off, so the frame shows AO's own accumulation (TAA would average it too).
    options.aoSettings.temporal = AoTemporal::Always;
    return options;
}

}  // namespace

// Temporal accumulation: a still view averages GTAO over frames whose slices rotate, so the
// frame-to-frame change of the floor's visibility falls as frames accumulate, and the
// accumulated result is no farther from the ray trace than a single frame.
TEST(AmbientOcclusionTemporal, AStillViewConverges) {
    BoxOnFloor scene(sharedContext(), 96);
    BoxOnFloor::Sequence sequence(scene, accumulating(), {});
    auto floor = [&](uint32_t x, uint32_t y) { return scene.trueVisibility(int(x), int(y)) >= 0; };
    std::vector<CapturedFrame> frames;
    constexpr uint32_t kFrames = 8;
    for (uint32_t f = 0; f < kFrames; ++f)
        frames.push_back(sequence.render(glm::vec3(0.0f)));
    const double early = meanFloorChange(frames[1], frames[0], floor);
    const double late = meanFloorChange(frames[kFrames - 1], frames[kFrames - 2], floor);
    const VisibilityError single = scene.compare(frames[0]);
    const VisibilityError accumulated = scene.compare(frames[kFrames - 1]);
    std::printf(
        "frame-to-frame floor change: frames 0-1 %.5f, %u-%u %.5f; error vs ray trace: "
        "1 frame %.4f (open %.4f), %u frames %.4f (open %.4f)\n",
        early, kFrames - 2, kFrames - 1, late, single.occludedMeanAbs, single.openMeanDarkening,
        kFrames, accumulated.occludedMeanAbs, accumulated.openMeanDarkening);
    EXPECT_GT(early, 1e-4) << "the slices must rotate between frames";
    EXPECT_LT(late, 0.3 * early);
    EXPECT_LE(accumulated.occludedMeanAbs, single.occludedMeanAbs + 0.005);
    EXPECT_LE(accumulated.occludedMeanAbs, 0.07);
    EXPECT_LE(accumulated.openMeanDarkening, 0.05);
    EXPECT_EQ(sharedContext().validationMessages(), 0u);
}

// The box jumps aside after the history has converged: the floor it uncovers rejects the
// history there (the box's depth and normals) and shows this frame's visibility, not the
// box's accumulated occlusion.
TEST(AmbientOcclusionTemporal, UncoveredFloorLeavesNoStaleOcclusion) {
    BoxOnFloor scene(sharedContext(), 96);
    BoxOnFloor::Sequence sequence(scene, accumulating(), {});
    const glm::vec3 start(0.0f), moved(-1.4f, 0.0f, 0.6f);
    CapturedFrame before;
    for (uint32_t f = 0; f < 4; ++f)
        before = sequence.render(start);
    const CapturedFrame after = sequence.render(moved);
    // The same frame without history: what the uncovered floor should show.
    RendererOptions fresh = accumulating();
    fresh.aoSettings.temporal = AoTemporal::Never;
    BoxOnFloor::Sequence single(scene, fresh, {});
    const CapturedFrame expected = single.render(moved);
    // Uncovered: the box (black) before, lit floor now, away from the new box's edges.
    auto uncovered = [&](uint32_t x, uint32_t y) {
        if (hdrPixel(before, x, y)[1] > 0.0f) return false;
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                const uint32_t qx = uint32_t(std::clamp(int(x) + dx, 0, int(after.width) - 1));
                const uint32_t qy = uint32_t(std::clamp(int(y) + dy, 0, int(after.height) - 1));
                if (hdrPixel(expected, qx, qy)[1] <= 0.0f) return false;
            }
        }
        return true;
    };
    uint32_t pixels = 0;
    for (uint32_t y = 0; y < after.height; ++y)
        for (uint32_t x = 0; x < after.width; ++x)
            pixels += uncovered(x, y) ? 1u : 0u;
    const double stale = meanFloorChange(after, expected, uncovered);
    std::printf("uncovered floor: %u px, mean |accumulated - fresh| %.4f\n", pixels, stale);
    ASSERT_GT(pixels, 60u) << "the move must uncover floor the box covered";
    // The slices rotate, so the two differ by GTAO's noise, not by the box's occlusion.
    EXPECT_LE(stale, 0.03);
    EXPECT_EQ(sharedContext().validationMessages(), 0u);
}
