// White furnace of the shared specular terms on the device (Karis 2013, "Real Shading in Unreal
// Engine 4", eq. 2-5 with F0 = 1): the directional albedo of D * Vis * F must not exceed 1 for any
// roughness or view angle, and the projected GGX distribution must integrate to 1. The
// energy-conserving BRDF's compensated lobe (height-correlated Smith x
// multipleScatteringCompensation, E_ss from the engine's LUT and from Karis 2014's ("Physically
// Based Shading on Mobile") fit) must not exceed 1 for any F0 either, and must reach ~1 for F0 = 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "check_records.h"
#include "compute_harness.h"
#include "ibl/environment_brdf_lut.h"
#include "shaders/stability_furnace.comp.spv.h"

using namespace candela;
using namespace candela::stability;

namespace {

struct FurnaceCell {
    float albedoSchlick;
    float albedoCorrelated;
    float projectedNdf;
    float alpha;
};

const std::vector<float> kRoughness = {0.0f,  1e-4f, 0.02f, 0.03f, 0.05f, 0.075f, 0.1f,
                                       0.15f, 0.2f,  0.25f, 0.3f,  0.4f,  0.5f,   0.6f,
                                       0.7f,  0.8f,  0.9f,  0.95f, 1.0f};
const std::vector<float> kNoV = {0.0f, 1e-7f, 1e-4f, 1e-3f, 0.01f, 0.05f, 0.1f,  0.2f, 0.3f,
                                 0.4f, 0.5f,  0.6f,  0.7f,  0.8f,  0.9f,  0.99f, 1.0f};
constexpr uint32_t kSamples = 8192;
constexpr uint32_t kQuadrature = 4096;

// Must match kF0 in stability_furnace.comp.
const std::vector<float> kF0 = {0.01f, 0.02f, 0.04f, 0.25f, 0.5f, 1.0f};

// E_ss = scale + bias of the LUT's height-correlated pair at (NoV, roughness), bilinear on its
// grid (texel x at NoV = (x / (n - 1))^2, y at roughness y / (n - 1): ibl.glsl
// correlatedLutCoordinates), as the lighting pass's sampler reads it.
float lutDirectionalAlbedo(const render::EnvironmentBrdfLut& lut, float NoV, float roughness) {
    const int n = int(render::EnvironmentBrdfLut::kSize);
    auto albedoAt = [&](int x, int y) {
        const uint32_t packed = lut.packedCorrelated(uint32_t(y * n + x));
        return float(double((packed & 0xFFFFu) + (packed >> 16)) / 65535.0);
    };
    const float u = std::clamp(std::sqrt(NoV) * float(n - 1), 0.0f, float(n - 1));
    const float v = std::clamp(roughness * float(n - 1), 0.0f, float(n - 1));
    const int x0 = int(u), y0 = int(v);
    const int x1 = std::min(x0 + 1, n - 1), y1 = std::min(y0 + 1, n - 1);
    const float fx = u - float(x0), fy = v - float(y0);
    const float top = albedoAt(x0, y0) * (1.0f - fx) + albedoAt(x1, y0) * fx;
    const float bottom = albedoAt(x0, y1) * (1.0f - fx) + albedoAt(x1, y1) * fx;
    return top * (1.0f - fy) + bottom * fy;
}

struct FurnaceRun {
    std::vector<FurnaceCell> cells;
    std::vector<std::array<float, 2>> compensated;  // per cell and F0: E_ss from LUT, from fit
    CheckRecord samples;
    uint32_t validationMessages;
};

FurnaceRun runFurnace() {
    ComputeHarness harness;
    std::vector<float> axes = kRoughness;
    axes.insert(axes.end(), kNoV.begin(), kNoV.end());
    {
        const render::EnvironmentBrdfLut lut(harness.context());
        for (float roughness : kRoughness) {
            for (float NoV : kNoV)
                axes.push_back(lutDirectionalAlbedo(lut, NoV, roughness));
        }
    }
    const uint32_t cellCount = uint32_t(kRoughness.size() * kNoV.size());
    render::GpuBuffer records = makeCheckRecords(harness, 1);
    render::GpuBuffer axisBuffer = harness.upload(std::span<const float>(axes));
    render::GpuBuffer cells = harness.buffer(cellCount * sizeof(FurnaceCell));
    render::GpuBuffer compensated = harness.buffer(cellCount * kF0.size() * sizeof(float) * 2);
    render::Pipeline pipeline = harness.pipeline(stability_furnace_comp_spv, 4, 16);
    const std::array<uint32_t, 4> grid = {uint32_t(kRoughness.size()), uint32_t(kNoV.size()),
                                          kSamples, kQuadrature};
    harness.dispatch(pipeline, {&records, &axisBuffer, &cells, &compensated}, grid.data(),
                     sizeof(grid), cellCount);
    return {harness.read<FurnaceCell>(cells, cellCount),
            harness.read<std::array<float, 2>>(compensated, cellCount * kF0.size()),
            harness.read<CheckRecord>(records, 1)[0], harness.validationMessages()};
}

const FurnaceRun& furnace() {
    static const FurnaceRun run = runFurnace();
    return run;
}

const FurnaceCell& cell(size_t r, size_t v) {
    return furnace().cells[r * kNoV.size() + v];
}

}  // namespace

