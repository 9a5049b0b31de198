#version 460
#extension GL_GOOGLE_include_directive : require
#include "volumetrics_bindings.h"
// Froxels, step 3: each pixel reads the integrated grid at its surface's depth (the far
// distance for the background) and attenuates the lit surface behind the medium:
// hdr = hdr * T + L.
#include "common/camera.glsl"
#define FROXEL_INTEGRATED_BINDING VOLUMETRICS_BINDING_FROXEL_INTEGRATED
#include "common/froxel_lookup.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = VOLUMETRICS_BINDING_DEPTH) uniform sampler2D gbufferDepth;
layout(binding = VOLUMETRICS_BINDING_HDR, rgba32f) uniform image2D hdrRadiance;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    uvec2 size = camera.frameInfo.xy;
    if (pixel.x >= int(size.x) || pixel.y >= int(size.y)) return;
    float depth = texelFetch(gbufferDepth, pixel, 0).r;
    // Reverse-Z: view depth = near / depth; 0 is the background.
    float viewDepth = depth > 0.0 ? froxelParams.range.x / depth : froxelParams.range.y;
    // Without the sun's boundaries: where the frame has them, the sun's march adds its own.
    vec4 v = froxelsAt(vec2(pixel) + 0.5, vec2(size), viewDepth, false);
    vec4 surface = imageLoad(hdrRadiance, pixel);
    imageStore(hdrRadiance, pixel, vec4(surface.rgb * v.a + v.rgb, surface.a));
}
