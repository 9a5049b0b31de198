#version 460
#extension GL_GOOGLE_include_directive : require
#include "ssr_bindings.h"
// One level of the Hi-Z pyramid (Uludag 2014, GPU Pro 5, "Hi-Z Screen-Space Cone-Traced
// Reflections", pass 1): each texel keeps the nearest depth (reverse-Z: the largest value, in r)
// and the farthest (the smallest, in g) of every finer texel it overlaps: Uludag's min-depth quad
// tree, which the trace climbs, and the other end of each cell's depth range, which the
// pre-integration (ssr_visibility.comp) and the cone's intersection test need. Level 0 copies the
// G-buffer depth into both. Sizes halve rounding up, so for an odd size the last texel of a level
// covers one finer texel instead of two: coarse texel i covers finer texels 2i and 2i + 1
// (clamped), and level k's texel i covers exactly the pixels [i 2^k, (i + 1) 2^k) (ssr_trace.comp
// relies on it). Every level lives in one image: level 0 at the origin, level k > 0 stacked in a
// column right of it (ssr_levels.glsl).
#include "ssr_levels.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = SSR_BINDING_DEPTH) uniform sampler2D gbufferDepth;
layout(binding = SSR_BINDING_HIZ, rgba32f) uniform image2D hiz;

layout(push_constant) uniform Push {
    uint level;
} push;

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    SsrLevel here = ssrLevel(push.level);
    if (any(greaterThanEqual(texel, here.size))) return;
    if (push.level == 0u) {
        float depth = texelFetch(gbufferDepth, texel, 0).r;
        imageStore(hiz, texel, vec4(depth, depth, 0.0, 0.0));
        return;
    }
    SsrLevel finer = ssrLevel(push.level - 1u);
    ivec2 a = texel * 2;
    ivec2 b = min(a + 1, finer.size - 1);
    vec2 c00 = imageLoad(hiz, finer.origin + a).rg;
    vec2 c10 = imageLoad(hiz, finer.origin + ivec2(b.x, a.y)).rg;
    vec2 c01 = imageLoad(hiz, finer.origin + ivec2(a.x, b.y)).rg;
    vec2 c11 = imageLoad(hiz, finer.origin + b).rg;
    float nearest = max(max(c00.x, c10.x), max(c01.x, c11.x));
    float farthest = min(min(c00.y, c10.y), min(c01.y, c11.y));
    imageStore(hiz, here.origin + texel, vec4(nearest, farthest, 0.0, 0.0));
}