TEST(WhiteFurnace, EverySampleIsFiniteAndNonNegative) {
    const CheckRecord& s = furnace().samples;
    printCheck("furnace integrands", s);
    EXPECT_EQ(s.evaluations, kRoughness.size() * kNoV.size() * (2 * kSamples + kQuadrature));
    EXPECT_EQ(s.nanCount, 0u);
    EXPECT_EQ(s.infCount, 0u);
    EXPECT_EQ(s.negativeCount, 0u);
    EXPECT_EQ(furnace().validationMessages, 0u);
}

// Energy conservation: albedo <= 1 + epsilon. Epsilon covers the quasi-Monte Carlo error of
// 8192 visible-normal-sampled Hammersley directions (the estimator G2 / G1 is bounded by 1, so
// the error is well under 1e-3) and fp32 rounding.
TEST(WhiteFurnace, SpecularAlbedoNeverExceedsOne) {
    EXPECT_EQ(furnace().validationMessages, 0u);
    constexpr float kEpsilon = 2e-3f;
    std::printf("specular albedo, F0 = 1, max over NoV (visibilitySmithSchlick | correlated)\n");
    std::printf("roughness   Schlick   at NoV  correlated  at NoV   at NoV=1 (S | C)\n");
    for (size_t r = 0; r < kRoughness.size(); ++r) {
        float maxSchlick = 0.0f, maxCorrelated = 0.0f;
        size_t atSchlick = 0, atCorrelated = 0;
        for (size_t v = 0; v < kNoV.size(); ++v) {
            const FurnaceCell& c = cell(r, v);
            if (c.albedoSchlick > maxSchlick) maxSchlick = c.albedoSchlick, atSchlick = v;
            if (c.albedoCorrelated > maxCorrelated) {
                maxCorrelated = c.albedoCorrelated, atCorrelated = v;
            }
        }
        const FurnaceCell& normal = cell(r, kNoV.size() - 1);
        std::printf("%9.4g  %8.5f  %7.2g  %10.5f  %6.2g   %.5f | %.5f\n", double(kRoughness[r]),
                    double(maxSchlick), double(kNoV[atSchlick]), double(maxCorrelated),
                    double(kNoV[atCorrelated]), double(normal.albedoSchlick),
                    double(normal.albedoCorrelated));
        EXPECT_LE(maxSchlick, 1.0f + kEpsilon) << "roughness " << kRoughness[r];
        EXPECT_LE(maxCorrelated, 1.0f + kEpsilon) << "roughness " << kRoughness[r];
    }
}

