#version 460
#extension GL_GOOGLE_include_directive : require
#include "scattering_bindings.h"
// Light shafts, step 3 (Yusov 2014, GPU Pro 5, "High Performance Outdoor Light Scattering Using
// Epipolar Sampling"; Yusov 2013 section 4): per slice and cascade, the blocker depths along the
// line the slice's plane cuts from the cascade's map, one per texel (the 1D height map every view
// ray of the slice is compared with), and above them the min/max binary tree: node j of level L
// holds the least and greatest depth of leaves j 2^L .. (j + 1) 2^L - 1. One invocation per row
// builds it bottom-up (M + M - 1 loop iterations, under lavapipe's limit of 65,535).
#include "scattering_march.glsl"

layout(local_size_x = 64) in;

layout(binding = SCATTERING_BINDING_TREE, rg32f) uniform image2D tree;
layout(std430, binding = SCATTERING_BINDING_SLICES) readonly buffer Slices {
    SliceInfo slices[];
};

void main() {
    uint row = gl_GlobalInvocationID.x;
    uint slice = row / SHADOW_MAX_CASCADES;
    uint cascade = row % SHADOW_MAX_CASCADES;
    if (slice >= push.epipolar.x || !kShadowsEnabled || push.lights.w == 0u) return;
    uvec2 views = shadowLights[push.lights.x];
    if (views.x == SHADOW_NO_VIEW || cascade >= views.y) return;
    ShadowView v = shadowViews[views.x + cascade];
    vec4 line = slices[slice].lines[cascade];
    int leaves = int(push.epipolar.w);
    float size = v.tile.z;
    for (int i = 0; i < leaves; ++i) {
        vec2 p = line.xy + line.zw * (float(i) + 0.5);
        float depth = kNoBlocker;
        if (all(greaterThanEqual(p, vec2(0.0))) && all(lessThan(p, vec2(size))))
            depth = shadowBlockerDepth(v, ivec2(floor(v.tile.xy + p)));
        imageStore(tree, ivec2(i, row), vec4(depth, depth, 0.0, 0.0));
    }
    int below = 0;  // where the level below starts
    for (int width = leaves / 2, offset = leaves; width >= 1; offset += width, width /= 2) {
        for (int j = 0; j < width; ++j) {
            vec2 l = imageLoad(tree, ivec2(below + 2 * j, row)).rg;
            vec2 r = imageLoad(tree, ivec2(below + 2 * j + 1, row)).rg;
            imageStore(tree, ivec2(offset + j, row), vec4(min(l.x, r.x), max(l.y, r.y), 0, 0));
        }
        below = offset;
    }
}
