#version 460
#extension GL_GOOGLE_include_directive : require
#include "ssr_bindings.h"
// One level of the Hi-Z pyramid (seed 004 section 4, pass 1): each texel keeps the nearest
// depth (reverse-Z: the largest value) of every finer texel it overlaps. Level 0 copies the
// G-buffer depth. Sizes halve rounding up, so for an odd size the last texel of a level covers
// one finer texel instead of two: coarse texel i covers finer texels 2i and 2i + 1 (clamped),
// and level k's texel i covers exactly the pixels [i 2^k, (i + 1) 2^k) (ssr_trace.comp relies
// on it). Every level lives in one image: level 0 at the origin, level k > 0 stacked in a
// column right of it (ssr_levels.glsl).
#include "ssr_levels.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = SSR_BINDING_DEPTH) uniform sampler2D gbufferDepth;
layout(binding = SSR_BINDING_HIZ, r32f) uniform image2D hiz;

layout(push_constant) uniform Push {
    uint level;
} push;

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    SsrLevel here = ssrLevel(push.level);
    if (any(greaterThanEqual(texel, here.size))) return;
    if (push.level == 0u) {
        imageStore(hiz, texel, vec4(texelFetch(gbufferDepth, texel, 0).r));
        return;
    }
    SsrLevel finer = ssrLevel(push.level - 1u);
    ivec2 a = texel * 2;
    ivec2 b = min(a + 1, finer.size - 1);
    float nearest = max(max(imageLoad(hiz, finer.origin + a).r,
                            imageLoad(hiz, finer.origin + ivec2(b.x, a.y)).r),
                        max(imageLoad(hiz, finer.origin + ivec2(a.x, b.y)).r,
                            imageLoad(hiz, finer.origin + b).r));
    imageStore(hiz, here.origin + texel, vec4(nearest));
}
