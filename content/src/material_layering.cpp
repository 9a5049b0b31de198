// withBaseLayer (material.h): how a layered material's base layer becomes its base fields.
#include "candela/content/material.h"

namespace candela::content {

namespace {

// uv' = offset + R * S * (uvScale * uv): the layer's UV scale multiplies the texture's scale.
TextureRef atLayerScale(TextureRef ref, const std::array<float, 2>& uvScale) {
    ref.transform.scale[0] *= uvScale[0];
    ref.transform.scale[1] *= uvScale[1];
    return ref;
}

}  // namespace

Material withBaseLayer(const Material& material) {
    if (!material.layered()) return material;
    Material out = material;
    const MaterialLayer& base = material.layering.layers[0];
    for (int i = 0; i < 3; ++i)
        out.baseColorFactor[size_t(i)] = base.baseColorFactor[size_t(i)];
    out.metallicFactor = base.metallicFactor;
    out.roughnessFactor = base.roughnessFactor;
    out.specular = base.specular;
    out.normalScale = base.normalScale;
    out.baseColorTexture = atLayerScale(base.baseColorTexture, base.uvScale);
    out.baseColorTexture.colorSpace = ColorSpace::Srgb;  // a colour slot, whatever the file says
    out.metallicRoughnessTexture = atLayerScale(base.metallicRoughnessTexture, base.uvScale);
    out.normalTexture = atLayerScale(base.normalTexture, base.uvScale);
    return out;
}

TextureRef layerTexture(const MaterialLayer& layer, const TextureRef& ref) {
    return atLayerScale(ref, layer.uvScale);
}

}  // namespace candela::content
