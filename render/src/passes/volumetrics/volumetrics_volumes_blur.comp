#version 460
#extension GL_GOOGLE_include_directive : require
#include "volumetrics_bindings.h"
// Per-light volumes, step 2 (Vos 2014, GPU Pro 5, "Volumetric Light Effects in Killzone: Shadow
// Fall"): a bilateral blur of the half-resolution march. The kernel is 1 2 2 2 1 each way, which
// weighs the four Bayer offsets of every row and column equally (the two ends share one), so it
// cancels the dither where the depth is smooth; the depth term keeps a surface's fog from bleeding
// onto another's.
#include "volumetrics_push.glsl"
#include "common/camera.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = VOLUMETRICS_BINDING_VOLUMES_MARCHED, rgba32f) uniform readonly image2D marched;
layout(binding = VOLUMETRICS_BINDING_VOLUMES_BLURRED, rgba32f) uniform writeonly image2D blurred;

// Weight of a neighbour at view depth z beside the centre at z0: falls off over 5% of z0.
float depthWeight(float z, float z0) {
    float r = (z - z0) / (0.05 * z0 + 1e-3);
    return exp(-r * r);
}

void main() {
    ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    ivec2 halfSize = (ivec2(camera.frameInfo.xy) + 1) / 2;
    if (q.x >= halfSize.x || q.y >= halfSize.y) return;
    const float kTaps[5] = float[5](1.0, 2.0, 2.0, 2.0, 1.0);
    float z0 = imageLoad(marched, q).a;
    vec3 sum = vec3(0.0);
    float weights = 0.0;
    for (int y = -2; y <= 2; ++y) {
        for (int x = -2; x <= 2; ++x) {
            ivec2 n = clamp(q + ivec2(x, y), ivec2(0), halfSize - 1);
            vec4 v = imageLoad(marched, n);
            float w = kTaps[x + 2] * kTaps[y + 2] * depthWeight(v.a, z0);
            sum += v.rgb * w;
            weights += w;
        }
    }
    imageStore(blurred, q, vec4(sum / weights, z0));
}
