// Material evaluation shared by the G-buffer pass and the forward transparency pass, so an
// opaque and a blended surface with the same material get the same inputs. The including
// shader defines MATERIAL_BUFFER_BINDING (the std430 material array, render/src/
// gpu_material.h) and MATERIAL_TEXTURE_BINDING (the first of the slot samplers, in
// TextureSlot order) before including this file.
#ifndef CANDELA_MATERIAL_GLSL
#define CANDELA_MATERIAL_GLSL

#include "common/math.glsl"
#include "common/specialization_ids.h"

// The texture slots the pipeline's draws may have (bit i: TextureSlot i). A slot outside it
// holds the white default, so its lookup (1.0) is left out: lavapipe runs both sides of a
// branch, and four textureGrad calls per fragment were most of an untextured G-buffer.
layout(constant_id = SPEC_MATERIAL_TEXTURE_SLOTS) const uint kMaterialTextureSlots = 0xffffffffu;
bool slotInPipeline(uint slot) { return (kMaterialTextureSlots & (1u << slot)) != 0u; }

struct TextureTransform {
    vec4 matrix;  // 2x2 column-major
    vec2 offset;
    uint texCoord;
    uint present;
};

// One layer over a layered material's base (gpu_material.h GpuMaterialLayer).
struct MaterialLayer {
    vec4 baseColor;
    vec4 parameters;  // metallic, roughness, specular, normal scale
    TextureTransform transforms[3];  // base colour, metallic-roughness, normal
};

struct Material {
    vec4 baseColor;
    vec4 emissive;
    vec4 customData;
    float metallic;
    float roughness;
    float specular;
    float normalScale;
    float occlusionStrength;
    float alphaCutoff;
    uint shadingModel;
    float cavity;  // see gpu_material.h
    vec4 specularColorScale;  // see gpu_material.h
    vec4 anisotropy;  // strength, cos(rotation), sin(rotation)
    vec4 clearcoat;   // factor, roughness, normal scale
    TextureTransform transforms[11];
    vec4 layering;  // layers over the base (0..3), 1: vertex-colour mask (material_layers.glsl)
    TextureTransform maskTransform;
    MaterialLayer layers[3];
};

layout(std430, binding = MATERIAL_BUFFER_BINDING) readonly buffer Materials {
    Material materials[];
};
layout(binding = MATERIAL_TEXTURE_BINDING + 0) uniform sampler2D baseColorTexture;
layout(binding = MATERIAL_TEXTURE_BINDING + 1) uniform sampler2D metallicRoughnessTexture;
layout(binding = MATERIAL_TEXTURE_BINDING + 2) uniform sampler2D normalTexture;
layout(binding = MATERIAL_TEXTURE_BINDING + 3) uniform sampler2D occlusionTexture;
layout(binding = MATERIAL_TEXTURE_BINDING + 4) uniform sampler2D emissiveTexture;
layout(binding = MATERIAL_TEXTURE_BINDING + 5) uniform sampler2D specularTexture;
layout(binding = MATERIAL_TEXTURE_BINDING + 6) uniform sampler2D specularColorTexture;
layout(binding = MATERIAL_TEXTURE_BINDING + 7) uniform sampler2D anisotropyTexture;
layout(binding = MATERIAL_TEXTURE_BINDING + 8) uniform sampler2D clearcoatTexture;
layout(binding = MATERIAL_TEXTURE_BINDING + 9) uniform sampler2D clearcoatRoughnessTexture;
layout(binding = MATERIAL_TEXTURE_BINDING + 10) uniform sampler2D clearcoatNormalTexture;

// A material evaluated at one fragment.
struct MaterialSample {
    vec4 baseColor;  // rgb, a = coverage (alpha)
    float roughness;
    float metallic;
    float specular;
    float occlusion;
    vec3 N;  // shading normal (normal map applied, flipped on back faces)
    vec3 emissive;  // cd/m^2
    vec4 customData;
    uint shadingModel;
};

