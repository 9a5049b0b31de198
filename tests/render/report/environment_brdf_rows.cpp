// Rows: the environment BRDF (eq. 8) three ways: Karis 2014's ("Physically Based Shading on
// Mobile") analytic fit (EnvBRDFApprox, mobile), the 128^2 LUT read bilinearly (split sum), and
// Monte Carlo at run time, each against eq. 8 integrated in double precision.
#include <cmath>
#include <cstdio>
#include <string>

#include "environment_brdf_reference.h"
#include "report_context.h"
#include "shader_values.h"

namespace candela::report {

namespace {

struct Worst {
    double error = -1.0;
    std::string where;
    void add(double e, double roughness, double NoV, double f0) {
        if (e <= error) return;
        error = e;
        char text[96];
        std::snprintf(text, sizeof(text), "roughness %.3f, NoV %.3f, F0 %.2f", roughness, NoV, f0);
        where = text;
    }
};

// Bilinear with clamp-to-edge between texel centres, as the lighting pass's linear sampler.
std::pair<double, double> lutBilinear(const std::vector<float>& lut, uint32_t size,
                                      double roughness, double NoV) {
    auto coordinate = [size](double u) {
        return std::clamp(u * size - 0.5, 0.0, double(size - 1));
    };
    double px = coordinate(NoV), py = coordinate(roughness);
    uint32_t x0 = uint32_t(px), y0 = uint32_t(py);
    uint32_t x1 = std::min(x0 + 1, size - 1), y1 = std::min(y0 + 1, size - 1);
    double fx = px - x0, fy = py - y0;
    auto at = [&](uint32_t x, uint32_t y, int c) { return double(lut[(y * size + x) * 2 + c]); };
    auto channel = [&](int c) {
        double top = at(x0, y0, c) * (1 - fx) + at(x1, y0, c) * fx;
        double bottom = at(x0, y1, c) * (1 - fx) + at(x1, y1, c) * fx;
        return top * (1 - fy) + bottom * fy;
    };
    return {channel(0), channel(1)};
}

}  // namespace

void addEnvironmentBrdfRows(ReportContext& context, const std::vector<float>& lut,
                            uint32_t lutSize) {
    const bool quick = context.budget.quick;
    const int steps = quick ? 4 : 24;
    const int referenceGrid = quick ? 64 : 384;
    const uint32_t monteCarloSamples = 64;
    const float f0s[] = {0.04f, 1.0f};
    // Grid points off the LUT's texel centres (where interpolation error is largest):
    // roughness 0..1, NoV 0.02..1.
    std::vector<ValueSample> samples;
    for (int r = 0; r <= steps; ++r) {
        for (int v = 0; v <= steps; ++v) {
            for (float f0 : f0s) {
                float roughness = float(r) / float(steps);
                float NoV = float(0.02 + 0.98 * v / steps);
                samples.push_back({{roughness, NoV, f0, float(monteCarloSamples)}});
            }
        }
    }
    auto approx = evaluateOnDevice(context.harness, ValueFunction::EnvBrdfApprox, samples);
    auto monteCarlo = evaluateOnDevice(context.harness, ValueFunction::EnvBrdfMonteCarlo, samples);
    Worst approxWorst, lutWorst, monteCarloWorst;
    for (size_t i = 0; i < samples.size(); i += 2) {
        const double roughness = samples[i].a[0], NoV = samples[i].a[1];
        const auto [a, b] = environmentBrdfReference(roughness, NoV, referenceGrid);
        const auto [la, lb] = lutBilinear(lut, lutSize, roughness, NoV);
        for (size_t k = 0; k < 2; ++k) {
            const double f0 = samples[i + k].a[2];
            const double reference = f0 * a + b;
            approxWorst.add(std::fabs(approx[i + k][0] - reference), roughness, NoV, f0);
            lutWorst.add(std::fabs(f0 * la + lb - reference), roughness, NoV, f0);
            monteCarloWorst.add(std::fabs(monteCarlo[i + k][0] - reference), roughness, NoV, f0);
        }
    }
    const uint32_t iterations = context.budget.iterations(16384);
    const uint32_t monteCarloIterations = context.budget.iterations(16);
    std::vector<Cost> ns = context.cost.nsPerEvaluation({
        {CostFunction::EnvBrdfApprox, iterations},
        {CostFunction::EnvBrdfLut, iterations},
        {CostFunction::EnvBrdfMonteCarlo, monteCarloIterations, monteCarloSamples},
    });
    char grid[200];
    std::snprintf(grid, sizeof(grid),
                  "max abs of F0 A + B (roughness 0..1 x NoV 0.02..1, %d x %d points, F0 {0.04, "
                  "1}); reference: eq. 8 in double, %d^2 stratified visible-normal samples",
                  steps + 1, steps + 1, referenceGrid);
    context.report.rows.push_back({"EnvBRDFApprox (Karis 2014, Physically Based Shading on Mobile)",
                                   "eq. 8 integrated (double)", grid, approxWorst.error, "abs",
                                   approxWorst.where, "vs LUT: " + formatShaderCost(ns[0], ns[1]),
                                   plottedNs(ns[0])});
    char lutName[96];
    std::snprintf(lutName, sizeof(lutName), "eq. 8 LUT, %ux%u R16G16 UNORM, bilinear (split sum)",
                  lutSize, lutSize);
    context.report.rows.push_back(
        {lutName, "eq. 8 integrated (double)", grid, lutWorst.error, "abs", lutWorst.where,
         "vs Monte Carlo (64 samples): " + formatShaderCost(ns[1], ns[2]) +
             "; the LUT read is a storage-buffer bilinear fetch here (the harness binds no "
             "sampler)",
         plottedNs(ns[1])});
    char mcName[96];
    std::snprintf(mcName, sizeof(mcName),
                  "eq. 8 by Monte Carlo at run time, %u visible-normal samples (device)",
                  monteCarloSamples);
    context.report.rows.push_back({mcName, "eq. 8 integrated (double)", grid, monteCarloWorst.error,
                                   "abs", monteCarloWorst.where,
                                   formatShaderCost(ns[2]) + " per evaluation", plottedNs(ns[2])});
}

}  // namespace candela::report
