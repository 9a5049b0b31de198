#pragma once
// The G-buffer images, transient in the frame graph. Layout (precision in brackets):
//   baseColor       RGBA8_SRGB   rgb base colour (Legacy: DiffuseColor), a occlusion
//   normalRoughMetal RGBA16_UNORM octahedral normal xy (max angular error ~0.005 deg at
//                                16 bits), roughness, metallic
//   specularModel   RGBA8_UNORM  r specular, g shading model ID / 255 (exact for IDs < 256)
//   customData      RGBA8_UNORM  Subsurface colour + opacity, or Legacy SpecularColor
//   depth           D32_SFLOAT   reverse-Z (see CameraView)
//   motion          RG16_SFLOAT  screen-space motion, current - previous texture coordinates
//                                (motion_vectors.glsl); 0 where nothing is drawn. Also
//                                written (alpha-blended) by the forward transparency pass.
// Only in frames whose materials use KHR_materials_anisotropy or KHR_materials_clearcoat
// (both created when either is used; gbuffer_extended.frag writes them):
//   anisotropy      RG16_UNORM   r: angle of the anisotropy direction in [0, pi) from the first
//                                axis of tangentFrame(decoded N) / pi (0.0027 degree steps;
//                                T and -T give the same lobe), g: strength
//   clearCoat       RGBA16_UNORM factor, roughness, octahedral coat normal xy (as the normal)
// Only in --aa gbaa frames (the *_edges.frag variants write it, after the targets above):
//   edges           RGBA16_SFLOAT distances in pixels from the pixel centre to the nearest edge
//                                of its triangle to the left, right (along x), above, below
//                                (along y), GBAA_NO_EDGE where none is within 1.5 pixels
//                                (common/gbaa_edges.glsl)
// Emissive goes straight into the HDR target, which the lighting pass then adds to.
#include <array>
#include <cstdint>

#include "frame_graph/graph_resources.h"

namespace candela::render {

struct GBufferTargets {
    static constexpr std::array<VkFormat, 4> kColorFormats = {
        VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_R16G16B16A16_UNORM, VK_FORMAT_R8G8B8A8_UNORM,
        VK_FORMAT_R8G8B8A8_UNORM};
    static constexpr std::array<const char*, 4> kColorNames = {
        "gbuffer.base_color", "gbuffer.normal_rough_metal", "gbuffer.specular_model",
        "gbuffer.custom_data"};
    static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
    static constexpr VkFormat kMotionFormat = VK_FORMAT_R16G16_SFLOAT;
    static constexpr const char* kMotionName = "gbuffer.motion";
    static constexpr VkFormat kAnisotropyFormat = VK_FORMAT_R16G16_UNORM;
    static constexpr VkFormat kClearCoatFormat = VK_FORMAT_R16G16B16A16_UNORM;
    static constexpr VkFormat kEdgesFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
    static constexpr const char* kEdgesName = "gbuffer.edges";

    static ImageDesc colorDesc(size_t index, uint32_t width, uint32_t height) {
        return {kColorFormats[index],
                width,
                height,
                1,
                false,
                VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT};
    }
    static ImageDesc extensionDesc(VkFormat format, uint32_t width, uint32_t height) {
        return {format, width, height,
                1,      false, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT};
    }
    static ImageDesc depthDesc(uint32_t width, uint32_t height) {
        return {
            kDepthFormat, width,
            height,       1,
            false,        VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT};
    }

    static ImageDesc motionDesc(uint32_t width, uint32_t height) {
        return {kMotionFormat, width, height, 1, false,
                // Transfer source: tests read it back (RendererOptions::captureMotionVectors).
                VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                    VK_IMAGE_USAGE_TRANSFER_SRC_BIT};
    }

    std::array<ImageRef, 4> color;
    ImageRef depth;
    ImageRef motion;
    bool extended = false;  // anisotropy and clearCoat exist
    ImageRef anisotropy;
    ImageRef clearCoat;
    bool hasEdges = false;  // edges exists
    ImageRef edges;
};

}  // namespace candela::render