// eq. 3 is normalised so that the projected microfacet area is the macro surface:
// integral of D(h) (n.h) dh = 1. Evaluated by a 4096-point midpoint rule in ln(tan^2), whose
// own error is ~1e-7, at NoH correct to an ulp, so what remains is the fp32 behaviour of D.
// The lobe lives within ~a2 / 2 of NoH = 1, where floats are 2^-24 apart: at kMinRoughness
// (a2 = 1.6e-7) that is ~1.3 representable NoH values, so no fp32 evaluation of D(NoH) can
// integrate correctly there (measured: -4.2% at 0.02, -2.6% at 0.03, -0.14% at 0.05; and +41%
// at 0.02 when NoH is formed as 1 / sqrt(1 + tan^2) in fp32, as a shading dot product would).
// Held to 1e-3 from roughness 0.075 (~260 NoH values across the lobe), to 5% below.
TEST(WhiteFurnace, ProjectedGgxIntegratesToOne) {
    EXPECT_EQ(furnace().validationMessages, 0u);
    std::printf("roughness  alpha      integral of D NoH\n");
    for (size_t r = 0; r < kRoughness.size(); ++r) {
        const FurnaceCell& c = cell(r, 0);
        std::printf("%9.4g  %.3e  %.7f\n", double(kRoughness[r]), double(c.alpha),
                    double(c.projectedNdf));
        const float tolerance = kRoughness[r] >= 0.075f ? 1e-3f : 0.05f;
        EXPECT_NEAR(c.projectedNdf, 1.0f, tolerance) << "roughness " << kRoughness[r];
    }
}

// Issue 26: "no material reflects more than it receives (+2e-3)". The energy-conserving lobe,
// single-scattering albedo x (1 + F0 (1 / E_ss - 1)), over the whole grid and F0 from 0.01
// (under the 2% rule) to 1, with E_ss as the renderer reads it for lights: the LUT's height-
// correlated scale + bias. For F0 = 1 it must also give back the lost energy: 0.95 to 1.01
// from roughness 0.25 on (NoV >= 0.1). Printed only: the same with Karis 2014's fit as E_ss,
// which overshoots (why the mobile path's lights read the LUT too).
TEST(WhiteFurnace, CompensatedLobeNeverExceedsOneAndRestoresRoughMetals) {
    EXPECT_EQ(furnace().validationMessages, 0u);
    constexpr float kEpsilon = 2e-3f;
    std::printf(
        "compensated specular albedo, max over NoV and F0 (E_ss from LUT | fit); "
        "F0 = 1 at NoV = 1 (single -> compensated)\n");
    for (size_t r = 0; r < kRoughness.size(); ++r) {
        float maxLut = 0.0f, maxFit = 0.0f;
        for (size_t v = 0; v < kNoV.size(); ++v) {
            for (size_t k = 0; k < kF0.size(); ++k) {
                const std::array<float, 2>& c =
                    furnace().compensated[(r * kNoV.size() + v) * kF0.size() + k];
                maxLut = std::max(maxLut, c[0]);
                maxFit = std::max(maxFit, c[1]);
                EXPECT_LE(c[0], 1.0f + kEpsilon) << "LUT E_ss, roughness " << kRoughness[r]
                                                 << " NoV " << kNoV[v] << " F0 " << kF0[k];
                if (kF0[k] == 1.0f && kRoughness[r] >= 0.25f && kNoV[v] >= 0.1f) {
                    EXPECT_GE(c[0], 0.95f) << "roughness " << kRoughness[r] << " NoV " << kNoV[v];
                    EXPECT_LE(c[0], 1.01f) << "roughness " << kRoughness[r] << " NoV " << kNoV[v];
                }
            }
        }
        const size_t normal = r * kNoV.size() + kNoV.size() - 1;
        std::printf("roughness %6.4g  max %.5f | %.5f   F0 = 1, NoV = 1: %.4f -> %.4f | %.4f\n",
                    double(kRoughness[r]), double(maxLut), double(maxFit),
                    double(furnace().cells[normal].albedoCorrelated),
                    double(furnace().compensated[normal * kF0.size() + kF0.size() - 1][0]),
                    double(furnace().compensated[normal * kF0.size() + kF0.size() - 1][1]));
    }
}
