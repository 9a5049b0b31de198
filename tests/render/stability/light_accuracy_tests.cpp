// Accuracy of the shared light helpers on the device against the double-precision reference
// (light_reference.h) over normal inputs: eq. 9 falloff, eq. 10/14/20 energy normalisation,
// eq. 11 representative point, eq. 19 closest point on a tube.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "error_stats.h"
#include "light_accuracy.h"
#include "light_reference.h"
#include "quasi_random.h"

using namespace candela::stability;
namespace ref = candela::stability::reference;
using ref::operator-;
using ref::operator*;

namespace {

constexpr double kUnitRoundoff = 5.9604644775390625e-08;  // 2^-24

ref::Vec3 toVec3(const Float4& v) {
    return {v[0], v[1], v[2]};
}

// A unit vector from two uniform numbers (uniform on the sphere).
Float4 unitVector(double u, double v) {
    const double z = 2.0 * u - 1.0;
    const double r = std::sqrt(std::max(1.0 - z * z, 0.0));
    const double phi = 2.0 * 3.14159265358979 * v;
    return {float(r * std::cos(phi)), float(r * std::sin(phi)), float(z), 0.0f};
}

double logUniform(double u, double lo, double hi) {
    return lo * std::pow(hi / lo, u);
}

std::string text(const char* format, double a, double b, double c = 0.0) {
    char buffer[128];
    std::snprintf(buffer, sizeof(buffer), format, a, b, c);
    return buffer;
}

}  // namespace

// eq. 9 in metres. inverseSquare is one add and one divide: 2 roundings, held to 1e-6.
// The window saturate(1 - (d/r)^4)^2 cancels toward the attenuation radius, where it goes to
// 0, so it is judged absolutely (it multiplies an intensity): 1e-6.
TEST(LightAccuracy, FalloffMatchesEq9) {
    ComputeHarness harness;
    std::vector<LightSample> samples;
    for (uint32_t i = 0; i < 20000; ++i) {
        const auto u = halton<2>(i);
        const double distance = logUniform(u[0], 1e-3, 1e4);
        const double radius = logUniform(u[1], 1e-2, 1e5);
        samples.push_back({{float(distance * distance), float(1.0 / radius), 0, 0}});
    }
    const auto window = evaluateOnDevice(harness, LightFunction::AttenuationWindow, samples);
    const auto inverse = evaluateOnDevice(harness, LightFunction::InverseSquare, samples);
    WorstError windowError, inverseError;
    for (size_t i = 0; i < samples.size(); ++i) {
        const double distanceSq = samples[i].a[0];
        const double radius = 1.0 / double(samples[i].a[1]);
        const double distance = std::sqrt(distanceSq);
        const auto where = [&] { return text("distance %.6g radius %.6g", distance, radius); };
        windowError.add(std::fabs(window[i][0] - ref::attenuationWindow(distance, radius)), where);
        inverseError.add(relativeError(inverse[i][0], ref::inverseSquare(distance)), where);
    }
    windowError.print("attenuationWindow (eq. 9)", "absolute");
    inverseError.print("inverseSquare (eq. 9, metres)", "relative");
    EXPECT_LE(windowError.error, 1e-6);
    EXPECT_LE(inverseError.error, 1e-6);
    EXPECT_EQ(harness.validationMessages(), 0u);
}

// eq. 10 + 14 and eq. 20: a handful of operations, held to 1e-5 relative.
TEST(LightAccuracy, EnergyNormalizationMatchesEq10To20) {
    ComputeHarness harness;
    std::vector<LightSample> samples;
    for (uint32_t i = 0; i < 20000; ++i) {
        const auto u = halton<3>(i);
        const double alpha = logUniform(u[0], 4e-4, 1.0);
        const double size = logUniform(u[1], 1e-4, 1e2);
        const double distance = logUniform(u[2], 1e-2, 1e3);
        samples.push_back({{float(alpha), float(size), float(distance), 0}});
    }
    const auto sphere =
        evaluateOnDevice(harness, LightFunction::SphereEnergyNormalization, samples);
    const auto tube = evaluateOnDevice(harness, LightFunction::TubeEnergyNormalization, samples);
    WorstError sphereError, tubeError;
    for (size_t i = 0; i < samples.size(); ++i) {
        const double alpha = samples[i].a[0], size = samples[i].a[1], distance = samples[i].a[2];
        const auto where = [&] {
            return text("alpha %.6g size %.6g distance %.6g", alpha, size, distance);
        };
        sphereError.add(
            relativeError(sphere[i][0], ref::sphereNormalization(alpha, size, distance)), where);
        tubeError.add(relativeError(tube[i][0], ref::tubeNormalization(alpha, size, distance)),
                      where);
    }
    sphereError.print("sphereEnergyNormalization (eq. 14)", "relative");
    tubeError.print("tubeEnergyNormalization (eq. 20)", "relative");
    EXPECT_LE(sphereError.error, 1e-5);
    EXPECT_LE(tubeError.error, 1e-5);
    EXPECT_EQ(harness.validationMessages(), 0u);
}

