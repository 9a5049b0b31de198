#version 460
#extension GL_GOOGLE_include_directive : require
#include "ssr_bindings.h"
// Pre-integration of the Hi-Z pyramid (Uludag 2014, GPU Pro 5, "Hi-Z Screen-Space Cone-Traced
// Reflections", pass 2): the visibility of each cell, the share of the volume between the cell's
// nearest and farthest depth (the pyramid's r and g, ssr_hiz.comp) that lies in front of the
// surfaces it holds, so a cone can see through it. A level-0 cell is one surface: 100%. A coarser
// cell averages, over the four finer cells it covers, the share of its own depth range in front of
// each finer cell's nearest surface, times that cell's own visibility: Visibility(n) <=
// Visibility(n - 1), e.g. 50% at level 1 and (1 - 0.25) x 50% = 37.5% at level 2 for Uludag's
// example. Depths are compared as view distances (reverse-Z with an infinite far plane: distance =
// near / depth; the near plane cancels out of the share), the sky (depth 0) infinitely far. A cell
// whose surfaces all lie at one depth holds no volume: its visibility is its finer cells'. Same
// layout as the Hi-Z pyramid (ssr_levels.glsl); ssr_trace.comp weights its cone samples by it
// (pass 5).
#include "ssr_levels.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = SSR_BINDING_HIZ, rgba32f) uniform readonly image2D hiz;
layout(binding = SSR_BINDING_VISIBILITY, r32f) uniform image2D visibility;

layout(push_constant) uniform Push {
    uint level;
} push;

// Proportional to the view distance of a reverse-Z depth; the sky's 0 is as far as a float
// allows without overflowing the differences below.
float distanceOf(float depth) {
    return 1.0 / max(depth, 1e-30);
}

// The share of [nearest, farthest] in front of `surface`, times the finer cell's visibility.
float emptyShare(vec2 cellRange, ivec2 finerTexel, SsrLevel finer) {
    float surface = distanceOf(imageLoad(hiz, finer.origin + finerTexel).r);
    float seen = imageLoad(visibility, finer.origin + finerTexel).r;
    float nearest = distanceOf(cellRange.x);
    float depthRange = distanceOf(cellRange.y) - nearest;
    if (depthRange <= 1e-6 * nearest) return seen;  // one depth: no volume to see through
    return clamp((surface - nearest) / depthRange, 0.0, 1.0) * seen;
}

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    SsrLevel here = ssrLevel(push.level);
    if (any(greaterThanEqual(texel, here.size))) return;
    if (push.level == 0u) {
        imageStore(visibility, texel, vec4(1.0));
        return;
    }
    SsrLevel finer = ssrLevel(push.level - 1u);
    vec2 cellRange = imageLoad(hiz, here.origin + texel).rg;  // (nearest, farthest) depth
    // The finer cells this one covers (the last of an odd size counts its one cell twice, as
    // ssr_hiz.comp and ssr_color.comp do).
    ivec2 a = texel * 2;
    ivec2 b = min(a + 1, finer.size - 1);
    float sum = emptyShare(cellRange, a, finer) + emptyShare(cellRange, ivec2(b.x, a.y), finer) +
                emptyShare(cellRange, ivec2(a.x, b.y), finer) + emptyShare(cellRange, b, finer);
    imageStore(visibility, here.origin + texel, vec4(sum * 0.25));
}
