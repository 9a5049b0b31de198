// The atmosphere's sky in the renderer (issue 16, render/README.md "Atmosphere"): the
// background it draws (blue overhead, the sun's disc as bright as the transmittance makes it)
// and its image-based lighting, re-filtered over three frames when the sun moves and swapped
// in at the third, with validation (synchronisation included) clean throughout.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <string>

#include "candela/render/atmosphere_transmittance.h"
#include "candela/render/gpu_context.h"
#include "test_scene.h"

namespace candela::render::test {
namespace {

LightInstance sunAt(float elevationDegrees, float lux) {
    const float e = glm::radians(elevationDegrees);
    LightInstance sun;
    sun.light.type = content::LightType::Directional;
    sun.light.lux = lux;
    sun.direction = -glm::vec3(0.0f, std::sin(e), -std::cos(e));
    return sun;
}

bool hasPass(const RendererStats& stats, const std::string& name) {
    return std::any_of(stats.passMs.begin(), stats.passMs.end(),
                       [&](const RendererStats::PassTime& p) { return p.first == name; });
}

double luminance(const float* rgb) {
    return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
}

// Looking straight at a sun 30 degrees up: the disc's centre pixel carries the disc's radiance
// outside the atmosphere times the transmittance (fp16 tables: 1 %); straight up, the sky is
// blue (B > G > R).
TEST(AtmosphereSky, BackgroundHasTheSunsDiscAndABlueZenith) {
    GpuContext context(requiredValidation());
    TestScene scene;
    scene.width = scene.height = 33;
    scene.lights.push_back(sunAt(30.0f, 0.0f));
    const float e = glm::radians(30.0f);
    // 0.2 degrees of view: the disc (0.545 degrees) covers the middle pixels.
    scene.lookAt(glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0.0f, 1.0f + std::sin(e), -std::cos(e)),
                 glm::vec3(0, 1, 0), glm::radians(0.2f));
    SceneResources resources(context);
    FrameInputs inputs = scene.prepare(resources);
    const content::Atmosphere earth;
    inputs.scene.atmosphere = earth;
    FrameSequence frames(context, 33, 33);  // one renderer for both views: one shader build
    CapturedFrame sun = frames.render(inputs, resources);
    const glm::dvec3 t = atmosphereTransmittance(earth, 1.0, std::sin(double(e)));
    const double angularRadius = 0.5 * glm::radians(double(earth.sunAngularDiameter));
    const double disc = earth.solarIlluminance /
                        (glm::pi<double>() * std::sin(angularRadius) * std::sin(angularRadius));
    const float* centre = hdrPixel(sun, 16, 16);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(centre[c] / (disc * t[c]), 1.0, 0.01) << "channel " << c;

    scene.lookAt(glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0.0f, 2.0f, 0.0f), glm::vec3(0, 0, -1),
                 glm::radians(10.0f));
    inputs = scene.prepare(resources);
    inputs.scene.atmosphere = earth;
    CapturedFrame zenith = frames.render(inputs, resources);
    const float* up = hdrPixel(zenith, 16, 16);
    EXPECT_GT(up[2], up[1]);
    EXPECT_GT(up[1], up[0]);
    EXPECT_GT(luminance(up), 1000.0) << "a clear day's zenith is thousands of cd/m^2";
    EXPECT_LT(luminance(up), 20000.0);
    EXPECT_EQ(context.validationMessages(), 0u);
}

// A white floor lit by the sky alone (the sun light at 0 lux): the sun drops from 60 to 10
// degrees after the first frame; the sky cube is re-made in three steps (frames 1, 2, 3),
// the floor keeps the old sky's light until the third swaps the new one in, and then no
// further step runs while the sun stays.
TEST(AtmosphereSky, AMovingSunRelightsTheSceneOverThreeFrames) {
    GpuContext context(requiredValidation());
    TestScene scene;
    scene.width = scene.height = 16;
    scene.add(content::makePlane(40.0f, 1), lambertWhite());
    scene.lookAt(glm::vec3(0.0f, 2.0f, 0.0f), glm::vec3(0.0f, 0.0f, -4.0f), glm::vec3(0, 1, 0));
    scene.lights.push_back(sunAt(60.0f, 0.0f));
    SceneResources resources(context);
    RendererOptions options;
    FrameSequence frames(context, scene.width, scene.height, options);
    std::vector<double> floor;
    std::vector<bool> ibl;
    for (int i = 0; i < 5; ++i) {
        scene.lights[0] = sunAt(i == 0 ? 60.0f : 10.0f, 0.0f);
        FrameInputs inputs = scene.prepare(resources);
        inputs.scene.atmosphere = content::Atmosphere{};
        RendererStats stats;
        CapturedFrame frame = frames.render(inputs, resources, &stats);
        floor.push_back(luminance(hdrPixel(frame, 8, 12)));
        ibl.push_back(hasPass(stats, "atmosphere_ibl"));
    }
    EXPECT_TRUE(ibl[0]) << "the first frame makes the sky cube";
    EXPECT_TRUE(ibl[1] && ibl[2] && ibl[3]) << "three amortised steps after the sun moved";
    EXPECT_FALSE(ibl[4]) << "nothing to do while the sun stays";
    EXPECT_GT(floor[0], 100.0);
    EXPECT_DOUBLE_EQ(floor[1], floor[0]) << "the old sky lights frames 1 and 2";
    EXPECT_DOUBLE_EQ(floor[2], floor[0]);
    EXPECT_LT(floor[3], 0.8 * floor[0]) << "a low sun's sky is darker, from the third frame";
    EXPECT_DOUBLE_EQ(floor[4], floor[3]);
    EXPECT_EQ(context.validationMessages(), 0u);
}

}  // namespace
}  // namespace candela::render::test
