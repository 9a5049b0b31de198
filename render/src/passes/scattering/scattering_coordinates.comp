#version 460
#extension GL_GOOGLE_include_directive : require
#include "scattering_bindings.h"
// Light shafts, step 1 (Yusov 2014, GPU Pro 5, "High Performance Outdoor Light Scattering Using
// Epipolar Sampling"): the epipolar samples. Each sample of each slice gets its pixel position,
// evenly spaced from the slice's entry to its exit point, and the view distance there from the
// depth buffer. The first sample of a slice also stores the slice's end points and, per cascade,
// the line its plane cuts from the cascade's map, which the trees (scattering_tree.comp) are built
// along.
#include "scattering_epipolar.glsl"
#include "scattering_march.glsl"

layout(local_size_x = 64) in;

layout(binding = SCATTERING_BINDING_DEPTH) uniform sampler2D gbufferDepth;
layout(binding = SCATTERING_BINDING_COORDINATES, rgba32f) uniform writeonly image2D coordinates;
layout(std430, binding = SCATTERING_BINDING_SLICES) writeonly buffer Slices {
    SliceInfo slices[];
};

// The line of the slice whose rays include `direction` in cascade v: the projection of the
// camera (texels) and the unit direction the rays' projections run along, moved up to where it
// enters the tile (before it nothing blocks).
vec4 cascadeLine(ShadowView v, vec3 direction) {
    vec3 from = cascadeTexelDepth(v, camera.cameraPosition.xyz);
    vec3 to = cascadeTexelDepth(v, camera.cameraPosition.xyz + direction);
    vec2 d = to.xy - from.xy;
    vec2 e = dot(d, d) > 1e-12 ? normalize(d) : vec2(1.0, 0.0);
    vec2 slab = screenSlab(from.xy, e, vec2(v.tile.z));
    float enter = slab.x <= slab.y ? max(slab.x, 0.0) : 0.0;
    return vec4(from.xy + e * enter, e);
}

void main() {
    uint sampleIndex = gl_GlobalInvocationID.x;
    uint slice = gl_GlobalInvocationID.y;
    uint samples = push.epipolar.y;
    if (sampleIndex >= samples || slice >= push.epipolar.x) return;
    vec2 size = vec2(camera.frameInfo.xy);
    vec2 entry, exitPoint;
    bool valid = sliceLine(slice, push.epipolar.x, push.sun.xy, size, entry, exitPoint);
    vec2 position = mix(entry, exitPoint, float(sampleIndex) / float(samples - 1u));
    position = clamp(position, vec2(0.5), size - 0.5);
    ivec2 pixel = ivec2(floor(position));
    float perDepth;
    vec3 direction = pixelRay(position, perDepth);
    float distance = rayDistance(texelFetch(gbufferDepth, pixel, 0).r, perDepth);
    imageStore(coordinates, ivec2(sampleIndex, slice),
               vec4(position, distance, valid ? 1.0 : 0.0));
    if (sampleIndex != 0u) return;
    SliceInfo info;
    info.endpoints = vec4(entry, exitPoint);
    info.flags = vec4(0.0, 0.0, 0.0, valid ? 1.0 : 0.0);
    float unused;
    vec3 exitRay = pixelRay(clamp(exitPoint, vec2(0.5), size - 0.5), unused);
    uvec2 views = kShadowsEnabled && push.lights.w != 0u ? shadowLights[push.lights.x]
                                                         : uvec2(SHADOW_NO_VIEW, 0u);
    for (uint c = 0u; c < SHADOW_MAX_CASCADES; ++c) {
        info.lines[c] = views.x != SHADOW_NO_VIEW && c < views.y
                            ? cascadeLine(shadowViews[views.x + c], exitRay)
                            : vec4(0.0, 0.0, 1.0, 0.0);
    }
    slices[slice] = info;
}
