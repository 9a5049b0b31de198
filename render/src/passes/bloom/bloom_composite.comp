#version 460
#extension GL_GOOGLE_include_directive : require
#include "bloom_bindings.h"
// Energy-conserving bloom: a fraction `strength` of every pixel's radiance is taken away and
// spread over a wide, normalised point-spread function (the pyramid's levels, upsampled
// bilinearly and averaged with equal weights: each level is a box of 2^(i+1) pixels, together
// a kernel that falls off with distance like a lens's veiling glare). The kernel sums to 1,
// so the frame's total radiance is unchanged: bloom moves light, it adds none.
//   out = (1 - strength) * hdr + strength * psf(hdr)

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = BLOOM_COMPOSITE_BINDING_HDR, rgba32f) uniform image2D hdr;
// One binding per level (bloom_pass.cpp's layout), BLOOM_MAX_LEVELS of them.
layout(binding = BLOOM_COMPOSITE_BINDING_FIRST_LEVEL + 0) uniform sampler2D level0;
layout(binding = BLOOM_COMPOSITE_BINDING_FIRST_LEVEL + 1) uniform sampler2D level1;
layout(binding = BLOOM_COMPOSITE_BINDING_FIRST_LEVEL + 2) uniform sampler2D level2;
layout(binding = BLOOM_COMPOSITE_BINDING_FIRST_LEVEL + 3) uniform sampler2D level3;
layout(binding = BLOOM_COMPOSITE_BINDING_FIRST_LEVEL + 4) uniform sampler2D level4;
layout(binding = BLOOM_COMPOSITE_BINDING_FIRST_LEVEL + 5) uniform sampler2D level5;

layout(push_constant) uniform Push {
    float strength;   // fraction of radiance scattered (a lens's veiling glare: a few percent)
    uint levelCount;  // 1..BLOOM_MAX_LEVELS
} push;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(hdr);
    if (any(greaterThanEqual(pixel, size))) return;
    vec2 uv = (vec2(pixel) + 0.5) / vec2(size);
    vec3 scattered = vec3(0.0);
    scattered += textureLod(level0, uv, 0.0).rgb;
    if (push.levelCount > 1u) scattered += textureLod(level1, uv, 0.0).rgb;
    if (push.levelCount > 2u) scattered += textureLod(level2, uv, 0.0).rgb;
    if (push.levelCount > 3u) scattered += textureLod(level3, uv, 0.0).rgb;
    if (push.levelCount > 4u) scattered += textureLod(level4, uv, 0.0).rgb;
    if (push.levelCount > 5u) scattered += textureLod(level5, uv, 0.0).rgb;
    scattered /= float(push.levelCount);
    vec4 radiance = imageLoad(hdr, pixel);
    imageStore(hdr, pixel, vec4(mix(radiance.rgb, scattered, push.strength), radiance.a));
}
