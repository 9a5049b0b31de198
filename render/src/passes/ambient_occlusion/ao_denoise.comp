#version 460
#extension GL_GOOGLE_include_directive : require
#include "ambient_occlusion_bindings.h"
// Depth- and normal-aware 5x5 blur of GTAO's (bent normal, visibility): averages away the
// per-pixel slice rotation and step jitter without bleeding occlusion across depth edges
// (a box's silhouette against the floor behind it) or creases.
#include "common/ambient_occlusion.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = AO_BINDING_DEPTH) uniform sampler2D gbufferDepth;
layout(binding = AO_BINDING_NORMAL) uniform sampler2D gbufferNormalRoughMetal;
layout(binding = AO_BINDING_INPUT) uniform sampler2D noisyOcclusion;
layout(binding = AO_BINDING_SECOND_OUTPUT, rgba16f) uniform writeonly image2D aoOutput;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(camera.frameInfo.xy);
    if (pixel.x >= size.x || pixel.y >= size.y) return;
    float depth = texelFetch(gbufferDepth, pixel, 0).r;
    vec4 centre = texelFetch(noisyOcclusion, pixel, 0);
    if (depth <= 0.0) {
        imageStore(aoOutput, pixel, centre);
        return;
    }
    vec3 N = octDecode(texelFetch(gbufferNormalRoughMetal, pixel, 0).xy);
    // Reverse-Z: depth is inversely proportional to view distance, so the relative depth
    // difference is the relative distance difference.
    vec4 sum = vec4(0.0);
    float weightSum = 0.0;
    for (int y = -2; y <= 2; ++y) {
        for (int x = -2; x <= 2; ++x) {
            ivec2 q = clamp(pixel + ivec2(x, y), ivec2(0), size - 1);
            float d = texelFetch(gbufferDepth, q, 0).r;
            if (d <= 0.0) continue;
            float relative = abs(d - depth) / depth;
            float depthWeight = exp(-relative * relative * 2500.0);  // ~2% apart: e^-1
            vec3 Nq = octDecode(texelFetch(gbufferNormalRoughMetal, q, 0).xy);
            float normalWeight = pow(saturate(dot(N, Nq)), 8.0);
            float w = depthWeight * normalWeight;
            vec4 value = texelFetch(noisyOcclusion, q, 0);
            sum += vec4(value.xyz, value.w) * w;
            weightSum += w;
        }
    }
    vec4 filtered = sum / max(weightSum, 1e-6);
    vec3 bent = safeNormalize(filtered.xyz);
    if (dot(bent, N) < 0.05) bent = N;
    imageStore(aoOutput, pixel, vec4(bent, saturate(filtered.w)));
}
