// Automatic exposure (issue 24): the histogram meters EV100 = log2(L * 100 / 12.5), and a step
// from a dark room to daylight converges to the metered value in the time the adaptation rate
// gives, without overshooting.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "candela/render/auto_exposure.h"
#include "test_scene.h"

namespace candela::render::test {
namespace {

float analyticEv100(float luminance) {
    return std::log2(luminance * 100.0f / 12.5f);
}

TEST(AutoExposure, ADarkRoomToDaylightStepConvergesInTheConfiguredTimeWithoutOvershoot) {
    GpuContext context(requiredValidation());
    constexpr uint32_t kSize = 64;
    constexpr float kDt = 1.0f / 30.0f;
    constexpr float kDarkRoom = 1.0f;     // cd/m^2: a dim hall
    constexpr float kDaylight = 5000.0f;  // cd/m^2: a sunlit facade
    constexpr float kTolerance = 0.1f;    // EV
    RendererOptions options;
    options.exposure = ExposureMode::Auto;
    const AutoExposureSettings& settings = options.autoExposure;
    Renderer renderer(context, kSize, kSize, options);
    FrameSubmitter submitter(context);
    SceneResources resources(context);

    auto frame = [&](float luminance) {
        FrameInputs inputs;
        inputs.clearRadiance = {luminance, luminance, luminance, 1.0f};
        inputs.deltaSeconds = kDt;
        renderer.recordFrame(submitter, inputs, &resources);
        submitter.submit();
        submitter.waitIdle();
        return renderer.collectStats();
    };
    RendererStats stats;
    for (int i = 0; i < 4; ++i)
        stats = frame(kDarkRoom);
    EXPECT_NEAR(stats.exposureEv100, analyticEv100(kDarkRoom), 0.13f);  // half a bin
    EXPECT_NEAR(stats.adaptedEv100, stats.exposureEv100, 1e-4f);        // settled in the hall

    // Daylight. The histogram is read a frame late; then the exposure covers 1 - e^(-rate t)
    // of the way, so it is within kTolerance after ln(step / kTolerance) / rate seconds.
    const float start = stats.adaptedEv100;
    const float step = analyticEv100(kDaylight) - start;
    const float configuredSeconds = std::log(step / kTolerance) / settings.brighteningRate;
    const int allowedFrames = int(std::ceil(configuredSeconds / kDt)) + 2;
    float previous = start;
    int convergedAt = -1;
    float metered = 0.0f;
    for (int i = 0; i < allowedFrames + 10; ++i) {
        stats = frame(kDaylight);
        if (i == 0) continue;  // still metering the hall's histogram
        metered = stats.exposureEv100;
        EXPECT_GE(stats.adaptedEv100, previous - 1e-5f) << "frame " << i;  // monotonic
        EXPECT_LE(stats.adaptedEv100, metered + 1e-4f) << "overshoot at frame " << i;
        previous = stats.adaptedEv100;
        if (convergedAt < 0 && std::abs(stats.adaptedEv100 - metered) <= kTolerance)
            convergedAt = i;
    }
    std::printf(
        "hall EV100 %.3f -> daylight %.3f (analytic %.3f): within %.1f EV after %d "
        "frames (%.2f s), allowed %d\n",
        start, metered, analyticEv100(kDaylight), kTolerance, convergedAt, float(convergedAt) * kDt,
        allowedFrames);
    EXPECT_NEAR(metered, analyticEv100(kDaylight), 0.13f);
    ASSERT_GE(convergedAt, 0);
    EXPECT_LE(convergedAt, allowedFrames);
}

TEST(AutoExposure, CompensationBiasesAndDarkeningIsSlowerThanBrightening) {
    AutoExposureSettings settings;
    settings.compensation = 1.0f;  // one stop brighter: aims one EV100 lower
    float ev = 10.0f;
    for (int i = 0; i < 600; ++i)
        ev = adaptEv100(ev, 10.0f, 1.0f / 30.0f, settings);
    EXPECT_NEAR(ev, 9.0f, 1e-3f);
    settings.compensation = 0.0f;
    const float up = adaptEv100(5.0f, 10.0f, 0.1f, settings) - 5.0f;
    const float down = 10.0f - adaptEv100(10.0f, 5.0f, 0.1f, settings);
    EXPECT_GT(up, down);
    // A histogram with every pixel in one bin meters that bin's centre.
    std::vector<uint32_t> bins(128, 0);
    bins[60] = 1000;
    EXPECT_FLOAT_EQ(*meterEv100(bins, settings), histogramBinEv100(60));
    EXPECT_FALSE(meterEv100(std::vector<uint32_t>(128, 0), settings).has_value());
}

}  // namespace
}  // namespace candela::render::test
