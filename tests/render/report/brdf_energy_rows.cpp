// Rows and a table for the energy-conserving BRDF (issue 26): the energy a white metal sphere
// loses in a white furnace by roughness, with and without multiple-scattering compensation, in
// every image-based lighting mode (the whole renderer: G-buffer, LUT or fit, lighting pass);
// and what the compensation costs, as lighting-pass time of the same frames with `--brdf ue4`
// and `--brdf energy-conserving`, alternated in this process.
#include <algorithm>
#include <cstdio>
#include <random>
#include <string>

#include "../test_scene.h"
#include "candela/content/procedural_mesh.h"
#include "candela/content/render_setting_table.h"
#include "candela/render/environment.h"
#include "ibl/environment_brdf_lut.h"
#include "median.h"
#include "report_context.h"
#include "shader_values.h"

namespace candela::report {

using namespace candela::render;
using namespace candela::render::test;

namespace {

content::Material whiteMetal(float roughness) {
    content::Material m;
    m.baseColorFactor = {1.0f, 1.0f, 1.0f, 1.0f};
    m.metallicFactor = 1.0f;
    m.roughnessFactor = roughness;
    return m;
}

// A unit sphere seen from 3 m in a uniform sky of radiance 1: the mean of the centre 16x16
// pixels is the share of the sky the sphere reflects toward the camera (NoV 0.87 to 1).
double furnaceMean(GpuContext& gpu, std::shared_ptr<const Environment> sky, float roughness,
                   const RendererOptions& options) {
    TestScene scene;
    scene.width = 64;
    scene.height = 64;
    scene.add(content::makeSphere(1.0f, 96, 48), whiteMetal(roughness));
    scene.lookAt({0.0f, 0.0f, 3.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
    scene.environment = std::move(sky);
    CapturedFrame frame = scene.render(gpu, options);
    double sum = 0.0;
    for (uint32_t y = 24; y < 40; ++y) {
        for (uint32_t x = 24; x < 40; ++x) {
            for (int c = 0; c < 3; ++c)
                sum += hdrPixel(frame, x, y)[c];
        }
    }
    return sum / (16.0 * 16.0 * 3.0);
}

// Dielectric and metal spheres of roughness 0.1..1 under 64 rough point lights and a sky:
// the lighting pass's work per pixel is what the compensation adds to.
TestScene costScene(std::shared_ptr<const Environment> sky, uint32_t width, uint32_t height) {
    TestScene scene;
    scene.width = width;
    scene.height = height;
    for (int i = 0; i < 10; ++i) {
        content::Material m = whiteMetal(0.1f + 0.1f * float(i));
        m.metallicFactor = i % 2 ? 1.0f : 0.0f;
        m.baseColorFactor = {0.9f, 0.6f, 0.3f, 1.0f};
        scene.add(content::makeSphere(0.45f, 48, 24), m,
                  glm::translate(glm::mat4(1.0f), glm::vec3(-4.5f + float(i), 0.0f, 0.0f)));
    }
    scene.lookAt({0.0f, 0.0f, 6.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
    std::mt19937 rng{26};
    std::uniform_real_distribution<float> x(-6.0f, 6.0f), y(-2.0f, 2.0f), z(-1.0f, 3.0f);
    for (int i = 0; i < 64; ++i)
        scene.lights.push_back(pointLight({x(rng), y(rng), z(rng)}, 2000.0f, 8.0f));
    scene.environment = std::move(sky);
    return scene;
}

}  // namespace

void addBrdfEnergyRows(ReportContext& context) {
    const bool quick = context.budget.quick;
    GpuContext& gpu = context.harness.context();
    std::shared_ptr<const Environment> sky = Environment::uniform(gpu, 1.0f);
    const float roughnesses[] = {0.25f, 0.5f, 0.75f, 1.0f};
    const IblMode modes[] = {IblMode::SplitSum, IblMode::Mobile, IblMode::Reference};

    ReportTable table;
    table.title = "Energy a white metal loses in a white furnace, by roughness";
    table.intro =
        "A white metal sphere (F0 = 1) in a uniform sky of radiance 1, rendered by the whole "
        "renderer; mean of the centre 16x16 pixels (NoV 0.87..1), energy lost = 1 - mean. "
        "`ue4`: Karis 2013's (\"Real Shading in Unreal Engine 4\") single-scattering GGX with "
        "Schlick-Smith; `energy-conserving`: "
        "height-correlated Smith, multiple scattering by Fdez-Aguera 2019 (E_ss from the LUT; on "
        "the mobile path from EnvBRDFApprox's own scale + bias, the analytic equivalent). The "
        "reference mode integrates single scattering per pixel and adds the same multiple-"
        "scattering term.";
    table.header = {"mode", "BRDF"};
    for (float r : roughnesses)
        table.header.push_back("roughness " + formatNumber(r));
    double worstCompensated = 0.0, worstUncompensated = 0.0, mobileVsLut = 0.0;
    std::string worstAt;
    std::vector<double> splitSumCompensated;
    for (IblMode mode : modes) {
        for (BrdfModel brdf : {BrdfModel::Ue4, BrdfModel::EnergyConserving}) {
            RendererOptions options;
            options.ibl = mode;
            options.brdf = brdf;
            options.referenceSamples = quick ? 64 : 1024;
            std::vector<std::string> row = {iblModeName(mode),
                                            candela::content::renderSettingName(brdf).c_str()};
            for (size_t i = 0; i < std::size(roughnesses); ++i) {
                const double mean = furnaceMean(gpu, sky, roughnesses[i], options);
                row.push_back(formatNumber(100.0 * (1.0 - mean), 3) + " %");
                const double lost = std::abs(1.0 - mean);
                if (brdf == BrdfModel::EnergyConserving) {
                    if (mode == IblMode::SplitSum) splitSumCompensated.push_back(mean);
                    if (mode == IblMode::Mobile) {
                        mobileVsLut =
                            std::max(mobileVsLut, std::abs(mean - splitSumCompensated[i]));
                    }
                    if (lost > worstCompensated) {
                        worstCompensated = lost;
                        worstAt = std::string(iblModeName(mode)) + ", roughness " +
                                  formatNumber(roughnesses[i]);
                    }
                } else if (mode == IblMode::SplitSum) {
                    worstUncompensated = std::max(worstUncompensated, lost);
                }
            }
            table.rows.push_back(row);
        }
    }
    context.report.tables.push_back(table);

    // Cost: the same frames with and without the compensation (and with Schlick-Smith or
    // height-correlated Smith), alternated so load on the machine hits both alike.
    const uint32_t width = quick ? 96 : 320, height = quick ? 32 : 96;
    const uint32_t repetitions = quick ? 1 : 7;
    TestScene scene = costScene(sky, width, height);
    std::vector<double> ue4Ms, conservingMs;
    for (uint32_t r = 0; r < repetitions; ++r) {
        for (BrdfModel brdf : {BrdfModel::Ue4, BrdfModel::EnergyConserving}) {
            RendererOptions options;
            options.brdf = brdf;
            RendererStats stats;
            scene.render(gpu, options, &stats, 2);
            (brdf == BrdfModel::Ue4 ? ue4Ms : conservingMs).push_back(stats.lightingMs);
        }
    }
    const uint32_t iterations = context.budget.iterations(16384);
    const std::vector<Cost> factor =
        context.cost.nsPerEvaluation({{CostFunction::MultipleScattering, iterations}});

    char metric[240];
    std::snprintf(metric, sizeof(metric),
                  "max |1 - reflected| of a white metal sphere in a white furnace, roughness "
                  "0.25..1, split sum, mobile and reference (table below); %s without "
                  "compensation (split sum, `--brdf ue4`)",
                  (formatNumber(100.0 * worstUncompensated, 3) + " %").c_str());
    char cost[320];
    std::snprintf(cost, sizeof(cost),
                  "lighting pass, 10 spheres, 64 point lights + sky, %ux%u: %s (energy-"
                  "conserving vs `ue4`, medians of %u alternated frames); the per-light factor "
                  "1 + F0 (1 / E_ss - 1): %s",
                  width, height, formatCost(median(conservingMs), median(ue4Ms), "ms").c_str(),
                  repetitions, formatShaderCost(factor[0]).c_str());
    context.report.rows.push_back(
        {"Multiple-scattering compensation (`--brdf energy-conserving`): Fdez-Aguera 2019 for "
         "IBL, 1 + F0 (1 / E_ss - 1) for lights, E_ss from the LUT",
         "a white furnace (reflects 1)", metric, 100.0 * worstCompensated, "% energy", worstAt,
         cost});
    // The mobile path's analytic E_ss (EnvBRDFApprox at F0 = 1, on the device) against the
    // LUT's height-correlated E_ss, over the LUT's own grid points.
    const render::EnvironmentBrdfLut lut(gpu);
    const uint32_t n = render::EnvironmentBrdfLut::kSize;
    std::vector<ValueSample> samples;
    std::vector<double> lutAlbedo;
    for (uint32_t y = 0; y < n; y += quick ? 16 : 2) {
        for (uint32_t x = 1; x < n; x += quick ? 16 : 2) {
            const double u = double(x) / (n - 1);
            const float roughness = float(double(y) / (n - 1)), NoV = float(u * u);
            if (NoV < 0.02f) continue;
            samples.push_back({{roughness, NoV, 1.0f, 0.0f}});
            const uint32_t packed = lut.packedCorrelated(y * n + x);
            lutAlbedo.push_back(double((packed & 0xFFFFu) + (packed >> 16)) / 65535.0);
        }
    }
    const auto fit = evaluateOnDevice(context.harness, ValueFunction::EnvBrdfApprox, samples);
    double worstFit = 0.0, sumFit = 0.0;
    std::string worstFitAt;
    for (size_t i = 0; i < samples.size(); ++i) {
        const double e = double(fit[i][0]) - lutAlbedo[i];
        sumFit += e;
        if (std::abs(e) > std::abs(worstFit)) {
            worstFit = e;
            worstFitAt = "roughness " + formatNumber(samples[i].a[0]) + ", NoV " +
                         formatNumber(samples[i].a[1]);
        }
    }
    char mobileMetric[320];
    std::snprintf(mobileMetric, sizeof(mobileMetric),
                  "max |E_fit - E_lut| over %zu LUT texels (roughness 0..1 x NoV 0.02..1), E_fit "
                  "= EnvBRDFApprox(F0 = 1) on the device, signed %+.3f, mean %+.3f; in the "
                  "furnace the mobile sphere reflects %.2g off the split sum's (table below)",
                  samples.size(), worstFit, sumFit / double(samples.size()), mobileVsLut);
    context.report.rows.push_back(
        {"Mobile IBL multiple scattering: E_ss = EnvBRDFApprox's scale + bias (analytic, no LUT "
         "read); lights read the LUT",
         "the LUT's height-correlated E_ss", mobileMetric, std::abs(worstFit), "abs", worstFitAt,
         "no texture read for the sky's term; the same per-light factor"});
}

}  // namespace candela::report
