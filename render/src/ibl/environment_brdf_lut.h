#pragma once
// The environment BRDF LUT of eq. 8: (scale, bias) of F0 over (NoV, roughness),
// R16G16B16A16_UNORM: .rg with Schlick-Smith visibility (the UE4 BRDF), .ba with height-
// correlated Smith (the energy-conserving BRDF, which also reads its scale + bias as the
// directional albedo E_ss for multiple scattering). Computed once on the device when the first
// environment is lit, or with the first frame of the energy-conserving BRDF. The environment
// never enters it, so one LUT serves every sky.
#include <cstdint>
#include <memory>
#include <vector>

#include "candela/render/gpu_buffer.h"
#include "candela/render/gpu_image.h"

namespace candela::render {

class GpuContext;
class Sampler;

class EnvironmentBrdfLut {
public:
    static constexpr uint32_t kSize = 128;
    // Hammersley samples per texel: deterministic, and within 2e-3 of a double-precision
    // integration at every texel (tests/render/ibl_tests.cpp).
    static constexpr uint32_t kSampleCount = 1024;

    explicit EnvironmentBrdfLut(GpuContext& context);
    ~EnvironmentBrdfLut();
    EnvironmentBrdfLut(const EnvironmentBrdfLut&) = delete;
    EnvironmentBrdfLut& operator=(const EnvironmentBrdfLut&) = delete;

    const GpuImage& image() const { return image_; }  // SHADER_READ_ONLY_OPTIMAL
    VkSampler sampler() const;
    // The texels as computed, two uints each: packUnorm2x16(scale, bias) with Schlick-Smith
    // then with height-correlated Smith; row = roughness, column = NoV.
    const uint32_t* packedTexels() const { return static_cast<const uint32_t*>(texels_.mapped()); }
    uint32_t packedSchlick(uint32_t texel) const { return packedTexels()[2 * texel]; }
    uint32_t packedCorrelated(uint32_t texel) const { return packedTexels()[2 * texel + 1]; }
    double buildMs() const { return buildMs_; }

private:
    GpuImage image_;
    GpuBuffer texels_;
    std::unique_ptr<Sampler> sampler_;
    double buildMs_ = 0.0;
};

}  // namespace candela::render
