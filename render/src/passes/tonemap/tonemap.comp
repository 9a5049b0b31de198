#version 460
#extension GL_GOOGLE_include_directive : require
// HDR scene radiance -> exposed, tonemapped, sRGB-encoded 8-bit output.
#include "common/color.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba32f) uniform readonly image2D hdrRadiance;
layout(binding = 1, rgba8) uniform writeonly image2D ldrOutput;

layout(push_constant) uniform Push {
    float exposure;  // exposureFromEv100 on the CPU, so one number travels
} push;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, imageSize(hdrRadiance)))) return;
    vec3 radiance = imageLoad(hdrRadiance, pixel).rgb;
    vec3 display = linearToSrgb(tonemapAcesFit(radiance * push.exposure));
    imageStore(ldrOutput, pixel, vec4(display, 1.0));
}
