#version 460
#extension GL_GOOGLE_include_directive : require
#include "ibl_bindings.h"
// Projects the environment onto order-2 spherical harmonics and convolves with the clamped
// cosine, giving diffuse irradiance E(n) = sum A_l L_lm Y_lm(n) (Ramamoorthi and Hanrahan).
// One workgroup: every thread sums a stride of the texels of one small mip, then the
// workgroup reduces. Weights are normalised so the solid angles sum to exactly 4 pi: a
// uniform environment of radiance L gives E = pi L at every n (the white furnace).
#include "common/ibl.glsl"

layout(local_size_x = 64) in;

layout(binding = IBL_BINDING_SOURCE) uniform samplerCube environment;
layout(std430, binding = IBL_BINDING_DESTINATION) writeonly buffer Coefficients {
    vec4 coefficients[9];
};

layout(push_constant) uniform Push {
    uint faceSize;  // of the mip read
    float lod;
} push;

shared vec3 partial[64][9];
shared float partialWeight[64];

void main() {
    uint thread = gl_LocalInvocationIndex;
    vec3 sum[9];
    for (int k = 0; k < 9; ++k) sum[k] = vec3(0.0);
    float weight = 0.0;
    uint texels = 6u * push.faceSize * push.faceSize;
    for (uint t = thread; t < texels; t += 64u) {
        uint face = t / (push.faceSize * push.faceSize);
        uint inFace = t % (push.faceSize * push.faceSize);
        vec2 st = (vec2(inFace % push.faceSize, inFace / push.faceSize) + 0.5) /
                  float(push.faceSize);
        vec3 d = cubeFaceDirection(face, st);
        float w = cubeTexelSolidAngle(st * 2.0 - 1.0, float(push.faceSize));
        vec3 radiance = textureLod(environment, d, push.lod).rgb;
        float y[9];
        shBasis9(d, y);
        for (int k = 0; k < 9; ++k) sum[k] += radiance * (y[k] * w);
        weight += w;
    }
    for (int k = 0; k < 9; ++k) partial[thread][k] = sum[k];
    partialWeight[thread] = weight;
    barrier();
    for (uint stride = 32u; stride > 0u; stride >>= 1u) {
        if (thread < stride) {
            for (int k = 0; k < 9; ++k) partial[thread][k] += partial[thread + stride][k];
            partialWeight[thread] += partialWeight[thread + stride];
        }
        barrier();
    }
    if (thread < 9u) {
        const float bandConvolution[3] = float[3](PI, 2.0 * PI / 3.0, PI / 4.0);
        uint band = thread == 0u ? 0u : (thread < 4u ? 1u : 2u);
        float normalisation = 4.0 * PI / partialWeight[0];
        coefficients[thread] =
            vec4(partial[0][thread] * normalisation * bandConvolution[band], 0.0);
    }
}
