// Rect and disk lights (issue 15, render/shaders/common/area_lights.glsl) on the device: irradiance
// on a floor under a ceiling light against the closed-form form factors. The "ltc" mode's diffuse
// (Lambert's edge sum; Heitz and Hill's disk integral) within 1 %; Drobot's representative point
// (2014, GPU Pro 5, "Physically Based Area Lights") within 5 % under the centre and 8 % elsewhere
// where it can hold, with its worst error on the whole grid printed.
//
// Where it cannot: off the centre, once the point's projection leaves the light (or its normal
// ray misses it), p_c and p_r are both the light's nearest edge point, so the sample is the
// integrand's maximum, carrying the whole area. For a light of side s at height h and a point
// at horizontal offset o, moving the sample from the centre to that edge shortens d^2 by about
// s o, and the irradiance (cos^2 / d^2, ~ h^2 / d^4) grows by about 2 s o / (h^2 + o^2): the
// overestimate peaks near o = h at about s / h (measured on the host in double: s / h = 0.05 ->
// 5.6 %, 0.1 -> 11 %, 0.25 -> 29 %, 0.5 -> 60 %, 1 -> 123 % at o = 1.5 h). So the 8 % holds at
// every offset only for lights under h / 14 across, and for lights up to h / 8 within h / 4 of
// the centre (the error grows with o there); past that Drobot's point is not a bound, and
// the ltc mode (1 %) is the one to use.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "error_stats.h"
#include "form_factors.h"
#include "light_accuracy.h"

using namespace candela::stability;

namespace {

constexpr double kPi = std::numbers::pi;

struct Case {
    double h, size, offset;
    bool disk;
    double reference;  // irradiance per unit luminance: pi x form factor
};

// A ceiling light at height h centred over (0, 0), lit side down, shading point at (offset, 0.2
// offset) on the floor. Rect: size x 0.6 size; disk: radius size / 2.
LightSample sampleOf(const Case& c) {
    LightSample s;
    s.a = {0.0f, 0.0f, float(c.h), c.disk ? 1.0f : 0.0f};
    s.b = {0.0f, 0.0f, -1.0f, float(0.5 * c.size)};
    s.c = {1.0f, 0.0f, 0.0f, float(0.3 * c.size)};
    s.d = {float(c.offset), float(0.2 * c.offset), 0.0f, 0.0f};
    return s;
}

std::vector<Case> floorCases() {
    std::vector<Case> cases;
    for (bool disk : {false, true}) {
        for (double h : {0.25, 1.0, 3.0}) {
            for (double size : {0.05, 0.2, 0.5, 1.0, 2.0, 6.0}) {
                for (double offset : {0.0, 0.1, 0.4, 1.0, 2.5}) {
                    const double x = offset, y = 0.2 * offset;
                    const double ff =
                        disk ? parallelDiskFormFactor(0.5 * size, h, std::hypot(x, y))
                             : parallelRectangleFormFactor(-0.5 * size - x, 0.5 * size - x,
                                                           -0.3 * size - y, 0.3 * size - y, h);
                    cases.push_back({h, size, offset, disk, kPi * ff});
                }
            }
        }
    }
    return cases;
}

}  // namespace

TEST(AreaLightIrradiance, FloorUnderRectAndDiskMatchesTheFormFactor) {
    ComputeHarness harness;
    const std::vector<Case> cases = floorCases();
    std::vector<LightSample> samples;
    for (const Case& c : cases)
        samples.push_back(sampleOf(c));
    const auto values = evaluateOnDevice(harness, LightFunction::AreaLightDiffuse, samples);
    WorstError ltc, centre, near, smallAnywhere, anywhere, unclamped;
    for (size_t i = 0; i < cases.size(); ++i) {
        const Case& c = cases[i];
        if (c.reference < 1e-3) continue;  // far off and tiny: fp32 edge sums cancel (ltc.glsl)
        const auto describe = [&] {
            return std::string(c.disk ? "disk" : "rect") + " h " + std::to_string(c.h) + " size " +
                   std::to_string(c.size) + " offset " + std::to_string(c.offset) + ": ltc " +
                   std::to_string(values[i][0]) + " representative " +
                   std::to_string(values[i][1]) + " reference " + std::to_string(c.reference);
        };
        ltc.add(std::fabs(values[i][0] / c.reference - 1.0), describe);
        const double representative = std::fabs(values[i][1] / c.reference - 1.0);
        anywhere.add(representative, describe);
        unclamped.add(std::fabs(values[i][2] / c.reference - 1.0), describe);
        // Drobot's point stands for the whole light off the centre while the light is small
        // against its height: under h / 14 at any offset, under h / 8 within h / 4 (see the top).
        if (c.offset == 0.0) {
            centre.add(representative, describe);
        } else {
            if (c.size <= c.h / 14.0) smallAnywhere.add(representative, describe);
            if (c.size <= c.h / 8.0 && c.offset <= c.h / 4.0) near.add(representative, describe);
        }
    }
    ltc.print("area light diffuse, ltc", "relative");
    centre.print("area light diffuse, representative, under the centre", "relative");
    smallAnywhere.print("area light diffuse, representative, lights under h / 14, any offset",
                        "relative");
    near.print("area light diffuse, representative, lights under h / 8 within h / 4", "relative");
    anywhere.print("area light diffuse, representative, whole grid", "relative");
    unclamped.print("area light diffuse, representative unclamped, whole grid", "relative");
    EXPECT_LE(ltc.error, 0.01);
    EXPECT_LE(centre.error, 0.05);
    EXPECT_LE(smallAnywhere.error, 0.08);
    EXPECT_LE(near.error, 0.08);
    // Each region has cases (a grid change cannot empty it and pass vacuously).
    EXPECT_GT(smallAnywhere.count, 0);
    EXPECT_GT(near.count, 0);
    EXPECT_EQ(harness.validationMessages(), 0u);
}

