#pragma once
// Runs one function of shaders/report_values.comp over host-chosen inputs.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "../stability/compute_harness.h"
#include "shaders/report_values.comp.spv.h"

namespace candela::report {

// Must match the function ids of shaders/report_values.comp.
enum class ValueFunction : uint32_t {
    Fresnel = 0,
    Visibility = 1,
    EnvBrdfApprox = 2,
    EnvBrdfMonteCarlo = 3,
    Falloff = 4,
    Ggx = 5,
    AreaLight = 6,
    VisibilityFast = 7,
    AreaLightLtc = 8,
    TubeDiffuse = 9,
};

struct ValueSample {
    std::array<float, 4> a{}, b{}, c{}, d{}, e{};
};

inline std::vector<std::array<float, 2>> evaluateOnDevice(stability::ComputeHarness& harness,
                                                          ValueFunction function,
                                                          const std::vector<ValueSample>& samples) {
    render::GpuBuffer in = harness.upload(std::span<const ValueSample>(samples));
    render::GpuBuffer out = harness.buffer(samples.size() * sizeof(float) * 2);
    render::Pipeline pipeline = harness.pipeline(report_values_comp_spv, 2, 8);
    const std::array<uint32_t, 2> job = {uint32_t(function), uint32_t(samples.size())};
    harness.dispatch(pipeline, {&in, &out}, job.data(), sizeof(job),
                     uint32_t((samples.size() + 63) / 64));
    return harness.read<std::array<float, 2>>(out, samples.size());
}

}  // namespace candela::report
