#pragma once
// The fitted LTC table (render/ltc/ltc_ggx_table.inc, candela-ltc-fit) as two 64 x 64 RGBA16F
// textures for the area lights' specular (shaders/common/area_lights.glsl): `matrix` holds M^-1
// (00, 02, 20, 22; 11 = 1), `magnitude` the lobe's magnitude n and Fresnel part f. Columns are
// cos theta_v = 1 - t^2 (t = column / 63), rows roughness 0.02..1; bilinear, clamped to the
// edge, sampled at cell centres.
#include <vulkan/vulkan.h>

#include "candela/render/gpu_image.h"
#include "vk/sampler.h"

namespace candela::render {

class GpuContext;

class LtcTableTexture {
public:
    explicit LtcTableTexture(GpuContext& context);

    VkDescriptorImageInfo matrix() const;
    VkDescriptorImageInfo magnitude() const;

private:
    GpuImage matrix_;
    GpuImage magnitude_;
    Sampler sampler_;
};

}  // namespace candela::render
