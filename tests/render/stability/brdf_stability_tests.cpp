// Hard inputs for the shared BRDF terms and shading models, evaluated on the device: roughness
// 0, 1e-4, denormal and 1; NoV and NoL 0, 1e-7, denormal and 1; N == L; V == -L (degenerate H);
// F0 and colours 0, 1 and denormal; lights of 0 and 1e9 lux. No result may be NaN or Inf or
// negative, reflectances stay within [0, 1].
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <vector>

#include "check_records.h"
#include "compute_harness.h"
#include "shaders/stability_brdf.comp.spv.h"

using namespace candela;
using namespace candela::stability;

namespace {

// Must match MaterialCase in shaders/stability_brdf.comp.
struct BrdfMaterialCase {
    std::array<float, 4> baseColorMetallic;
    std::array<float, 4> customData;
    float specular;
    uint32_t shadingModel;
    float intensity;
    float pad;
};
static_assert(sizeof(BrdfMaterialCase) == 48);

// Record order of shaders/stability_brdf.comp.
enum BrdfCheck : uint32_t {
    kAlpha,
    kD,
    kVisSchlick,
    kVisCorrelated,
    kFresnelSg,
    kFresnelPow5,
    kLambert,
    kEnvBrdf,
    kEnvBrdfNonmetal,
    kSpecularGgx,
    kShadeSurface,
    kBrdfCheckCount
};
constexpr std::array<const char*, kBrdfCheckCount> kCheckNames = {"alphaFromRoughness",
                                                                  "distributionGgx",
                                                                  "visibilitySmithSchlick",
                                                                  "visibilitySmithGgxCorr",
                                                                  "fresnelSchlickSg",
                                                                  "fresnelSchlickPow5",
                                                                  "diffuseLambert",
                                                                  "envBrdfApprox",
                                                                  "envBrdfApproxNonmetal",
                                                                  "specularGgx",
                                                                  "shadeSurface"};

const float kDenormal = std::bit_cast<float>(0x00000400u);  // ~1.4e-42
const float kSmallestNormal = std::bit_cast<float>(0x00800000u);

std::vector<float> roughnessAxis() {
    std::vector<float> r = {0.0f,  kDenormal, kSmallestNormal, 1e-30f, 1e-4f,      0.01f, 0.0199f,
                            0.02f, 0.0201f,   0.05f,           0.99f,  0.9999999f, 1.0f};
    for (int i = 1; i <= 11; ++i)
        r.push_back(float(i) / 12.0f);  // the sweep
    return r;
}

std::vector<float> cosineAxis() {
    // Signed: back-facing views and lights reach shadeSurface, which must cope.
    return {-1.0f, -0.5f, -1e-7f, -0.0f, 0.0f, kDenormal, 1e-30f, 1e-7f,      1e-4f, 1e-3f,
            0.01f, 0.1f,  0.3f,   0.5f,  0.7f, 0.9f,      0.99f,  0.9999999f, 1.0f};
}

// (cos, sin) of the light's azimuth around N, the view being at azimuth 0. (-1, 0) with
// cosLight == -cosView puts L at exactly -V, where H = V + L is the zero vector.
std::vector<std::array<float, 2>> azimuthAxis() {
    return {{1.0f, 0.0f},       {0.0f, 1.0f},        {-1.0f, 0.0f},      {0.0f, -1.0f},
            {0.5f, 0.8660254f}, {-0.8660254f, 0.5f}, {-1.0f, kDenormal}, {1.0f, -1e-7f}};
}

std::vector<BrdfMaterialCase> materials() {
    constexpr float kHugeLux = 1e9f;
    const float d = kDenormal;
    const uint32_t defaultLit = 1, subsurface = 2, legacy = 3, unlit = 0;
    return {
        {{0.5f, 0.5f, 0.5f, 0.0f}, {0, 0, 0, 0}, 0.5f, defaultLit, 1.0f, 0},
        {{1.0f, 1.0f, 1.0f, 1.0f}, {0, 0, 0, 0}, 0.5f, defaultLit, kHugeLux, 0},  // F0 = 1
        {{0.0f, 0.0f, 0.0f, 0.0f}, {0, 0, 0, 0}, 0.0f, defaultLit, kHugeLux, 0},  // F0 = 0
        {{d, d, d, d}, {d, d, d, d}, d, defaultLit, d, 0},                        // denormals
        {{1.0f, 0.0f, 1.0f, 1.0f}, {0, 0, 0, 0}, 0.5f, defaultLit, 1e5f, 0},      // magenta metal
        {{0.8f, 0.6f, 0.4f, 0.0f}, {1.0f, 0.2f, 0.1f, 0.0f}, 0.5f, subsurface, 1e5f, 0},
        {{0.3f, 0.3f, 0.3f, 0.0f}, {1.0f, 0.0f, 1.0f, 0.0f}, 0.5f, legacy, kHugeLux, 0},
        {{1.0f, 1.0f, 1.0f, 0.0f}, {0, 0, 0, 0}, 0.5f, unlit, kHugeLux, 0},
    };
}

}  // namespace

