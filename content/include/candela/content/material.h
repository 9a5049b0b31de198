#pragma once
// Surface description shared by glTF materials, scene-file overrides and the renderer.
// Field meanings follow glTF 2.0 plus the engine's shading models (SPEC.md "Shading").
#include <array>
#include <cstdint>
#include <string>

#include "candela/content/image.h"

namespace candela::content {

enum class ShadingModel : std::uint8_t { DefaultLit, Subsurface, Legacy, Unlit };
enum class AlphaMode : std::uint8_t { Opaque, Mask, Blend };

// KHR_texture_transform: uv' = offset + rotate(rotation) * (scale * uv).
struct TextureTransform {
    std::array<float, 2> offset{0, 0};
    float rotation = 0;  // radians, counter-clockwise in UV space
    std::array<float, 2> scale{1, 1};
};

struct TextureRef {
    std::int32_t texture = -1;   // into Model::textures; -1 means no texture
    std::uint32_t texCoord = 0;  // 0: uv0, 1: uv1 (after any KHR_texture_transform override)
    TextureTransform transform;
    ColorSpace colorSpace = ColorSpace::Linear;  // set by the slot: sRGB for colour slots

    bool present() const { return texture >= 0; }
};

struct Material {
    std::string name;
    ShadingModel shadingModel = ShadingModel::DefaultLit;

    std::array<float, 4> baseColorFactor{1, 1, 1, 1};  // linear RGBA
    TextureRef baseColorTexture;                       // sRGB
    float metallicFactor = 1;
    float roughnessFactor = 1;
    TextureRef metallicRoughnessTexture;  // linear; B = metallic, G = roughness
    TextureRef normalTexture;             // linear, tangent space
    float normalScale = 1;
    TextureRef occlusionTexture;  // linear; R = occlusion
    float occlusionStrength = 1;
    // UE4's Cavity (seed 000 §2.3): small-scale shadowing of the ambient (sky) light finer than
    // the runtime shadows and AO resolve, in [0, 1]; 1: none. Read from extras.cavity. Combined
    // with the occlusion texture by min (render/README.md "Ambient occlusion").
    float cavity = 1;
    TextureRef emissiveTexture;  // sRGB
    std::array<float, 3> emissiveFactor{0, 0, 0};
    float emissiveStrength = 1;  // KHR_materials_emissive_strength

    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;  // used when alphaMode == Mask
    bool doubleSided = false;

    // Engine inputs (SPEC.md): specular 0.5 means F0 = 0.04 for non-metals. Set from
    // KHR_materials_specular where it maps, or from extras.specular.
    float specular = 0.5f;
    TextureRef specularTexture;       // KHR_materials_specular; A = specular factor
    TextureRef specularColorTexture;  // KHR_materials_specular; sRGB
    std::array<float, 3> specularColorFactor{1, 1, 1};  // KHR_materials_specular

    // Subsurface model (extras).
    std::array<float, 3> subsurfaceColor{1, 1, 1};
    float subsurfaceOpacity = 1;  // 1: no transmission; 0: fully translucent thin parts

    // Legacy diffuse/specular model (extras): used directly, not derived from metallic.
    std::array<float, 3> diffuseColor{0.8f, 0.8f, 0.8f};
    std::array<float, 3> specularColor{0.04f, 0.04f, 0.04f};

    // KHR_materials_anisotropy: the GGX lobe stretched along a direction in the tangent plane,
    // alpha along it mix(alpha, 1, strength^2). The direction is the tangent rotated by
    // `anisotropyRotation` (radians, counter-clockwise toward the bitangent), then by the
    // texture's RG (a direction, [0, 1] -> [-1, 1]); the texture's B scales the strength.
    float anisotropyStrength = 0;  // [0, 1]; 0: isotropic (compiled out of frames without it)
    float anisotropyRotation = 0;
    TextureRef anisotropyTexture;  // linear

    // KHR_materials_clearcoat: a second, dielectric (F0 0.04) GGX lobe over the base, whose
    // Fresnel takes its share of the light from everything under it.
    float clearcoatFactor = 0;    // [0, 1]; 0: no coat (compiled out of frames without it)
    TextureRef clearcoatTexture;  // linear; R scales the factor
    float clearcoatRoughnessFactor = 0;
    TextureRef clearcoatRoughnessTexture;  // linear; G scales the roughness
    TextureRef clearcoatNormalTexture;     // linear, tangent space; none: the geometric normal
    float clearcoatNormalScale = 1;

    bool anisotropic() const { return anisotropyStrength > 0; }
    bool clearCoated() const { return clearcoatFactor > 0; }
};

}  // namespace candela::content
