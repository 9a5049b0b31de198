#version 460
#extension GL_GOOGLE_include_directive : require
#include "tonemap_bindings.h"
// HDR scene radiance -> exposed, tonemapped, sRGB-encoded 8-bit output.
#include "common/color.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = TONEMAP_BINDING_HDR, rgba32f) uniform readonly image2D hdrRadiance;
layout(binding = TONEMAP_BINDING_LDR, rgba8) uniform writeonly image2D ldrOutput;

layout(push_constant) uniform Push {
    float exposure;  // exposureFromEv100 on the CPU, so one number travels
} push;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, imageSize(hdrRadiance)))) return;
    vec3 radiance = imageLoad(hdrRadiance, pixel).rgb;
    // Robust for any finite radiance and exposure: an exposure that overflowed to Inf (EV100
    // below about -127) would turn black texels into 0 * Inf = NaN, so it is capped at the
    // largest float, and the exposed value is capped where the ACES curve has long saturated
    // (it reaches 1.0 at 7.25) so that x * x inside the fit cannot overflow to Inf / Inf.
    // Both caps leave every value below them, and so every ordinary frame, bit for bit alone.
    const float kLargestFloat = 3.402823466e38;
    const float kSaturated = 64.0;
    vec3 exposed = min(radiance * min(push.exposure, kLargestFloat), vec3(kSaturated));
    vec3 display = linearToSrgb(tonemapAcesFit(exposed));
    imageStore(ldrOutput, pixel, vec4(display, 1.0));
}
