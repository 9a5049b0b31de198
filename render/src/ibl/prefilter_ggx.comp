#version 460
#extension GL_GOOGLE_include_directive : require
#include "ibl_bindings.h"
// One roughness level of the prefiltered radiance cube (PrefilterEnvMap of Karis 2013, "Real
// Shading in Unreal Engine 4", eq. 7's first sum): GGX importance sampling with n = v = r, NoL
// weights, and filtered importance sampling -- each sample reads the environment mip whose texel
// matches the solid angle the sample stands for -- so a small sample count gives a smooth result.
#include "common/ibl.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = IBL_BINDING_SOURCE) uniform samplerCube environment;  // all mips, trilinear
layout(binding = IBL_BINDING_DESTINATION, rgba16f) uniform writeonly image2DArray destination;

layout(push_constant) uniform Push {
    uint faceSize;      // of the destination mip
    uint sampleCount;
    float roughness;
    float environmentFaceSize;
    float environmentMipCount;
} push;

void main() {
    uvec3 id = gl_GlobalInvocationID;
    if (id.x >= push.faceSize || id.y >= push.faceSize) return;
    vec3 R = cubeFaceDirection(id.z, (vec2(id.xy) + 0.5) / float(push.faceSize));
    float alpha = push.roughness * push.roughness;
    // Roughness 0 is a mirror: the environment itself at this mip's resolution.
    float baseLod = log2(push.environmentFaceSize / float(push.faceSize));
    if (alpha == 0.0) {
        imageStore(destination, ivec3(id), vec4(textureLod(environment, R, baseLod).rgb, 1.0));
        return;
    }
    mat3 frame = tangentFrame(R);
    float texelSolidAngle =
        4.0 * PI / (6.0 * push.environmentFaceSize * push.environmentFaceSize);
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    for (uint i = 0u; i < push.sampleCount; ++i) {
        vec3 H = importanceSampleGgx(hammersley(i, push.sampleCount, vec2(0.0)), alpha);
        float NoH = H.z;
        vec3 L = 2.0 * NoH * H - vec3(0.0, 0.0, 1.0);  // n = v = r: VoH = NoH
        float NoL = L.z;
        if (NoL <= 0.0) continue;
        // pdf(L) = D NoH / (4 VoH) = D / 4; the sample covers 1 / (N pdf) steradians.
        float pdf = distributionGgx(alpha * alpha, NoH) * 0.25;
        float sampleSolidAngle = 1.0 / (float(push.sampleCount) * pdf + 1e-6);
        float lod = clamp(0.5 * log2(sampleSolidAngle / texelSolidAngle) + 1.0, baseLod,
                          push.environmentMipCount - 1.0);
        sum += textureLod(environment, frame * L, lod).rgb * NoL;
        weight += NoL;
    }
    imageStore(destination, ivec3(id), vec4(sum / max(weight, 1e-6), 1.0));
}