// The solid angle of the rectangle [x0, x1] x [y0, y1] at height h over the origin: a
// constant-intensity light's irradiance per unit I_A on a parallel floor (cos theta_o = cos
// theta_i, so I_A integral of cos / r^2 dA is I_A times the solid angle).
double parallelRectangleSolidAngle(double x0, double x1, double y0, double y1, double h) {
    const auto corner = [h](double x, double y) {
        return std::atan2(x * y, h * std::sqrt(x * x + y * y + h * h));
    };
    return corner(x1, y1) - corner(x0, y1) - corner(x1, y0) + corner(x0, y0);
}

// Drobot's (2014, GPU Pro 5, "Physically Based Area Lights") constant-intensity variant on the
// floor grid: the exact Lambertian irradiance times the pre-integrated diffuse factor
// (area_light_constant_intensity.glsl) against the closed form I_A x solid angle, for rects. The
// factor is the luminance averaged over the light's area, not weighted by what each part delivers,
// so it holds while the luminance I_A r / h varies little over the light: within 2.5 % for lights
// up to h / 2 across (host double: s / h 0.5 -> 2.0 % worst, at o = h), 7.5 % at s = h, 23 % at 2
// h, and a light 24 h across (the grid's 6 m at 0.25 m) is 3.2x over, its far parts' large
// luminance counted at full area; printed with the whole grid's worst.
TEST(AreaLightIrradiance, ConstantIntensityRectFactorTracksTheSolidAngle) {
    ComputeHarness harness;
    std::vector<Case> cases;
    for (const Case& c : floorCases()) {
        if (!c.disk) cases.push_back(c);
    }
    std::vector<LightSample> samples;
    for (const Case& c : cases)
        samples.push_back(sampleOf(c));
    const auto values = evaluateOnDevice(harness, LightFunction::AreaLightDiffuse, samples);
    WorstError upToHalfHeight, anywhere;
    for (size_t i = 0; i < cases.size(); ++i) {
        const Case& c = cases[i];
        const double x = c.offset, y = 0.2 * c.offset;
        const double reference = parallelRectangleSolidAngle(
            -0.5 * c.size - x, 0.5 * c.size - x, -0.3 * c.size - y, 0.3 * c.size - y, c.h);
        if (reference < 1e-3) continue;
        const auto describe = [&] {
            return "h " + std::to_string(c.h) + " size " + std::to_string(c.size) + " offset " +
                   std::to_string(c.offset) + ": " + std::to_string(values[i][3]) + " reference " +
                   std::to_string(reference);
        };
        const double error = std::fabs(values[i][3] / reference - 1.0);
        anywhere.add(error, describe);
        if (c.size <= 0.5 * c.h) upToHalfHeight.add(error, describe);
    }
    upToHalfHeight.print("constant intensity, ltc x factor, lights up to h / 2", "relative");
    anywhere.print("constant intensity, ltc x factor, whole grid", "relative");
    EXPECT_LE(upToHalfHeight.error, 0.025);
    EXPECT_GT(upToHalfHeight.count, 0);
    EXPECT_EQ(harness.validationMessages(), 0u);
}

// One-sided: a shading point behind the light's plane, or a light facing away, gets nothing.
TEST(AreaLightIrradiance, BackSideAndFacingAwayGetNothing) {
    ComputeHarness harness;
    std::vector<LightSample> samples;
    for (bool disk : {false, true}) {
        Case facingAway{1.0, 1.0, 0.3, disk, 0.0};
        LightSample s = sampleOf(facingAway);
        s.b = {0.0f, 0.0f, 1.0f, s.b[3]};  // emits upwards, away from the floor
        s.c = {1.0f, 0.0f, 0.0f, s.c[3]};
        samples.push_back(s);
        LightSample below = sampleOf(facingAway);
        below.a[2] = -0.5f;  // under the floor, facing down: the floor is behind it
        samples.push_back(below);
    }
    const auto values = evaluateOnDevice(harness, LightFunction::AreaLightDiffuse, samples);
    for (const auto& v : values) {
        EXPECT_EQ(v[0], 0.0f);
        EXPECT_EQ(v[1], 0.0f);
        EXPECT_EQ(v[2], 0.0f);
    }
    EXPECT_EQ(harness.validationMessages(), 0u);
}
