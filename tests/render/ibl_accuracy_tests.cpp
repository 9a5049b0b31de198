// Split sum and mobile IBL against eq. 6 integrated per pixel (the reference mode), under two
// real HDR skies from ../shared/assets (issue 6). Slow on lavapipe: labelled `slow`.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <vector>

#include "candela/render/environment.h"
#include "ibl_sphere_rows.h"
#include "ibl_test_support.h"
#include "report/image_difference.h"

using namespace candela::render;
using namespace candela::render::test;
using candela::content::Diagnostics;

// Errors are relative to each sphere's mean reference radiance; render/README.md records the
// table. The skies' suns are clipped to 65504 cd/m^2 in a few texels: the reference integrates
// them exactly, the split sum smears them through fp16 prefiltered mips, which dominates the
// metals' errors.
constexpr uint32_t kReferenceSamples = 2048;

TEST(IblAccuracy, SplitSumAndMobileAgainstReferenceUnderRealSkies) {
    GpuContext& context = sharedContext();
    EnvironmentCacheOptions cache{freshDirectory("accuracy")};
    for (const char* sky : {"env/chinese_garden_1k.exr", "env/qwantani_afternoon_puresky_1k.exr"}) {
        Diagnostics diagnostics;
        std::shared_ptr<const Environment> env =
            Environment::load(context, sharedAsset(sky), diagnostics, cache);
        ASSERT_FALSE(env->stats().fallback) << diagnostics.toString();
        SphereRows rows = sphereRows(env, 288, 128);
        std::map<IblMode, CapturedFrame> images;
        std::map<IblMode, double> lightingMs;
        for (IblMode mode : kIblModes) {
            RendererOptions options;
            options.ibl = mode;
            options.referenceSamples = kReferenceSamples;
            RendererStats stats;
            images[mode] = rows.scene.render(context, options, &stats);
            lightingMs[mode] = stats.lightingMs;
            // CANDELA_IBL_DUMP=dir writes the three images for a look.
            if (const char* dump = std::getenv("CANDELA_IBL_DUMP")) {
                std::string name =
                    std::filesystem::path(sky).stem().string() + "_" + iblModeName(mode) + ".png";
                writeCapture(std::filesystem::path(dump) / name, images[mode]);
            }
        }
        std::printf(
            "\n%s (%ux%u): lighting pass %.2f ms split-sum, %.2f ms mobile, %.1f ms "
            "reference (%u + %u samples per pixel)\n",
            sky, rows.scene.width, rows.scene.height, lightingMs[IblMode::SplitSum],
            lightingMs[IblMode::Mobile], lightingMs[IblMode::Reference], kReferenceSamples,
            kReferenceSamples);
        std::printf(
            "| material | roughness | split-sum RMSE | max | bias | mobile RMSE | max | "
            "bias |\n|---|---|---|---|---|---|---|---|\n");
        // Each sphere's pixels, against the reference's mean radiance there.
        auto perSphere = [&](IblMode mode) {
            std::vector<candela::report::ImageDifference> out;
            for (int i = 0; i < int(rows.centres.size()); ++i) {
                out.push_back(candela::report::imageDifference(
                    images[mode], images[IblMode::Reference],
                    [&](uint32_t x, uint32_t y) { return sphereAtPixel(rows, x, y) == i; }));
            }
            return out;
        };
        auto splitSum = perSphere(IblMode::SplitSum);
        auto mobile = perSphere(IblMode::Mobile);
        for (size_t i = 0; i < rows.centres.size(); ++i) {
            std::printf("| %s | %.1f | %.3f | %.2f | %+.3f | %.3f | %.2f | %+.3f |\n",
                        rows.metallic[i] ? "metal" : "dielectric", rows.roughness[i],
                        splitSum[i].relativeRmse, splitSum[i].relativeMax, splitSum[i].relativeBias,
                        mobile[i].relativeRmse, mobile[i].relativeMax, mobile[i].relativeBias);
            if (rows.roughness[i] == 0.0f && rows.metallic[i]) {
                // A mirror: both read the same texels; only fp16 and the LUT's F round.
                EXPECT_LT(splitSum[i].relativeRmse, 0.01) << sky;
            } else if (!rows.metallic[i]) {
                // Dielectrics: mostly diffuse, where order-2 SH irradiance is close.
                EXPECT_LT(splitSum[i].relativeRmse, 0.25)
                    << sky << " roughness " << rows.roughness[i];
                EXPECT_LT(std::abs(splitSum[i].relativeBias), 0.1) << sky;
            } else {
                // Rough metals: the sun's highlight, a few clipped texels, dominates the RMSE
                // (its peak lands between two prefiltered roughness mips); the energy (bias)
                // stays close. A broken prefilter or LUT misses both by far more.
                EXPECT_LT(splitSum[i].relativeRmse, 2.5)
                    << sky << " roughness " << rows.roughness[i];
                EXPECT_LT(std::abs(splitSum[i].relativeBias), 0.25) << sky;
            }
        }
    }
    EXPECT_EQ(context.validationMessages(), 0u);
}
