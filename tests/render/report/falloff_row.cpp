// Row: eq. 9's windowed falloff saturate(1 - (d / R)^4)^2 / (d^2 + 1e-4) against pure inverse
// square 1 / d^2: the share of a point light's energy the window drops. The flux through a
// sphere of radius d is 4 pi I d^2 E(d): constant for 1 / d^2, so 1 - d^2 E(d) is the share
// dropped at distance d, and its mean over d in (0, R] the share dropped within the radius.
#include <cmath>
#include <cstdio>
#include <string>

#include "report_context.h"
#include "shader_values.h"

namespace candela::report {

void addFalloffRow(ReportContext& context) {
    const double radius = 10.0;  // the fractions depend on d / R only, except for the bias
    const int steps = context.budget.quick ? 256 : 16384;
    std::vector<ValueSample> samples;
    for (int i = 1; i <= steps; ++i) {
        const double d = radius * i / steps;
        samples.push_back({{float(d * d), float(1.0 / radius), 0, 0}});
    }
    auto values = evaluateOnDevice(context.harness, ValueFunction::Falloff, samples);
    double meanDropped = 0.0, droppedAtHalf = 0.0, tenPercentAt = -1.0;
    for (int i = 0; i < steps; ++i) {
        const double d = radius * (i + 1) / steps;
        const double dropped = 1.0 - values[size_t(i)][0] * d * d;
        meanDropped += dropped / steps;
        if (i + 1 == steps / 2) droppedAtHalf = dropped;
        if (tenPercentAt < 0.0 && d > 0.05 && dropped >= 0.1) tenPercentAt = d / radius;
    }
    const uint32_t iterations = context.budget.iterations(16384);
    std::vector<Cost> ns = context.cost.nsPerEvaluation({
        {CostFunction::WindowedFalloff, iterations},
        {CostFunction::InverseSquare, iterations},
    });
    char metric[200];
    std::snprintf(metric, sizeof(metric),
                  "share of the flux dropped, 1 - d^2 E(d), mean over d in (0, R] (%d steps, "
                  "device fp32); %.1f %% at d = R / 2",
                  steps, 100.0 * droppedAtHalf);
    char where[160];
    std::snprintf(where, sizeof(where),
                  "d = R (100 %%); >= 10 %% from d = %.2f R on; the 1e-4 m^2 bias drops 50 %% at "
                  "d = 1 cm",
                  tenPercentAt);
    context.report.rows.push_back(
        {"Windowed falloff (eq. 9)", "inverse square 1 / d^2", metric, 100.0 * meanDropped,
         "% energy", where,
         formatShaderCost(ns[0], ns[1]) + " (the window is what lets clustering cull at R)",
         plottedNs(ns[0])});
}

}  // namespace candela::report