// KHR_materials_anisotropy and KHR_materials_clearcoat at one fragment (evaluateMaterialLayers
// below): only the G-buffer variant that has targets for them evaluates these.
struct MaterialExtensions {
    float anisotropy;     // strength, 0: isotropic
    vec3 anisotropyT;     // unit direction of the stretched lobe, orthogonal to the shading N
    float clearCoat;      // 0: no coat
    float clearCoatRoughness;
    vec3 clearCoatN;      // the coat's own normal (its normal map, else the geometric normal)
};

// UV gradients, taken once per fragment in uniform control flow (materialGradients), so the
// alpha-test discard and the normal-map branch cannot leave implicit derivatives undefined
// (which showed as sparkles and seams on lavapipe).
struct MaterialUv {
    vec4 uv;  // uv0, uv1
    vec4 dx;
    vec4 dy;
};

MaterialUv materialGradients(vec2 uv0, vec2 uv1) {
    MaterialUv m;
    m.uv = vec4(uv0, uv1);
    m.dx = dFdx(m.uv);
    m.dy = dFdy(m.uv);
    return m;
}

vec4 sampleSlot(sampler2D tex, TextureTransform t, MaterialUv uv) {
    mat2 m = mat2(t.matrix.xy, t.matrix.zw);
    bool second = t.texCoord == 1u;
    vec2 coord = m * (second ? uv.uv.zw : uv.uv.xy) + t.offset;
    vec2 ddx = m * (second ? uv.dx.zw : uv.dx.xy);
    vec2 ddy = m * (second ? uv.dy.zw : uv.dy.xy);
    return textureGrad(tex, coord, ddx, ddy);
}

// Base colour with vertex colour: what the alpha test and blending read.
vec4 materialBaseColor(Material m, MaterialUv uv, vec4 vertexColor) {
    vec4 texel = slotInPipeline(0u) ? sampleSlot(baseColorTexture, m.transforms[0], uv) : vec4(1.0);
    return m.baseColor * vertexColor * texel;
}

// Everything but the base colour (pass materialBaseColor's result in).
MaterialSample evaluateMaterial(Material m, MaterialUv uv, vec4 baseColor, vec3 normal,
                                vec4 tangent, bool frontFacing) {
    MaterialSample s;
    s.baseColor = baseColor;
    vec4 metalRough =
        slotInPipeline(1u) ? sampleSlot(metallicRoughnessTexture, m.transforms[1], uv) : vec4(1.0);
    s.roughness = saturate(m.roughness * metalRough.g);
    s.metallic = saturate(m.metallic * metalRough.b);
    float occlusion =
        slotInPipeline(3u) ? sampleSlot(occlusionTexture, m.transforms[3], uv).r : 1.0;
    s.occlusion = 1.0 + m.occlusionStrength * (occlusion - 1.0);
    // Cavity joins the occlusion texture by the same rule AO uses: the minimum (both describe
    // the same small-scale shadowing; the product would count it twice). Cavity 1: unchanged.
    s.occlusion = min(s.occlusion, m.cavity);

    vec3 N = safeNormalize(normal);
    if (!frontFacing) N = -N;  // double-sided surfaces light their back side
    float tangentLength = dot(tangent.xyz, tangent.xyz);
    if (slotInPipeline(2u) && m.transforms[2].present != 0u && tangentLength > 0.0) {
        vec3 T = safeNormalize(tangent.xyz - N * dot(N, tangent.xyz));
        vec3 B = cross(N, T) * (tangent.w < 0.0 ? -1.0 : 1.0);
        vec3 n = sampleSlot(normalTexture, m.transforms[2], uv).xyz * 2.0 - 1.0;
        n.xy *= m.normalScale;
        N = safeNormalize(mat3(T, B, N) * n);
    }
    s.N = N;
    vec3 emissive =
        slotInPipeline(4u) ? sampleSlot(emissiveTexture, m.transforms[4], uv).rgb : vec3(1.0);
    s.emissive = m.emissive.rgb * emissive;
    // KHR_materials_specular: glTF's dielectric F0 = 0.04 * specularFactor * specularTexture.a *
    // specularColorFactor * specularColorTexture.rgb; the engine's F0 = 0.08 * specular with one
    // scalar, so the colour's largest channel is taken (as the loader does for the factors).
    // The slots are sampled only when the material has the texture (uniform per draw).
    float specular = m.specular;
    if (slotInPipeline(5u) && m.transforms[5].present != 0u) {
        specular *= sampleSlot(specularTexture, m.transforms[5], uv).a;
    }
    if (slotInPipeline(6u) && m.transforms[6].present != 0u) {
        vec3 c = m.specularColorScale.rgb * sampleSlot(specularColorTexture, m.transforms[6], uv).rgb;
        specular *= max(c.r, max(c.g, c.b));
    }
    s.specular = saturate(specular);
    s.customData = clamp(m.customData, 0.0, 1.0);
    s.shadingModel = m.shadingModel;
    return s;
}

