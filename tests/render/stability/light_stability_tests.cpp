// Hard inputs for the shared light incidence on the device (Karis 2013, "Real Shading in Unreal
// Engine 4", eq. 9-20): distances 0, denormal, 1e-6 .. 1e6 m; sources on the normal, on the horizon
// and below it; sphere radii and tube lengths 0, denormal, 1e-25 .. 1e6 m (far larger than the
// distance too); 0 and 1e9 lm; attenuation radii from 1 um to infinite; point and spot lights.
// Nothing may be NaN, Inf or negative; zero radius and length must give exactly the point light;
// vanishing ones must come within 1e-5 of it.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "check_records.h"
#include "compute_harness.h"
#include "shaders/stability_lights.comp.spv.h"

using namespace candela;
using namespace candela::stability;

namespace {

using Float4 = std::array<float, 4>;

// Axis order of shaders/stability_lights.comp.
enum LightAxis : uint32_t {
    kDistance,
    kDirection,
    kLightParams,
    kView,
    kRoughness,
    kType,
    kRadius,
    kLength,
    kTubeAxis,
    kTinyFraction,
    kAxisCount
};

// Record order of shaders/stability_lights.comp.
enum LightCheck : uint32_t {
    kDiffuseIlluminance,
    kSpecularIlluminance,
    kIncidentIlluminance,
    kDiffuseDirection,
    kSpecularDirection,
    kShadedRadiance,
    kPointBitIdentical,
    kVanishingTube,
    kVanishingSphere,
    kDirectional,
    kCheckCount
};
constexpr std::array<const char*, kCheckCount> kCheckNames = {
    "diffuseIlluminance",     "specularIlluminance",
    "incidentIlluminance",    "|diffuseL|^2",
    "|specularL|^2",          "shadeSurface(DefaultLit)",
    "r=0,len=0 == point",     "len->0 within 1e-5 point",
    "r->0 within 1e-5 point", "directional light"};

const float kDenormal = std::bit_cast<float>(0x00000400u);  // ~1.4e-42
const float kSmallestNormal = std::bit_cast<float>(0x00800000u);
const float kHugeCandela = float(1e9 / (4.0 * std::numbers::pi));  // 1e9 lm point light

Float4 scalar(float x) {
    return {x, 0.0f, 0.0f, 0.0f};
}
Float4 unit(float x, float y, float z) {
    const float n = std::sqrt(x * x + y * y + z * z);
    return {x / n, y / n, z / n, 0.0f};
}

std::array<std::vector<Float4>, kAxisCount> lightAxes() {
    std::array<std::vector<Float4>, kAxisCount> a;
    for (float d : {0.0f, kDenormal, 1e-30f, 1e-6f, 1e-3f, 0.1f, 1.0f, 10.0f, 100.0f, 1e4f, 1e6f}) {
        a[kDistance].push_back(scalar(d));
    }
    a[kDirection] = {unit(0, 0, 1),       unit(1, 0, 0),        unit(0, 0, -1),
                     unit(0.6f, 0, 0.8f), unit(0.8f, 0, -0.6f), unit(0, 1e-7f, 1)};
    // (candela, 1 / attenuation radius): 0 is an infinite radius, 1e6 a 1 um one.
    a[kLightParams] = {{kHugeCandela, 0.0f, 0, 0},
                       {1.0f, 1e-6f, 0, 0},
                       {0.0f, 1.0f, 0, 0},
                       {kDenormal, 1e6f, 0, 0},
                       {kHugeCandela, 1e-3f, 0, 0}};
    a[kView] = {unit(0, 0, 1), unit(1, 0, 0), unit(0.6f, 0, 0.8f), unit(-0.6f, 0, 0.8f)};
    for (float r : {0.0f, 0.5f, 1.0f})
        a[kRoughness].push_back(scalar(r));
    for (float t : {0.0f, 1.0f, 2.0f})
        a[kType].push_back(scalar(t));
    for (float r : {0.0f, kDenormal, 1e-25f, 1e-20f, 1e-6f, 0.01f, 1.0f, 100.0f, 1e6f}) {
        a[kRadius].push_back(scalar(r));
    }
    for (float l : {0.0f, kDenormal, 1e-20f, 1e-6f, 0.01f, 1.0f, 100.0f, 1e4f}) {
        a[kLength].push_back(scalar(l));
    }
    a[kTubeAxis] = {unit(0, 0, 1), unit(1, 0, 0), unit(1, 1, 1)};
    // (fraction of the distance, absolute): sizes that vanish against the distance.
    a[kTinyFraction] = {{1e-9f, 0, 0, 0},
                        {1e-12f, 0, 0, 0},
                        {1e-20f, 0, 0, 0},
                        {0, kSmallestNormal, 0, 0},
                        {0, kDenormal, 0, 0}};
    return a;
}

std::string axisText(const Float4& v, bool vector) {
    std::ostringstream s;
    s.precision(7);
    if (vector) {
        s << "(" << v[0] << ", " << v[1] << ", " << v[2] << ")";
    } else {
        s << v[0];
        if (v[1] != 0.0f) s << " / " << v[1];
    }
    return s.str();
}

}  // namespace