// eq. 11, judged in units of the distance to the light (the point's position error relative
// to |L|): 1e-5. Directions are as fp32 makes them (the device's inputs feed the reference).
TEST(LightAccuracy, SphereRepresentativePointMatchesEq11) {
    ComputeHarness harness;
    std::vector<LightSample> samples;
    for (uint32_t i = 0; i < 20000; ++i) {
        const auto u = halton<6>(i);
        const double distance = logUniform(u[0], 1e-2, 1e3);
        Float4 L = unitVector(u[1], u[2]);
        for (int k = 0; k < 3; ++k)
            L[k] = float(L[k] * distance);
        const Float4 R = unitVector(u[3], u[4]);
        const double radius = distance * logUniform(u[5], 1e-3, 10.0);
        samples.push_back({L, R, {float(radius), 0, 0, 0}});
    }
    const auto values =
        evaluateOnDevice(harness, LightFunction::SphereRepresentativePoint, samples);
    WorstError error;
    for (size_t i = 0; i < samples.size(); ++i) {
        const ref::Vec3 L = toVec3(samples[i].a), R = toVec3(samples[i].b);
        const double radius = samples[i].c[0];
        const ref::Vec3 expected = ref::sphereRepresentativePoint(L, R, radius);
        const double e = ref::length(toVec3(values[i]) - expected) / ref::length(L);
        error.add(e, [&] {
            return text("|L| %.6g radius %.6g L.R/|L| %.6g", ref::length(L), radius,
                        ref::dot(L, R) / ref::length(L));
        });
    }
    error.print("sphereRepresentativePoint (eq. 11)", "|error| / |L|");
    EXPECT_LE(error.error, 1e-5);
    EXPECT_EQ(harness.validationMessages(), 0u);
}

// eq. 19: t = (R.L0 R.Ld - L0.Ld) / (|Ld|^2 - (R.Ld)^2). The denominator is |Ld|^2 sin^2 of
// the angle between R and the tube, so t's rounding error grows as 1 / sin^2: the test keeps
// sin^2 >= 0.01 and holds |t - t_ref| to 64 ulp(1) * |L0| |Ld| / (|Ld|^2 sin^2) + 1e-6
// (numerator terms of size |L0||Ld| each carry ~ulp errors).
TEST(LightAccuracy, TubeClosestParameterMatchesEq19) {
    ComputeHarness harness;
    std::vector<LightSample> samples;
    for (uint32_t i = 0; i < 20000; ++i) {
        const auto u = halton<7>(i);
        const double distance = logUniform(u[0], 1e-2, 1e3);
        const double length = distance * logUniform(u[1], 1e-2, 1e2);
        Float4 center = unitVector(u[2], u[3]);
        const Float4 axis = unitVector(u[4], u[5]);
        const Float4 R = unitVector(u[6], halton<8>(i)[7]);
        Float4 L0{}, Ld{};
        for (int k = 0; k < 3; ++k) {
            L0[k] = float(center[k] * distance - 0.5 * length * axis[k]);
            Ld[k] = float(length * axis[k]);
        }
        samples.push_back({L0, Ld, R, {}});
    }
    const auto values = evaluateOnDevice(harness, LightFunction::TubeClosestParameter, samples);
    WorstError error;
    long used = 0;
    for (size_t i = 0; i < samples.size(); ++i) {
        const ref::Vec3 L0 = toVec3(samples[i].a), Ld = toVec3(samples[i].b),
                        R = toVec3(samples[i].c);
        const double LdLd = ref::dot(Ld, Ld);
        const double sinSq = 1.0 - ref::dot(R, Ld) * ref::dot(R, Ld) / LdLd;
        if (sinSq < 0.01) continue;
        ++used;
        const double bound =
            64.0 * kUnitRoundoff * ref::length(L0) * std::sqrt(LdLd) / (LdLd * sinSq) + 1e-6;
        const double t = ref::tubeClosestParameter(L0, Ld, R);
        error.add(std::fabs(values[i][0] - t) / bound, [&] {
            return text("|L0| %.6g |Ld| %.6g sin^2 %.3g", ref::length(L0), std::sqrt(LdLd), sinSq);
        });
    }
    error.print("tubeClosestParameter (eq. 19)", "|t error| / bound");
    EXPECT_LE(error.error, 1.0);
    EXPECT_GT(used, 10000);
    EXPECT_EQ(harness.validationMessages(), 0u);
}

// Tells the report whether the denormal inputs of the hard grids reached the arithmetic as
// denormals or were flushed to zero on this device (both are allowed by Vulkan).
TEST(LightAccuracy, ReportsDenormalHandling) {
    ComputeHarness harness;
    const float denormal = 1.4e-42f;
    const auto product =
        evaluateOnDevice(harness, LightFunction::Product, {{{denormal, 2.0f, 0, 0}}});
    const bool preserved = product[0][0] == 2.0f * denormal;
    std::printf("  %s: fp32 denormals are %s\n", harness.context().deviceName().c_str(),
                preserved ? "preserved" : "flushed to zero");
    EXPECT_TRUE(product[0][0] == 0.0f || preserved);
    EXPECT_EQ(harness.validationMessages(), 0u);
}