// The anisotropy direction and the clear coat. `tangent` as evaluateMaterial's; `N` the shading
// normal it returned (the stretched direction is made orthogonal to it, as KHR's
// anisotropicB = cross(N, anisotropicT) implies).
MaterialExtensions evaluateMaterialExtensions(Material m, MaterialUv uv, vec3 normal,
                                              vec4 tangent, bool frontFacing, vec3 N) {
    MaterialExtensions e;
    vec3 geometricN = safeNormalize(normal);
    if (!frontFacing) geometricN = -geometricN;
    vec3 T, B;
    if (dot(tangent.xyz, tangent.xyz) > 0.0) {
        T = safeNormalize(tangent.xyz - geometricN * dot(geometricN, tangent.xyz));
        B = cross(geometricN, T) * (tangent.w < 0.0 ? -1.0 : 1.0);
    } else {
        mat3 frame = tangentFrame(geometricN);
        T = frame[0];
        B = frame[1];
    }

    // KHR_materials_anisotropy: direction = rotation(anisotropyRotation) * (texture.rg * 2 - 1),
    // (1, 0) without a texture; strength *= texture.b.
    e.anisotropy = m.anisotropy.x;
    vec2 direction = vec2(1.0, 0.0);
    if (slotInPipeline(7u) && m.transforms[7].present != 0u) {
        vec3 t = sampleSlot(anisotropyTexture, m.transforms[7], uv).rgb;
        direction = t.rg * 2.0 - 1.0;
        e.anisotropy *= t.b;
    }
    direction = mat2(m.anisotropy.y, m.anisotropy.z, -m.anisotropy.z, m.anisotropy.y) * direction;
    vec3 stretched = T * direction.x + B * direction.y;
    stretched -= N * dot(N, stretched);
    e.anisotropy = dot(stretched, stretched) > 1e-12 ? saturate(e.anisotropy) : 0.0;
    e.anisotropyT = safeNormalize(stretched);

    e.clearCoat = m.clearcoat.x;
    if (slotInPipeline(8u) && m.transforms[8].present != 0u) {
        e.clearCoat *= sampleSlot(clearcoatTexture, m.transforms[8], uv).r;
    }
    e.clearCoat = saturate(e.clearCoat);
    e.clearCoatRoughness = m.clearcoat.y;
    if (slotInPipeline(9u) && m.transforms[9].present != 0u) {
        e.clearCoatRoughness *= sampleSlot(clearcoatRoughnessTexture, m.transforms[9], uv).g;
    }
    e.clearCoatRoughness = saturate(e.clearCoatRoughness);
    e.clearCoatN = geometricN;
    if (slotInPipeline(10u) && m.transforms[10].present != 0u) {
        vec3 n = sampleSlot(clearcoatNormalTexture, m.transforms[10], uv).xyz * 2.0 - 1.0;
        n.xy *= m.clearcoat.z;
        e.clearCoatN = safeNormalize(mat3(T, B, geometricN) * n);
    }
    return e;
}

#endif