TEST(LightStability, HardInputGridIsFiniteNonNegativeAndReducesToThePointLight) {
    ComputeHarness harness;
    const auto axes = lightAxes();
    std::vector<Float4> flat;
    struct Grid {
        uint32_t offset[kAxisCount];
        uint32_t count[kAxisCount];
    } grid{};
    for (uint32_t a = 0; a < kAxisCount; ++a) {
        grid.offset[a] = uint32_t(flat.size());
        grid.count[a] = uint32_t(axes[a].size());
        flat.insert(flat.end(), axes[a].begin(), axes[a].end());
    }
    uint32_t invocations = 1;
    for (uint32_t a = 0; a < 6; ++a)
        invocations *= grid.count[a];
    const uint64_t perInvocation =
        uint64_t(grid.count[kRadius]) * grid.count[kLength] * grid.count[kTubeAxis];

    render::GpuBuffer records = makeCheckRecords(harness, kCheckCount);
    render::GpuBuffer axisBuffer = harness.upload(std::span<const Float4>(flat));
    render::Pipeline pipeline = harness.pipeline(stability_lights_comp_spv, 2, sizeof(Grid));
    harness.dispatch(pipeline, {&records, &axisBuffer}, &grid, sizeof(grid),
                     (invocations + 63) / 64);

    std::printf("light hard grid: %u configurations x %llu shapes = %llu lights on %s\n",
                invocations, static_cast<unsigned long long>(perInvocation),
                static_cast<unsigned long long>(invocations * perInvocation),
                harness.context().deviceName().c_str());
    const auto results = harness.read<CheckRecord>(records, kCheckCount);
    // Decodes the configuration part of a case index (the first six axes).
    auto configuration = [&](uint32_t index) {
        std::ostringstream s;
        const char* names[6] = {"distance", "direction", "cd/invRadius", "V", "roughness", "type"};
        uint32_t i[6];
        for (int a = 5; a >= 0; --a) {
            i[a] = index % grid.count[a];
            index /= grid.count[a];
        }
        for (int a = 0; a < 6; ++a) {
            s << names[a] << " " << axisText(axes[a][i[a]], a == kDirection || a == kView) << " ";
        }
        return s.str();
    };
    for (uint32_t c = 0; c < kCheckCount; ++c) {
        const CheckRecord& r = results[c];
        printCheck(kCheckNames[c], r);
        EXPECT_GT(r.evaluations, 0u) << kCheckNames[c];
        EXPECT_EQ(r.nanCount, 0u) << kCheckNames[c];
        EXPECT_EQ(r.infCount, 0u) << kCheckNames[c];
        EXPECT_EQ(r.outOfRangeCount, 0u) << kCheckNames[c];
        if (!r.failed()) continue;
        std::ostringstream shape;
        uint32_t index = r.firstFailure;
        if (c <= kShadedRadiance) {
            const uint32_t x = index % grid.count[kTubeAxis];
            index /= grid.count[kTubeAxis];
            const uint32_t l = index % grid.count[kLength];
            index /= grid.count[kLength];
            const uint32_t rr = index % grid.count[kRadius];
            index /= grid.count[kRadius];
            shape << "sourceRadius " << axisText(axes[kRadius][rr], false) << " sourceLength "
                  << axisText(axes[kLength][l], false) << " tubeAxis "
                  << axisText(axes[kTubeAxis][x], true);
        } else if (c == kVanishingTube || c == kVanishingSphere) {
            if (c == kVanishingTube) {
                shape << "tubeAxis "
                      << axisText(axes[kTubeAxis][index % grid.count[kTubeAxis]], true) << " ";
                index /= grid.count[kTubeAxis];
            }
            shape << "size (fraction/absolute) "
                  << axisText(axes[kTinyFraction][index % grid.count[kTinyFraction]], false);
            index /= grid.count[kTinyFraction];
        }
        ADD_FAILURE() << kCheckNames[c] << " first failure: " << configuration(index)
                      << shape.str();
    }
    EXPECT_EQ(results[kDiffuseIlluminance].evaluations, 3 * invocations * perInvocation);
    EXPECT_EQ(results[kPointBitIdentical].evaluations, invocations);
    EXPECT_EQ(harness.validationMessages(), 0u);
}