TEST(BrdfStability, HardInputGridIsFiniteNonNegativeAndBounded) {
    ComputeHarness harness;
    const std::vector<float> roughness = roughnessAxis();
    const std::vector<float> cosines = cosineAxis();
    const auto azimuths = azimuthAxis();
    const std::vector<BrdfMaterialCase> mats = materials();

    std::vector<float> axes = roughness;
    axes.insert(axes.end(), cosines.begin(), cosines.end());
    for (const auto& a : azimuths)
        axes.insert(axes.end(), a.begin(), a.end());

    render::GpuBuffer records = makeCheckRecords(harness, kBrdfCheckCount);
    render::GpuBuffer axisBuffer = harness.upload(std::span<const float>(axes));
    render::GpuBuffer materialBuffer = harness.upload(std::span<const BrdfMaterialCase>(mats));
    render::Pipeline pipeline = harness.pipeline(stability_brdf_comp_spv, 3, 16);

    const std::array<uint32_t, 4> grid = {uint32_t(roughness.size()), uint32_t(cosines.size()),
                                          uint32_t(azimuths.size()), uint32_t(mats.size())};
    const uint32_t triples = grid[0] * grid[1] * grid[1];
    harness.dispatch(pipeline, {&records, &axisBuffer, &materialBuffer}, grid.data(), sizeof(grid),
                     (triples + 63) / 64);

    const uint64_t cases = uint64_t(triples) * grid[2] * grid[3];
    std::printf("BRDF hard grid: %llu cases on %s\n", static_cast<unsigned long long>(cases),
                harness.context().deviceName().c_str());
    const auto results = harness.read<CheckRecord>(records, kBrdfCheckCount);
    uint64_t evaluations = 0;
    for (uint32_t c = 0; c < kBrdfCheckCount; ++c) {
        const CheckRecord& r = results[c];
        printCheck(kCheckNames[c], r);
        evaluations += r.evaluations;
        const bool perChannel = c == kFresnelSg || c == kFresnelPow5 || c == kLambert ||
                                c == kEnvBrdf || c == kSpecularGgx || c == kShadeSurface;
        EXPECT_EQ(r.evaluations, cases * (perChannel ? 3 : 1)) << kCheckNames[c];
        EXPECT_EQ(r.nanCount, 0u) << kCheckNames[c];
        EXPECT_EQ(r.infCount, 0u) << kCheckNames[c];
        EXPECT_EQ(r.negativeCount, 0u) << kCheckNames[c];
        EXPECT_EQ(r.outOfRangeCount, 0u) << kCheckNames[c];
        if (r.failed()) {
            // Decode the first failing case so the input can be reproduced.
            const uint32_t m = r.firstFailure % grid[3];
            const uint32_t a = (r.firstFailure / grid[3]) % grid[2];
            const uint32_t triple = r.firstFailure / (grid[3] * grid[2]);
            const uint32_t l = triple % grid[1];
            const uint32_t v = (triple / grid[1]) % grid[1];
            const uint32_t ri = triple / (grid[1] * grid[1]);
            ADD_FAILURE() << kCheckNames[c] << " first failure: roughness " << roughness[ri]
                          << " cosView " << cosines[v] << " cosLight " << cosines[l] << " azimuth ("
                          << azimuths[a][0] << ", " << azimuths[a][1] << ") material " << m;
        }
    }
    std::printf("BRDF hard grid: %llu evaluations\n", static_cast<unsigned long long>(evaluations));
    EXPECT_EQ(harness.validationMessages(), 0u);
}
