// Material layers (content::MaterialLayering, Karis 2013, "Real Shading in Unreal Engine 4",
// "Material Layering") blended in the G-buffer pass, before lighting: the blended parameters are
// what the G-buffer stores, so the lighting pass costs the same whatever the layer count. Compiled
// only into the G-buffer's layered variants (gbuffer_layered.frag, gbuffer_extended_layered.frag),
// which frames with a layered material use; the including shader defines
// MATERIAL_LAYER_TEXTURE_BINDING (the mask, then base colour, metallic-roughness and normal of
// layers 1, 2 and 3: LayerTextureSlot order).
#ifndef CANDELA_MATERIAL_LAYERS_GLSL
#define CANDELA_MATERIAL_LAYERS_GLSL

#include "common/material.glsl"

layout(binding = MATERIAL_LAYER_TEXTURE_BINDING + 0) uniform sampler2D layerMaskTexture;
layout(binding = MATERIAL_LAYER_TEXTURE_BINDING + 1) uniform sampler2D layer1BaseColorTexture;
layout(binding = MATERIAL_LAYER_TEXTURE_BINDING + 2) uniform sampler2D layer1MetallicRoughnessTexture;
layout(binding = MATERIAL_LAYER_TEXTURE_BINDING + 3) uniform sampler2D layer1NormalTexture;
layout(binding = MATERIAL_LAYER_TEXTURE_BINDING + 4) uniform sampler2D layer2BaseColorTexture;
layout(binding = MATERIAL_LAYER_TEXTURE_BINDING + 5) uniform sampler2D layer2MetallicRoughnessTexture;
layout(binding = MATERIAL_LAYER_TEXTURE_BINDING + 6) uniform sampler2D layer2NormalTexture;
layout(binding = MATERIAL_LAYER_TEXTURE_BINDING + 7) uniform sampler2D layer3BaseColorTexture;
layout(binding = MATERIAL_LAYER_TEXTURE_BINDING + 8) uniform sampler2D layer3MetallicRoughnessTexture;
layout(binding = MATERIAL_LAYER_TEXTURE_BINDING + 9) uniform sampler2D layer3NormalTexture;

bool vertexColorMasks(Material m) {
    return m.layering.x > 0.0 && m.layering.y > 0.5;
}

// The vertex colour's part in the base colour: none when it is the layers' mask.
vec4 layeredVertexTint(Material m, vec4 vertexColor) {
    return vertexColorMasks(m) ? vec4(1.0) : vertexColor;
}

// Blends one layer over `s` by weight w. Each layer samples its own textures at its own UV
// scale (folded into its transforms), the mask at the mask's: Karis 2013's "different
// frequencies". All reads use explicit gradients, so skipping a zero-weight layer is safe.
void blendLayer(inout MaterialSample s, MaterialLayer l, float w, sampler2D baseColorMap,
                sampler2D metallicRoughnessMap, sampler2D normalMap, MaterialUv uv,
                vec3 geometricN, vec4 tangent) {
    if (w <= 0.0) return;
    vec3 baseColor = l.baseColor.rgb * sampleSlot(baseColorMap, l.transforms[0], uv).rgb;
    vec4 metalRough = sampleSlot(metallicRoughnessMap, l.transforms[1], uv);
    vec3 N = geometricN;
    if (l.transforms[2].present != 0u && dot(tangent.xyz, tangent.xyz) > 0.0) {
        vec3 T = safeNormalize(tangent.xyz - N * dot(N, tangent.xyz));
        vec3 B = cross(N, T) * (tangent.w < 0.0 ? -1.0 : 1.0);
        vec3 n = sampleSlot(normalMap, l.transforms[2], uv).xyz * 2.0 - 1.0;
        n.xy *= l.parameters.w;
        N = safeNormalize(mat3(T, B, N) * n);
    }
    // Linear parameters blend linearly (Karis 2013: "a small linear material parameter set");
    // w = 1 gives the layer's own values exactly.
    s.baseColor.rgb = mix(s.baseColor.rgb, baseColor, w);
    s.metallic = mix(s.metallic, saturate(l.parameters.x * metalRough.b), w);
    s.roughness = mix(s.roughness, saturate(l.parameters.y * metalRough.g), w);
    s.specular = mix(s.specular, saturate(l.parameters.z), w);
    s.N = w >= 1.0 ? N : safeNormalize(mix(s.N, N, w));
}

// Layers 1..3 over the base sample `s` (evaluateMaterial's, which already holds layer 0), by
// the mask's R, G and B (texture or vertex colour), each over the result of those below.
void blendMaterialLayers(inout MaterialSample s, Material m, MaterialUv uv, vec4 vertexColor,
                         vec3 normal, vec4 tangent, bool frontFacing) {
    int count = int(m.layering.x + 0.5);
    if (count <= 0) return;
    vec3 mask = vertexColorMasks(m) ? vertexColor.rgb
                                    : sampleSlot(layerMaskTexture, m.maskTransform, uv).rgb;
    mask = clamp(mask, 0.0, 1.0);
    vec3 geometricN = safeNormalize(normal);
    if (!frontFacing) geometricN = -geometricN;
    blendLayer(s, m.layers[0], mask.r, layer1BaseColorTexture, layer1MetallicRoughnessTexture,
               layer1NormalTexture, uv, geometricN, tangent);
    if (count < 2) return;
    blendLayer(s, m.layers[1], mask.g, layer2BaseColorTexture, layer2MetallicRoughnessTexture,
               layer2NormalTexture, uv, geometricN, tangent);
    if (count < 3) return;
    blendLayer(s, m.layers[2], mask.b, layer3BaseColorTexture, layer3MetallicRoughnessTexture,
               layer3NormalTexture, uv, geometricN, tangent);
}

#endif
