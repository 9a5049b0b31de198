#pragma once
// GPU cost per evaluation of the shared GLSL functions (shaders/report_cost.comp): whole
// dispatches timed by wall clock around submit-and-wait, the input-generation loop subtracted,
// medians over repetitions. Functions compared with each other are timed interleaved in the
// same repetitions, so load on the machine hits both alike.
#include <cstdint>
#include <string>
#include <vector>

#include "../stability/compute_harness.h"

namespace candela::report {

// Must match the function ids of shaders/report_cost.comp.
enum class CostFunction : uint32_t {
    Baseline = 0,
    FresnelSg = 1,
    FresnelPow5 = 2,
    VisSchlick = 3,
    VisSmithGgx = 4,
    EnvBrdfApprox = 5,
    EnvBrdfLut = 6,
    EnvBrdfMonteCarlo = 7,
    InverseSquare = 8,
    WindowedFalloff = 9,
    SphereRepresentative = 10,
    SphereMonteCarlo = 11,
    TubeRepresentative = 12,
    TubeMonteCarlo = 13,
    VisSmithGgxFast = 14,
    MultipleScattering = 15,
    PointLight = 16,  // representative-point specular (correlated Smith) of a point light
    SphereLtc = 17,
    TubeLtc = 18,         // ltcTubeIntegral, radius 0 (the thin path: no caps)
    TubeCapsuleLtc = 19,  // ltcTubeIntegral, radius 0.1 m (cylinder and both caps)
    // Rect and disk lights (area_light_shapes_rows.cpp): diffuse + specular of one light.
    PointLightShading = 20,
    RectRepresentative = 21,
    RectLtc = 22,
    DiskRepresentative = 23,
    DiskLtc = 24,
    // Textured rect lights: the same with the image read once per lobe.
    TexturedRectRepresentative = 25,
    TexturedRectLtc = 26,
    // Constant-intensity rect and disk lights: the same with Drobot's pre-integrated factors
    // (2014, GPU Pro 5, "Physically Based Area Lights").
    RectRepresentativeConstantIntensity = 27,
    RectLtcConstantIntensity = 28,
    DiskRepresentativeConstantIntensity = 29,
    DiskLtcConstantIntensity = 30,
    TubeSegmentLtc = 31,  // ltcLineIntegral, the bare segment (the tube before the capsule)
    // Tube lights of radius 0.1 m, diffuse + specular: the capsule by LTC (ltcTubeIntegrals, both
    // integrals), and the representative point with lineIrradiance (evaluateLocalLight).
    TubeCapsuleLtcShading = 32,
    TubeRepresentativeShading = 33,
};

struct CostJob {
    CostFunction function;
    uint32_t iterations;   // evaluations per invocation (loop trip count, << 65,535)
    uint32_t samples = 0;  // Monte Carlo samples per evaluation
};

// Median nanoseconds per evaluation over the repetitions and their interquartile range: a
// median under its spread is indistinguishable from zero on this (shared, loaded) machine.
struct Cost {
    double ns = 0.0;
    double spread = 0.0;
};

// The nanoseconds of a cost for ReportRow::costNs: 0 when under the timer's noise.
double plottedNs(const Cost& cost);
// "0.36 ns", or "< noise (IQR 0.05 ns)" when the median is under its spread.
std::string formatShaderCost(const Cost& cost);
// "a vs b (ratio x)"; the ratio only when both are above their noise.
std::string formatShaderCost(const Cost& approximation, const Cost& reference);

class ShaderCost {
public:
    // lut: the environment BRDF LUT as (scale, bias) pairs, lutSize^2 of them.
    ShaderCost(stability::ComputeHarness& harness, const std::vector<float>& lut, uint32_t lutSize,
               uint32_t repetitions, uint32_t invocations);

    // Nanoseconds per evaluation of each job, net of the baseline loop with the same trip
    // count; the median may be <= 0 when a function costs less than the timer's noise.
    std::vector<Cost> nsPerEvaluation(const std::vector<CostJob>& jobs);

private:
    double timeDispatchMs(CostFunction function, uint32_t iterations, uint32_t samples);

    stability::ComputeHarness& harness_;
    render::GpuBuffer sums_;
    render::GpuBuffer lut_;
    render::Pipeline pipeline_;
    uint32_t lutSize_;
    uint32_t repetitions_;
    uint32_t invocations_;
};

}  // namespace candela::report
