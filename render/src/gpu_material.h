#pragma once
// The G-buffer pass's view of a material (std430; matches gbuffer.frag's Material).
#include <cstdint>

#include "candela/content/material.h"
#include "candela/render/shading_model.h"

namespace candela::render {

struct GpuTextureTransform {
    float matrix[4];  // 2x2 rotation*scale, column-major
    float offset[2];
    uint32_t texCoord;
    uint32_t present;  // 0: slot uses the fallback (white / flat normal)
};

// One layer over a layered material's base (content::MaterialLayering layers 1..3).
struct GpuMaterialLayer {
    float baseColor[4];
    float parameters[4];                // metallic, roughness, specular, normal scale
    GpuTextureTransform transforms[3];  // base colour, metallic-roughness, normal (UV scale in)
};

struct GpuMaterial {
    float baseColor[4];   // DefaultLit/Subsurface base colour; Legacy DiffuseColor; alpha
    float emissive[4];    // rgb = factor * strength (cd/m^2 per unit texel)
    float customData[4];  // Subsurface colour + opacity; Legacy SpecularColor
    float metallic;
    float roughness;
    float specular;
    float normalScale;
    float occlusionStrength;
    float alphaCutoff;  // < 0: opaque (no alpha test)
    uint32_t shadingModel;
    float cavity;  // content::Material::cavity; min'ed into the occlusion
    // KHR_materials_specular textures scale `specular` per texel by specularTexture.a *
    // max(this.rgb * specularColorTexture.rgb); rgb = specularColorFactor / its largest
    // channel, so untextured (white) slots leave `specular` exactly as it is.
    float specularColorScale[4];
    // KHR_materials_anisotropy: strength, cos and sin of the rotation; 0 strength: isotropic.
    float anisotropy[4];
    // KHR_materials_clearcoat: factor, roughness, normal scale; 0 factor: no coat.
    float clearcoat[4];
    GpuTextureTransform transforms[11];  // TextureSlot order
    // Material layers (read only by the G-buffer's layered variant): x the layers over the base
    // (0 to 3), y 1 when the vertex colour is the mask (else the mask texture).
    float layering[4];
    GpuTextureTransform maskTransform;
    GpuMaterialLayer layers[3];
};
static_assert(sizeof(GpuMaterial) % 16 == 0, "std430 array stride");

GpuMaterial packMaterial(const content::Material& material);
// The texture slots packMaterial marks present (bit i: GpuMaterial::transforms[i]): the
// G-buffer pipeline a draw takes (material.glsl's kMaterialTextureSlots). SceneResources keeps
// it per material (materialTextureSlots).
uint32_t presentTextureSlots(const content::Material& material);
ShadingModelId shadingModelId(content::ShadingModel model);

}  // namespace candela::render
