// Rows: Fresnel with the spherical-Gaussian exponent (eq. 5) against pow5 Schlick, Schlick-
// Smith visibility (eq. 4, k = alpha / 2) against exact height-correlated Smith GGX; and the
// note on kMinRoughness: how much of GGX's projected area fp32 keeps near the clamp.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "../stability/brdf_reference.h"
#include "report_context.h"
#include "shader_values.h"

namespace candela::report {

namespace ref = stability::reference;

namespace {

constexpr double kPi = std::numbers::pi;

void addFresnelRow(ReportContext& context, const Cost& costSg, const Cost& costPow5) {
    const float f0s[] = {0.02f, 0.04f, 0.1f, 0.5f, 0.95f, 1.0f};
    const int steps = context.budget.quick ? 64 : 4096;
    std::vector<ValueSample> samples;
    for (float f0 : f0s) {
        for (int i = 0; i <= steps; ++i)
            samples.push_back({{float(i) / float(steps), f0, 0, 0}});
    }
    auto values = evaluateOnDevice(context.harness, ValueFunction::Fresnel, samples);
    double worst = -1.0;
    std::string where;
    for (size_t i = 0; i < samples.size(); ++i) {
        const float VoH = samples[i].a[0], f0 = samples[i].a[1];
        double e = std::fabs(values[i][0] - ref::fresnelSchlickPow5(f0, f0, VoH));
        if (!(e <= worst)) {
            worst = e;
            char text[96];
            std::snprintf(text, sizeof(text), "VoH %.3f, F0 %.2f", double(VoH), double(f0));
            where = text;
        }
    }
    char metric[160];
    std::snprintf(metric, sizeof(metric),
                  "max abs, device fp32 vs double pow5 (VoH 0..1 in %d steps x F0 {0.02, 0.04, "
                  "0.1, 0.5, 0.95, 1})",
                  steps);
    context.report.rows.push_back(
        {"Fresnel: Schlick with SG exponent exp2((-5.55473 VoH - 6.98316) "
         "VoH) (eq. 5)",
         "Schlick (1 - VoH)^5", metric, worst, "abs", where, formatShaderCost(costSg, costPow5),
         plottedNs(costSg)});
}

// `function` evaluates (approximation, exact height-correlated Smith) on the device. Returns
// the worst relative error.
double addVisibilityRow(ReportContext& context, ValueFunction function, const char* name,
                        const Cost& costApproximation, const Cost& costSmith) {
    const int roughnessSteps = context.budget.quick ? 8 : 50;
    const int angleSteps = context.budget.quick ? 16 : 128;
    std::vector<ValueSample> samples;
    for (int r = 0; r <= roughnessSteps; ++r) {
        double roughness = ref::kMinRoughness + (1.0 - ref::kMinRoughness) * r / roughnessSteps;
        float alpha = float(ref::alphaFromRoughness(roughness));
        for (int v = 0; v < angleSteps; ++v) {
            for (int l = 0; l < angleSteps; ++l) {
                // NoV, NoL over [0.01, 1]: grazing 0.01 is where the two differ most.
                float NoV = float(0.01 + 0.99 * v / (angleSteps - 1));
                float NoL = float(0.01 + 0.99 * l / (angleSteps - 1));
                samples.push_back({{alpha, NoV, NoL, float(roughness)}});
            }
        }
    }
    auto values = evaluateOnDevice(context.harness, function, samples);
    double worst = -1.0, worstMid = -1.0;
    std::string where;
    for (size_t i = 0; i < samples.size(); ++i) {
        const auto& a = samples[i].a;
        double exact = ref::smithGgxCorrelatedVisibility(a[0], a[1], a[2]);
        double e = std::fabs(values[i][0] - exact) / exact;
        if (a[1] >= 0.2f && a[2] >= 0.2f) worstMid = std::max(worstMid, e);
        if (!(e <= worst)) {
            worst = e;
            char text[128];
            std::snprintf(text, sizeof(text), "roughness %.2f, NoV %.2f, NoL %.2f", double(a[3]),
                          double(a[1]), double(a[2]));
            where = text;
        }
    }
    char metric[200];
    std::snprintf(metric, sizeof(metric),
                  "max rel, device fp32 vs double exact (roughness 0.02..1 in %d steps x NoV, "
                  "NoL 0.01..1 in %d steps each); %s with NoV, NoL >= 0.2",
                  roughnessSteps, angleSteps, formatNumber(worstMid).c_str());
    context.report.rows.push_back({name, "height-correlated Smith GGX (exact)", metric, worst,
                                   "rel", where, formatShaderCost(costApproximation, costSmith),
                                   plottedNs(costApproximation)});
    return worst;
}

// Projected area of D: the integral of D(h) NoH over the hemisphere is 1 for any alpha. With
// NoH rounded to fp32 (as the shader gets it), angles under ~sqrt(2 * 2^-24) = 3.5e-4 rad all
// read NoH = 1: at roughness 0.02 (alpha 4e-4) that is most of the peak.
void addGgxNote(ReportContext& context) {
    ReportTable table;
    table.title = "GGX peak in fp32 near kMinRoughness";
    table.intro =
        "Projected area of GGX, integral of D(NoH) NoH over the hemisphere (exactly 1), with D "
        "evaluated by the device's distributionGgx at NoH = cos(theta) rounded to fp32, against "
        "the same integral with D in double. fp32 NoH cannot resolve angles under ~3.5e-4 rad "
        "(1 - 2^-24 is the largest float under 1), so the narrowest lobes lose part of their "
        "peak. brdf.glsl clamps roughness to kMinRoughness = 0.02 for analytic lights; it is "
        "left there (changing it changes every golden image): the loss is confined to mirror-"
        "like surfaces under point lights.";
    table.header = {"roughness", "alpha", "fp32 D integral", "double D integral", "energy lost"};
    double lostAtClamp = 0.0;
    for (double roughness : {0.02, 0.03, 0.05, 0.1}) {
        const float r = float(roughness);
        const float alpha = r * r;
        const float a2 = alpha * alpha;
        // Trapezoid over theta with steps of alpha / 400 up to 60 alpha, then 1e-4 to pi / 2.
        std::vector<double> thetas;
        const double fine = double(alpha) / (context.budget.quick ? 50.0 : 400.0);
        for (double t = 0.0; t < 60.0 * alpha; t += fine)
            thetas.push_back(t);
        for (double t = 60.0 * alpha; t < kPi / 2; t += context.budget.quick ? 1e-3 : 1e-4)
            thetas.push_back(t);
        thetas.push_back(kPi / 2);
        std::vector<ValueSample> samples;
        for (double t : thetas)
            samples.push_back({{a2, float(std::cos(t)), 0, 0}});
        auto values = evaluateOnDevice(context.harness, ValueFunction::Ggx, samples);
        double fp32 = 0.0, exact = 0.0;
        for (size_t i = 0; i + 1 < thetas.size(); ++i) {
            auto weight = [&](size_t k) {
                return 2.0 * kPi * std::sin(thetas[k]) * std::cos(thetas[k]);
            };
            double h = thetas[i + 1] - thetas[i];
            fp32 += 0.5 * h * (values[i][0] * weight(i) + values[i + 1][0] * weight(i + 1));
            exact += 0.5 * h *
                     (ref::ggxDistribution(alpha, std::cos(thetas[i])) * weight(i) +
                      ref::ggxDistribution(alpha, std::cos(thetas[i + 1])) * weight(i + 1));
        }
        if (roughness == ref::kMinRoughness) lostAtClamp = 1.0 - fp32 / exact;
        table.rows.push_back({formatNumber(roughness), formatNumber(alpha), formatNumber(fp32, 4),
                              formatNumber(exact, 4),
                              formatNumber(100.0 * (1.0 - fp32 / exact), 3) + " %"});
    }
    context.report.tables.push_back(table);
    context.report.rows.push_back(
        {"GGX D (eq. 3) in fp32 at kMinRoughness = 0.02", "the same D in double",
         "share of the projected area (integral of D NoH, 1 exactly) lost to fp32 NoH, see "
         "the table below",
         100.0 * lostAtClamp, "% energy", "the peak, theta < ~3.5e-4 rad (NoH rounds to 1)",
         "same function"});
    const float r = float(ref::kMinRoughness);
    const double peak = 1.0 / (kPi * double(r * r) * double(r * r));
    context.report.notes.push_back(
        "fp16: at kMinRoughness D peaks at 1 / (pi alpha^2) = " + formatNumber(peak) +
        ", finite in fp32 but above half precision's largest value 65,504; in fp16 D is Inf up "
        "to roughness 0.125 and Vis (Schlick) up to 0.0625: see "
        "tests/render/stability/FP16_REPORT.md (regenerated by render_stability_tests). "
        "Candela's shaders evaluate the BRDF in fp32.");
}

}  // namespace

void addBrdfRows(ReportContext& context) {
    const uint32_t iterations = context.budget.iterations(16384);
    std::vector<Cost> ns = context.cost.nsPerEvaluation({
        {CostFunction::FresnelSg, iterations},
        {CostFunction::FresnelPow5, iterations},
        {CostFunction::VisSchlick, iterations},
        {CostFunction::VisSmithGgx, iterations},
        {CostFunction::VisSmithGgxFast, iterations},
    });
    addFresnelRow(context, ns[0], ns[1]);
    context.report.notes.push_back(
        "Fresnel: llvmpipe evaluates exp2 as a polynomial in SIMD code, so eq. 5's exp2 form is "
        "not cheaper than pow5's four multiplications on this device; the SG exponent was "
        "chosen for GPUs, where exp2 is a single special-function instruction. The error "
        "column shows what it costs in accuracy.");
    const double schlick =
        addVisibilityRow(context, ValueFunction::Visibility,
                         "Vis: Schlick-Smith, k = alpha / 2 (eq. 4; `--brdf ue4`)", ns[2], ns[3]);
    const double hammon = addVisibilityRow(
        context, ValueFunction::VisibilityFast,
        "Vis: height-correlated Smith, Hammon's linear form (Filament's fast Vis)", ns[4], ns[3]);
    context.report.notes.push_back(
        "Visibility for the energy-conserving BRDF (`--brdf energy-conserving`, the default): "
        "the exact height-correlated Smith term, the reference of both Vis rows. Schlick-Smith "
        "is off it by up to " +
        formatNumber(100.0 * schlick) + "% and Hammon's linear form by up to " +
        formatNumber(100.0 * hammon) +
        "%; the exact term costs two square roots per light (cost column), and the LUT's "
        "height-correlated pair and the multiple-scattering compensation are integrated with "
        "it, so direct and image-based light agree. `--brdf ue4` keeps Schlick-Smith.");
    addGgxNote(context);
}

}  // namespace candela::report
