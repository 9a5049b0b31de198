#version 460
#extension GL_GOOGLE_include_directive : require
// Writes the G-buffer (layout in gbuffer_layout.h) and the emissive radiance into the HDR target.
#include "common/math.glsl"

struct TextureTransform {
    vec4 matrix;  // 2x2 column-major
    vec2 offset;
    uint texCoord;
    uint present;
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
    uint pad;
    TextureTransform transforms[5];
};

layout(std430, binding = 1) readonly buffer Materials { Material materials[]; };
layout(binding = 2) uniform sampler2D baseColorTexture;
layout(binding = 3) uniform sampler2D metallicRoughnessTexture;
layout(binding = 4) uniform sampler2D normalTexture;
layout(binding = 5) uniform sampler2D occlusionTexture;
layout(binding = 6) uniform sampler2D emissiveTexture;

layout(push_constant) uniform Draw {
    mat4 world;
    uint material;
} draw;

layout(location = 0) in vec3 inNormal;
layout(location = 1) in vec4 inTangent;
layout(location = 2) in vec2 inUv0;
layout(location = 3) in vec2 inUv1;
layout(location = 4) in vec4 inColor;

layout(location = 0) out vec4 outBaseColor;  // rgb, a = occlusion
layout(location = 1) out vec4 outNormalRoughMetal;  // oct normal xy, roughness, metallic
layout(location = 2) out vec4 outSpecularModel;  // specular, shading model / 255
layout(location = 3) out vec4 outCustomData;
layout(location = 4) out vec4 outEmissive;  // HDR radiance, cd/m^2

vec4 uvDx;  // d(uv0, uv1)/dx, set first thing in main()
vec4 uvDy;

// Samples a material slot with explicit gradients: taken from the interpolated UVs once, in
// uniform control flow, so the alpha-test discard and the normal-map branch cannot leave
// implicit derivatives undefined (which showed as sparkles and seams on lavapipe).
vec4 sampleSlot(sampler2D tex, TextureTransform t) {
    mat2 m = mat2(t.matrix.xy, t.matrix.zw);
    bool second = t.texCoord == 1u;
    vec2 uv = m * (second ? inUv1 : inUv0) + t.offset;
    vec2 ddx = m * (second ? uvDx.zw : uvDx.xy);
    vec2 ddy = m * (second ? uvDy.zw : uvDy.xy);
    return textureGrad(tex, uv, ddx, ddy);
}

void main() {
    uvDx = dFdx(vec4(inUv0, inUv1));
    uvDy = dFdy(vec4(inUv0, inUv1));
    Material m = materials[draw.material];
    vec4 baseColor = m.baseColor * inColor * sampleSlot(baseColorTexture, m.transforms[0]);
    if (m.alphaCutoff >= 0.0 && baseColor.a < m.alphaCutoff) discard;

    vec4 metalRough = sampleSlot(metallicRoughnessTexture, m.transforms[1]);
    float roughness = saturate(m.roughness * metalRough.g);
    float metallic = saturate(m.metallic * metalRough.b);
    float occlusion =
        1.0 + m.occlusionStrength * (sampleSlot(occlusionTexture, m.transforms[3]).r - 1.0);

    vec3 N = safeNormalize(inNormal);
    if (!gl_FrontFacing) N = -N;  // double-sided surfaces light their back side
    float tangentLength = dot(inTangent.xyz, inTangent.xyz);
    if (m.transforms[2].present != 0u && tangentLength > 0.0) {
        vec3 T = safeNormalize(inTangent.xyz - N * dot(N, inTangent.xyz));
        vec3 B = cross(N, T) * (inTangent.w < 0.0 ? -1.0 : 1.0);
        vec3 n = sampleSlot(normalTexture, m.transforms[2]).xyz * 2.0 - 1.0;
        n.xy *= m.normalScale;
        N = safeNormalize(mat3(T, B, N) * n);
    }

    vec3 emissive = m.emissive.rgb * sampleSlot(emissiveTexture, m.transforms[4]).rgb;
    outBaseColor = vec4(baseColor.rgb, occlusion);
    outNormalRoughMetal = vec4(octEncode(N), roughness, metallic);
    outSpecularModel = vec4(saturate(m.specular), float(m.shadingModel) / 255.0, 0.0, 0.0);
    outCustomData = clamp(m.customData, 0.0, 1.0);
    outEmissive = vec4(emissive, 1.0);
}
