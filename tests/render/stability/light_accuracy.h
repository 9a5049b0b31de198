#pragma once
// Runs one function of shaders/light_accuracy.comp over CPU-chosen inputs.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "compute_harness.h"
#include "shaders/light_accuracy.comp.spv.h"

namespace candela::stability {

// Must match the function ids of shaders/light_accuracy.comp.
enum class LightFunction : uint32_t {
    AttenuationWindow = 0,
    InverseSquare = 1,
    SphereIrradianceFactor = 2,
    SphereEnergyNormalization = 3,
    TubeEnergyNormalization = 4,
    LineIrradiance = 5,
    TubeClosestParameter = 6,
    SphereRepresentativePoint = 7,
    LocalLight = 8,
    Product = 9,
    LtcQuad = 10,
    LtcDisk = 11,
    LtcTube = 12,
    AreaLightDiffuse = 20,
};

using Float4 = std::array<float, 4>;

// Must match LightSample in shaders/light_accuracy.comp.
struct LightSample {
    Float4 a{}, b{}, c{}, d{};
};

inline std::vector<Float4> evaluateOnDevice(ComputeHarness& harness, LightFunction function,
                                            const std::vector<LightSample>& samples) {
    render::GpuBuffer in = harness.upload(std::span<const LightSample>(samples));
    render::GpuBuffer out = harness.buffer(samples.size() * sizeof(Float4));
    render::Pipeline pipeline = harness.pipeline(light_accuracy_comp_spv, 2, 8);
    const std::array<uint32_t, 2> job = {uint32_t(function), uint32_t(samples.size())};
    harness.dispatch(pipeline, {&in, &out}, job.data(), sizeof(job),
                     uint32_t((samples.size() + 63) / 64));
    return harness.read<Float4>(out, samples.size());
}

}  // namespace candela::stability
