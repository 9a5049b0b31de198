#include "gpu_material.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace candela::render {

namespace {

GpuTextureTransform packTransform(const content::TextureRef& ref) {
    GpuTextureTransform t{};
    const float c = std::cos(ref.transform.rotation);
    const float s = std::sin(ref.transform.rotation);
    // KHR_texture_transform: uv' = offset + R(rotation) * (scale * uv), with R rotating
    // counter-clockwise in UV space: [c s; -s c].
    t.matrix[0] = c * ref.transform.scale[0];
    t.matrix[1] = -s * ref.transform.scale[0];
    t.matrix[2] = s * ref.transform.scale[1];
    t.matrix[3] = c * ref.transform.scale[1];
    t.offset[0] = ref.transform.offset[0];
    t.offset[1] = ref.transform.offset[1];
    t.texCoord = ref.texCoord;
    t.present = ref.present() ? 1u : 0u;
    return t;
}

}  // namespace

uint32_t presentTextureSlots(const content::Material& material) {
    const GpuMaterial packed = packMaterial(material);
    uint32_t slots = 0;
    for (uint32_t i = 0; i < std::size(packed.transforms); ++i) {
        if (packed.transforms[i].present != 0u) slots |= 1u << i;
    }
    return slots;
}

ShadingModelId shadingModelId(content::ShadingModel model) {
    switch (model) {
        case content::ShadingModel::Subsurface:
            return ShadingModelId::Subsurface;
        case content::ShadingModel::Legacy:
            return ShadingModelId::LegacyDiffuseSpecular;
        case content::ShadingModel::Unlit:
            return ShadingModelId::Unlit;
        case content::ShadingModel::DefaultLit:
            break;
    }
    return ShadingModelId::DefaultLit;
}

GpuMaterial packMaterial(const content::Material& material) {
    // A layered material's base layer packs as its base fields; layers 1..3 go below.
    const content::Material m = content::withBaseLayer(material);
    GpuMaterial g{};
    const bool legacy = m.shadingModel == content::ShadingModel::Legacy;
    for (int i = 0; i < 3; ++i) {
        g.baseColor[i] = legacy ? m.diffuseColor[i] : m.baseColorFactor[i];
        g.emissive[i] = m.emissiveFactor[i] * m.emissiveStrength;
        g.customData[i] = legacy ? m.specularColor[i] : m.subsurfaceColor[i];
    }
    g.baseColor[3] = m.baseColorFactor[3];
    g.customData[3] = legacy ? 0.0f : m.subsurfaceOpacity;
    g.metallic = legacy ? 0.0f : m.metallicFactor;
    g.roughness = m.roughnessFactor;
    g.specular = m.specular;
    g.normalScale = m.normalScale;
    g.occlusionStrength = m.occlusionStrength;
    g.cavity = m.cavity;
    g.alphaCutoff = m.alphaMode == content::AlphaMode::Mask ? m.alphaCutoff : -1.0f;
    g.shadingModel = static_cast<uint32_t>(shadingModelId(m.shadingModel));
    g.transforms[0] = packTransform(m.baseColorTexture);
    g.transforms[1] = packTransform(m.metallicRoughnessTexture);
    g.transforms[2] = packTransform(m.normalTexture);
    g.transforms[3] = packTransform(m.occlusionTexture);
    g.transforms[4] = packTransform(m.emissiveTexture);
    g.transforms[5] = packTransform(m.specularTexture);
    g.transforms[6] = packTransform(m.specularColorTexture);
    g.transforms[7] = packTransform(m.anisotropyTexture);
    g.transforms[8] = packTransform(m.clearcoatTexture);
    g.transforms[9] = packTransform(m.clearcoatRoughnessTexture);
    g.transforms[10] = packTransform(m.clearcoatNormalTexture);
    g.anisotropy[0] = m.anisotropyStrength;
    g.anisotropy[1] = std::cos(m.anisotropyRotation);
    g.anisotropy[2] = std::sin(m.anisotropyRotation);
    g.clearcoat[0] = m.clearcoatFactor;
    g.clearcoat[1] = m.clearcoatRoughnessFactor;
    g.clearcoat[2] = m.clearcoatNormalScale;
    const auto& c = m.specularColorFactor;
    const float largest = std::max({c[0], c[1], c[2]});
    for (int i = 0; i < 3; ++i)
        g.specularColorScale[i] = largest > 0.0f ? c[i] / largest : 1.0f;
    g.specularColorScale[3] = 1.0f;
    const content::MaterialLayering& layering = material.layering;
    if (layering.layers.size() > 1) {
        const size_t count = std::min(layering.layers.size(), content::kMaxMaterialLayers);
        g.layering[0] = float(count - 1);
        g.layering[1] = layering.maskSource == content::LayerMaskSource::VertexColor ? 1.0f : 0.0f;
        g.maskTransform = packTransform(layering.maskTexture);
        for (size_t i = 1; i < count; ++i) {
            const content::MaterialLayer& l = layering.layers[i];
            GpuMaterialLayer& out = g.layers[i - 1];
            for (int channel = 0; channel < 4; ++channel)
                out.baseColor[channel] = l.baseColorFactor[size_t(channel)];
            out.parameters[0] = l.metallicFactor;
            out.parameters[1] = l.roughnessFactor;
            out.parameters[2] = l.specular;
            out.parameters[3] = l.normalScale;
            out.transforms[0] = packTransform(content::layerTexture(l, l.baseColorTexture));
            out.transforms[1] = packTransform(content::layerTexture(l, l.metallicRoughnessTexture));
            out.transforms[2] = packTransform(content::layerTexture(l, l.normalTexture));
        }
    }
    return g;
}

}  // namespace candela::render
