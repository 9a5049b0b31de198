#version 460
#extension GL_GOOGLE_include_directive : require
#include "gbuffer_bindings.h"
// Writes the G-buffer (layout in gbuffer_targets.h) and the emissive radiance into the HDR
// target. Blended materials are drawn by the forward transparency pass instead.
#define MATERIAL_BUFFER_BINDING GBUFFER_BINDING_MATERIALS
#define MATERIAL_TEXTURE_BINDING GBUFFER_BINDING_FIRST_TEXTURE
#include "common/material.glsl"
#include "common/motion_vectors.glsl"

layout(push_constant) uniform Draw {
    mat4 world;
    uint material;
} draw;

layout(location = 0) in vec3 inNormal;
layout(location = 1) in vec4 inTangent;
layout(location = 2) in vec2 inUv0;
layout(location = 3) in vec2 inUv1;
layout(location = 4) in vec4 inColor;
layout(location = 5) in vec4 inCurrentClip;
layout(location = 6) in vec4 inPreviousClip;

layout(location = 0) out vec4 outBaseColor;  // rgb, a = occlusion
layout(location = 1) out vec4 outNormalRoughMetal;  // oct normal xy, roughness, metallic
layout(location = 2) out vec4 outSpecularModel;  // specular, shading model / 255
layout(location = 3) out vec4 outCustomData;
layout(location = 4) out vec4 outEmissive;  // HDR radiance, cd/m^2
layout(location = 5) out vec2 outMotion;    // gbuffer.motion (motion_vectors.glsl)

void main() {
    MaterialUv uv = materialGradients(inUv0, inUv1);
    Material m = materials[draw.material];
    vec4 baseColor = materialBaseColor(m, uv, inColor);
    if (m.alphaCutoff >= 0.0 && baseColor.a < m.alphaCutoff) discard;

    MaterialSample s = evaluateMaterial(m, uv, baseColor, inNormal, inTangent, gl_FrontFacing);
    outBaseColor = vec4(s.baseColor.rgb, s.occlusion);
    outNormalRoughMetal = vec4(octEncode(s.N), s.roughness, s.metallic);
    outSpecularModel = vec4(s.specular, float(s.shadingModel) / 255.0, 0.0, 0.0);
    outCustomData = s.customData;
    outEmissive = vec4(s.emissive, 1.0);
    outMotion = screenMotion(inCurrentClip, inPreviousClip);
}
