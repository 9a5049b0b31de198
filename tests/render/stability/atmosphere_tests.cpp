// The atmosphere (issue 16, render/README.md "Atmosphere"): the transmittance the shaders'
// table stores (common/atmosphere.glsl, run on the device with the table's sample count)
// against a direct numerical integral of the density profiles in double
// (render::atmosphereTransmittance with 20,000 samples), and the sun it gives at the ground:
// at the zenith a clear-sky sun of 100-120 klux, at 5 degrees reddened.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "candela/render/atmosphere_transmittance.h"
#include "candela/render/renderer_options.h"
#include "compute_harness.h"
#include "passes/atmosphere/atmosphere_parameters.h"
#include "shaders/atmosphere_accuracy.comp.spv.h"

using namespace candela;

namespace {

struct Push {
    render::GpuAtmosphere atmosphere;
    uint32_t info[4];
};

struct Ray {
    float altitudeKm, mu, unused0, unused1;
};

std::vector<Ray> raySweep() {
    std::vector<Ray> rays;
    for (float altitude : {0.0f, 0.2f, 1.0f, 5.0f, 12.0f, 30.0f, 60.0f, 99.0f}) {
        for (int i = 0; i <= 40; ++i)
            rays.push_back({altitude, -1.0f + float(i) / 20.0f, 0, 0});
        for (float mu : {-0.2f, -0.1f, -0.05f, -0.02f, 0.0f, 0.01f, 0.02f, 0.05f, 0.1f, 0.2f})
            rays.push_back({altitude, mu, 0, 0});
    }
    return rays;
}

}  // namespace

// Every ray of the sweep, from the ground to the top and from straight down to straight up
// (the table's rays ignore the ground), within 1e-3 of the double integral per channel.
TEST(AtmosphereTransmittance, TableSamplesMatchTheDoubleIntegralWithin1e3) {
    stability::ComputeHarness harness;
    const content::Atmosphere earth;
    const render::AtmosphereSettings settings;
    const std::vector<Ray> rays = raySweep();
    render::GpuBuffer in = harness.upload(std::span<const Ray>(rays));
    render::GpuBuffer out = harness.buffer(rays.size() * 16);
    render::GpuBuffer trip = harness.buffer(rays.size() * 16);
    render::Pipeline pipeline = harness.pipeline(atmosphere_accuracy_comp_spv, 3, sizeof(Push));
    const Push push{render::gpuAtmosphere(earth),
                    {uint32_t(rays.size()), settings.transmittanceSteps,
                     settings.transmittanceWidth, settings.transmittanceHeight}};
    harness.dispatch(pipeline, {&in, &out, &trip}, &push, sizeof(push),
                     uint32_t((rays.size() + 63) / 64));
    const auto device = harness.read<glm::vec4>(out, rays.size());
    const auto roundTrip = harness.read<glm::vec4>(trip, rays.size());
    double worst = 0.0, worstMu = 0.0, worstAltitude = 0.0, worstTrip = 0.0;
    for (size_t i = 0; i < rays.size(); ++i) {
        const glm::dvec3 reference = render::atmosphereTransmittance(
            earth, double(rays[i].altitudeKm) * 1000.0, double(rays[i].mu));
        for (int c = 0; c < 3; ++c) {
            const double error = std::abs(double(device[i][c]) - reference[c]);
            if (error > worst) {
                worst = error;
                worstMu = rays[i].mu;
                worstAltitude = rays[i].altitudeKm;
            }
        }
        // The parameterisation gives back the ray (float rounding of a 6,360 km radius).
        worstTrip = std::max(worstTrip, std::abs(double(roundTrip[i].y) - rays[i].mu));
        EXPECT_NEAR(roundTrip[i].x, rays[i].altitudeKm, 2e-3) << "mu " << rays[i].mu;
    }
    std::printf(
        "transmittance: worst |device - double| %.3g at altitude %.3g km, mu %.3g; "
        "parameterisation round trip |d mu| %.3g\n",
        worst, worstAltitude, worstMu, worstTrip);
    EXPECT_LT(worst, 1e-3);
    EXPECT_LT(worstTrip, 2e-3);
    EXPECT_EQ(harness.validationMessages(), 0u);
}

// The sun straight overhead at sea level: 128,000 lux outside times the zenith transmittance.
TEST(AtmosphereSun, ZenithSunIsAClearSkySunOf100To120Klux) {
    const content::Atmosphere earth;
    const glm::dvec3 e = render::sunIlluminanceAtGround(earth, 0.0, 1.0);
    const double lux = render::luminanceOf(e);
    std::printf("zenith sun at sea level: %.0f lux (rgb %.0f %.0f %.0f)\n", lux, e.r, e.g, e.b);
    EXPECT_GT(lux, 100000.0);
    EXPECT_LT(lux, 120000.0);
}

// At 5 degrees the light crosses ~10 air masses: blue is scattered away first, so the sun's
// colour (normalised to its luminance) has R > G > B, and far more red than blue.
TEST(AtmosphereSun, SunAt5DegreesIsReddened) {
    const content::Atmosphere earth;
    const glm::dvec3 e =
        render::sunIlluminanceAtGround(earth, 0.0, std::sin(5.0 * std::numbers::pi / 180.0));
    const double lux = render::luminanceOf(e);
    const glm::dvec3 colour = e / lux;
    std::printf("sun at 5 degrees: %.0f lux, colour %.3f %.3f %.3f\n", lux, colour.r, colour.g,
                colour.b);
    EXPECT_GT(colour.r, colour.g);
    EXPECT_GT(colour.g, colour.b);
    EXPECT_GT(colour.r / colour.b, 2.0);
    const glm::dvec3 zenith = render::sunIlluminanceAtGround(earth, 0.0, 1.0);
    EXPECT_LT(lux, 0.5 * render::luminanceOf(zenith));
}
