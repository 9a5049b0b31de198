#pragma once
// What a pass binds for image-based lighting: the sky's textures and buffers, or 1x1
// placeholders when the scene has none (the shader variant without IBL never reads them, but
// every declared binding must hold something valid).
#include <vulkan/vulkan.h>

#include <memory>

#include "candela/render/gpu_buffer.h"
#include "candela/render/gpu_image.h"

namespace candela::render {

class Environment;
class EnvironmentBrdfLut;
class GpuContext;
class Sampler;

struct EnvironmentDescriptors {
    VkDescriptorImageInfo environment;     // cube with mips (background, reference mode)
    VkDescriptorImageInfo prefiltered;     // roughness per mip
    VkDescriptorImageInfo brdfLut;         // eq. 8, R16G16B16A16
    VkDescriptorBufferInfo irradianceSh;   // 9 vec4
    VkDescriptorBufferInfo samplingTable;  // the reference mode's luminance CDF
    float prefilteredMipCount = 1.0f;
    // Not the sky's, but bound beside it by the same passes: the area lights' LTC table
    // (lights/ltc_table_texture.h), filled in by the renderer.
    VkDescriptorImageInfo ltcMatrix{};
    VkDescriptorImageInfo ltcMagnitude{};
    // Textured rect lights' images (lights/area_light_textures.h).
    VkDescriptorImageInfo areaLightTextures{};
};

class EnvironmentPlaceholders {
public:
    explicit EnvironmentPlaceholders(GpuContext& context);
    ~EnvironmentPlaceholders();
    EnvironmentPlaceholders(const EnvironmentPlaceholders&) = delete;
    EnvironmentPlaceholders& operator=(const EnvironmentPlaceholders&) = delete;

    // The environment's descriptors where given, the LUT's where given (the energy-conserving
    // BRDF reads it without a sky too); placeholders for the rest.
    EnvironmentDescriptors describe(const Environment* environment, const EnvironmentBrdfLut* lut,
                                    const GpuBuffer* samplingTable) const;

private:
    GpuImage cube_;
    GpuImage lut_;
    GpuBuffer buffer_;
    std::unique_ptr<Sampler> sampler_;
};

}  // namespace candela::render
