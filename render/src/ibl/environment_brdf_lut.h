#pragma once
// The environment BRDF LUT of eq. 8: (scale, bias) of F0 over (NoV, roughness), R16G16_UNORM,
// computed once on the device when the first environment is lit. The environment never
// enters it, so one LUT serves every sky.
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
    // The texels as computed: packUnorm2x16(scale, bias), row = roughness, column = NoV.
    const uint32_t* packedTexels() const { return static_cast<const uint32_t*>(texels_.mapped()); }
    double buildMs() const { return buildMs_; }

private:
    GpuImage image_;
    GpuBuffer texels_;
    std::unique_ptr<Sampler> sampler_;
    double buildMs_ = 0.0;
};

}  // namespace candela::render
