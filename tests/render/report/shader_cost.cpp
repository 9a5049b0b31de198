#include "shader_cost.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <span>

#include "median.h"
#include "report_table.h"
#include "shaders/report_cost.comp.spv.h"

namespace candela::report {

namespace {

double quantile(std::vector<double> values, double q) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[size_t(q * double(values.size() - 1) + 0.5)];
}

bool aboveNoise(const Cost& cost) {
    return cost.ns > 0.0 && cost.ns > cost.spread;
}

}  // namespace

double plottedNs(const Cost& cost) {
    return aboveNoise(cost) ? cost.ns : 0.0;
}

std::string formatShaderCost(const Cost& cost) {
    if (aboveNoise(cost)) return formatNumber(cost.ns) + " ns";
    return "< noise (IQR " + formatNumber(cost.spread, 2) + " ns)";
}

std::string formatShaderCost(const Cost& approximation, const Cost& reference) {
    std::string text = formatShaderCost(approximation) + " vs " + formatShaderCost(reference);
    if (aboveNoise(approximation) && aboveNoise(reference)) {
        text += " (" + formatNumber(reference.ns / approximation.ns) + "x)";
    }
    return text;
}

ShaderCost::ShaderCost(stability::ComputeHarness& harness, const std::vector<float>& lut,
                       uint32_t lutSize, uint32_t repetitions, uint32_t invocations)
    : harness_(harness),
      sums_(harness.buffer(invocations * sizeof(float))),
      lut_(harness.upload(std::span<const float>(lut))),
      pipeline_(harness.pipeline(report_cost_comp_spv, 2, 16)),
      lutSize_(lutSize),
      repetitions_(repetitions),
      invocations_(invocations) {}

double ShaderCost::timeDispatchMs(CostFunction function, uint32_t iterations, uint32_t samples) {
    const std::array<uint32_t, 4> job = {uint32_t(function), iterations, samples, lutSize_};
    auto start = std::chrono::steady_clock::now();
    harness_.dispatch(pipeline_, {&sums_, &lut_}, job.data(), sizeof(job), invocations_ / 64);
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

std::vector<Cost> ShaderCost::nsPerEvaluation(const std::vector<CostJob>& jobs) {
    // One untimed pass compiles and warms every variant.
    for (const CostJob& job : jobs)
        timeDispatchMs(job.function, 1, job.samples);
    std::vector<std::vector<double>> net(jobs.size());
    for (uint32_t r = 0; r < repetitions_; ++r) {
        for (size_t j = 0; j < jobs.size(); ++j) {
            const CostJob& job = jobs[j];
            double baseline = timeDispatchMs(CostFunction::Baseline, job.iterations, 0);
            double measured = timeDispatchMs(job.function, job.iterations, job.samples);
            net[j].push_back((measured - baseline) * 1e6 /
                             (double(invocations_) * double(job.iterations)));
        }
    }
    std::vector<Cost> out;
    for (auto& values : net)
        out.push_back({median(values), quantile(values, 0.75) - quantile(values, 0.25)});
    return out;
}

}  // namespace candela::report
