// Antialiasing (issue 24): TAA and FXAA against a 4x4 supersampled reference on hard edges,
// TAA's temporal stability under a slow pan, and its ghosting behind a moving bright object.
#include <gtest/gtest.h>

#include <cstdio>

#include "antialiasing_scenes.h"

namespace candela::render::test {
namespace {

class Antialiasing : public ::testing::Test {
protected:
    GpuContext context{requiredValidation()};
};

// The goals: TAA after 16 static frames at most a third of the unantialiased edge
// RMSE, the post-process AA at most half (displayed values; reference resolved in linear
// light: antialiasing_scenes.h).
TEST_F(Antialiasing, EdgeErrorAgainstSupersamplingOnABoxOnAFloor) {
    constexpr uint32_t kWidth = 128, kHeight = 96;
    const std::vector<float> reference =
        supersampledReference(context, &boxOnFloor, kWidth, kHeight);
    const std::vector<uint8_t> mask = edgeMask(reference, kWidth, kHeight);
    size_t edgePixels = 0;
    for (uint8_t m : mask)
        edgePixels += m;
    ASSERT_GT(edgePixels, 200u);  // the scene has edges to measure

    TestScene scene = boxOnFloor(kWidth, kHeight);
    const double off =
        edgeRmse(displayed(renderStatic(context, scene, AntiAliasing::Off, 1)), reference, mask);
    const double fxaa =
        edgeRmse(displayed(renderStatic(context, scene, AntiAliasing::Fxaa, 1)), reference, mask);
    const double taa =
        edgeRmse(displayed(renderStatic(context, scene, AntiAliasing::Taa, 16)), reference, mask);
    std::printf("edge RMSE over %zu pixels: off %.4f, fxaa %.4f, taa %.4f\n", edgePixels, off, fxaa,
                taa);
    EXPECT_GT(off, 0.02);  // the unantialiased frame really has staircases
    EXPECT_LE(fxaa, off / 2.0);
    EXPECT_LE(taa, off / 3.0);
}

// A slow pan over thin posts: the mean absolute frame-to-frame change of the displayed image,
// after moving the previous frame by the pan's screen motion, is at least 3x lower with TAA.
TEST_F(Antialiasing, TaaCutsFlickerUnderASlowPanOverThinGeometry) {
    constexpr uint32_t kWidth = 128, kHeight = 64;
    constexpr uint32_t kWarmUp = 8, kMeasured = 12;
    TestScene scene = thinPosts(kWidth, kHeight);
    const float focal = float(kHeight) * 0.5f / std::tan(glm::radians(40.0f) * 0.5f);
    const float shiftPixels = 0.3f;  // per frame, at the posts' depth (4 m)
    const float step = shiftPixels * 4.0f / focal;

    auto flicker = [&](AntiAliasing aa) {
        SceneResources resources(context);
        FrameSequence sequence(context, kWidth, kHeight, aa);
        std::vector<float> previous;
        double sum = 0.0;
        for (uint32_t f = 0; f < kWarmUp + kMeasured; ++f) {
            const glm::vec3 eye(step * float(f), 0.0f, 4.0f);
            scene.lookAt(eye, eye - glm::vec3(0, 0, 4), {0, 1, 0}, glm::radians(40.0f));
            FrameInputs inputs = scene.prepare(resources);
            std::vector<float> current = displayed(sequence.render(inputs, resources));
            if (f >= kWarmUp)
                sum += compensatedFlicker(previous, current, kWidth, kHeight, shiftPixels);
            previous = std::move(current);
        }
        return sum / kMeasured;
    };
    const double off = flicker(AntiAliasing::Off);
    const double taa = flicker(AntiAliasing::Taa);
    std::printf("compensated flicker: off %.5f, taa %.5f (%.1fx)\n", off, taa, off / taa);
    EXPECT_GT(off, 0.005);  // the pan really crawls without AA
    EXPECT_GE(off / taa, 3.0);
}

// A small bright object crossing a dark frame 8 pixels per frame: 4 frames after it left a
// place, TAA keeps under 5% of its radiance there (the clipped history drops it).
TEST_F(Antialiasing, TaaLeavesUnderFivePercentOfAMovingBrightObjectBehind) {
    constexpr uint32_t kWidth = 128, kHeight = 64;
    content::Material glow = lambertWhite();
    glow.baseColorFactor = {0.0f, 0.0f, 0.0f, 1.0f};
    glow.emissiveFactor = {1.0f, 1.0f, 1.0f};
    glow.emissiveStrength = 50.0f;
    auto sceneAt = [&](float x) {
        TestScene scene;
        scene.width = kWidth;
        scene.height = kHeight;
        scene.add(content::makeSphere(0.12f, 16, 8), glow,
                  glm::translate(glm::mat4(1.0f), glm::vec3(x, 0.0f, 0.0f)));
        scene.lookAt({0, 0, 4}, {0, 0, 0}, {0, 1, 0}, glm::radians(40.0f));
        scene.camera.ev100 = 0.0f;
        return scene;
    };
    const float focal = float(kHeight) * 0.5f / std::tan(glm::radians(40.0f) * 0.5f);
    const float step = 8.0f * 4.0f / focal;  // 8 pixels per frame at 4 m
    constexpr uint32_t kFrames = 10;

    auto radiance = [](const CapturedFrame& frame, const std::vector<uint8_t>* exclude) {
        double sum = 0.0;
        for (size_t p = 0; p < size_t(frame.width) * frame.height; ++p) {
            if (exclude && (*exclude)[p]) continue;
            sum += frame.hdrRgb[p * 3] + frame.hdrRgb[p * 3 + 1] + frame.hdrRgb[p * 3 + 2];
        }
        return sum;
    };
    SceneResources resources(context);
    FrameSequence taa(context, kWidth, kHeight, AntiAliasing::Taa);
    FrameSequence off(context, kWidth, kHeight, AntiAliasing::Off);
    std::vector<glm::mat4> previousWorld(1);
    double worst = 0.0;
    for (uint32_t f = 0; f < kFrames; ++f) {
        const float x = -1.0f + step * float(f);
        TestScene scene = sceneAt(x);
        FrameInputs inputs = scene.prepare(resources);
        previousWorld[0] =
            glm::translate(glm::mat4(1.0f), glm::vec3(f == 0 ? x : x - step, 0.0f, 0.0f));
        inputs.scene.previousWorlds = previousWorld;
        const CapturedFrame resolved = taa.render(inputs, resources);
        const CapturedFrame plain = off.render(inputs, resources);
        if (f < 4) continue;  // the object must have moved 4 frames away from where it began
        // Where the object is now, grown by 2 pixels (its antialiased rim).
        std::vector<uint8_t> now(size_t(kWidth) * kHeight, 0);
        for (uint32_t y = 0; y < kHeight; ++y) {
            for (uint32_t px = 0; px < kWidth; ++px) {
                if (hdrPixel(plain, px, y)[0] <= 0.0f) continue;
                for (int dy = -2; dy <= 2; ++dy) {
                    for (int dx = -2; dx <= 2; ++dx) {
                        int qx = int(px) + dx, qy = int(y) + dy;
                        if (qx >= 0 && qy >= 0 && qx < int(kWidth) && qy < int(kHeight))
                            now[size_t(qy) * kWidth + size_t(qx)] = 1;
                    }
                }
            }
        }
        const double object = radiance(plain, nullptr);
        ASSERT_GT(object, 0.0);
        worst = std::max(worst, radiance(resolved, &now) / object);
    }
    std::printf("radiance left behind (worst frame): %.4f of the object's\n", worst);
    EXPECT_LT(worst, 0.05);
}

}  // namespace
}  // namespace candela::render::test
