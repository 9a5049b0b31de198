#pragma once
// Surface description shared by glTF materials, scene-file overrides and the renderer.
// Field meanings follow glTF 2.0 plus the engine's shading models (SPEC.md "Shading").
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

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

// Material layers (Karis 2013, "Real Shading in Unreal Engine 4", "Material Layering"): a material
// built by blending a few layers, each a small linear set of parameters with its own textures at
// its own UV scale, by per-pixel masks. Layers come from a scene file's shared library
// ("materialLayers") by name; a material's copies may change any parameter (scene_file.h). The
// G-buffer shader blends them before lighting, so the lighting cost does not grow with the layer
// count (render/README.md "Material layers").
//
// At most four layers: the base and three over it, weighted by one RGBA mask's R, G and B. One
// mask texture then gives every weight in a single fetch, and four keeps the blend (three
// extra layers of three texture reads each) a small fixed cost in the G-buffer pass.
inline constexpr std::size_t kMaxMaterialLayers = 4;

struct MaterialLayer {
    std::string name;                                  // its name in the scene's layer library
    std::array<float, 4> baseColorFactor{1, 1, 1, 1};  // linear RGBA (alpha unused)
    float metallicFactor = 0;
    float roughnessFactor = 0.5f;
    float specular = 0.5f;
    float normalScale = 1;
    TextureRef baseColorTexture;          // sRGB
    TextureRef metallicRoughnessTexture;  // linear; B = metallic, G = roughness
    TextureRef normalTexture;             // linear, tangent space
    // The layer's texture frequency: its textures read at uvScale * uv (before their own
    // KHR_texture_transform), so a fine rust grain can tile over a coarse mask.
    std::array<float, 2> uvScale{1, 1};
};

// Where the blend weights of layers 1..3 come from: a texture's R, G, B (at the texture's own
// transform, the mask's frequency), or the vertex colour's (which then no longer tints the
// base colour).
enum class LayerMaskSource : std::uint8_t { Texture, VertexColor };

struct MaterialLayering {
    // Empty: not layered. Else layers[0] is the base (it replaces the material's base colour,
    // metallic, roughness, specular, normal scale and their textures) and layer i > 0 is
    // blended over the layers below it by mask channel i - 1.
    std::vector<MaterialLayer> layers;
    LayerMaskSource maskSource = LayerMaskSource::Texture;
    TextureRef maskTexture;  // linear; used when maskSource is Texture

    bool used() const { return !layers.empty(); }
};

// A hair material (Martin et al. 2014, GPU Pro 5, "TressFX: Advanced Real-Time Hair Rendering"):
// the strand's radius from root to tip, its colour (K_d of the diffuse K_d sin(t, l)) and
// Kajiya-Kay's two highlights, each from a tangent tilted toward the normal by its shift (the
// primary toward the tip, coloured by the light; the secondary toward the root, coloured by the
// light and the hair) and sharpened by its exponent. glTF: material extras `hair` {rootRadius,
// tipRadius, color, primaryShift, secondaryShift, primaryExponent, secondaryExponent}
// (content/README.md).
struct HairStyle {
    float rootRadius = 4e-5f;                         // metres
    float tipRadius = 1e-5f;                          // metres
    std::array<float, 3> color{0.35f, 0.22f, 0.12f};  // linear
    float primaryShift = 0.1f;
    float secondaryShift = -0.1f;
    float primaryExponent = 80.0f;
    float secondaryExponent = 20.0f;

    bool operator==(const HairStyle&) const = default;
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
    // UE4's Cavity (Karis 2013, "Material Model"): small-scale shadowing of the ambient (sky) light
    // finer than the runtime shadows and AO resolve, in [0, 1]; 1: none. Read from extras.cavity.
    // Combined with the occlusion texture by min (render/README.md "Ambient occlusion").
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

    // extras.wireRadius (metres, > 0): line primitives with this material are wires (wire.h);
    // 0: lines with it are skipped.
    float wireRadius = 0;

    // extras.hair (Martin et al. 2014): line primitives with this material are hair strands
    // (hair.h).
    std::optional<HairStyle> hair;

    MaterialLayering layering;  // compiled out of frames without layered materials

    bool anisotropic() const { return anisotropyStrength > 0; }
    bool clearCoated() const { return clearcoatFactor > 0; }
    bool layered() const { return layering.used(); }
};

// The material as the renderer binds it: a layered material's base layer (layers[0]) written
// over its base colour, metallic, roughness, specular, normal scale and their textures (the
// layer's UV scale folded into the texture transforms). Other materials come back unchanged.
Material withBaseLayer(const Material& material);
// One of `layer`'s textures with the layer's UV scale folded into its transform.
TextureRef layerTexture(const MaterialLayer& layer, const TextureRef& ref);

}  // namespace candela::content
