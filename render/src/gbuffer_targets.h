#pragma once
// The G-buffer images. Layout (precision in brackets):
//   baseColor       RGBA8_SRGB   rgb base colour (Legacy: DiffuseColor), a occlusion
//   normalRoughMetal RGBA16_UNORM octahedral normal xy (max angular error ~0.005 deg at
//                                16 bits), roughness, metallic
//   specularModel   RGBA8_UNORM  r specular, g shading model ID / 255 (exact for IDs < 256)
//   customData      RGBA8_UNORM  Subsurface colour + opacity, or Legacy SpecularColor
//   depth           D32_SFLOAT   reverse-Z (see CameraView)
// Emissive goes straight into the HDR target, which the lighting pass then adds to.
#include <array>
#include <cstdint>

#include "candela/render/gpu_image.h"

namespace candela::render {

class GpuContext;

struct GBufferTargets {
    static constexpr std::array<VkFormat, 4> kColorFormats = {
        VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_R16G16B16A16_UNORM, VK_FORMAT_R8G8B8A8_UNORM,
        VK_FORMAT_R8G8B8A8_UNORM};
    static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

    GBufferTargets() = default;
    GBufferTargets(GpuContext& context, uint32_t width, uint32_t height);

    std::array<GpuImage, 4> color;
    GpuImage depth;
};

}  // namespace candela::render
