#version 460
#extension GL_GOOGLE_include_directive : require
#include "ssr_bindings.h"
// Adds the traced reflection (ssr_trace.comp: confidence x (reflection - the environment's
// split-sum specular)) to the lit HDR radiance: the environment's specular is replaced in
// proportion to the confidence, and stays where rays miss or leave the screen.
#include "common/camera.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = SSR_BINDING_HDR, rgba32f) uniform image2D hdrRadiance;
layout(binding = SSR_BINDING_REFLECTION) uniform sampler2D reflection;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, ivec2(camera.frameInfo.xy)))) return;
    vec4 r = texelFetch(reflection, pixel, 0);
    if (r.a <= 0.0) return;
    vec4 lit = imageLoad(hdrRadiance, pixel);
    imageStore(hdrRadiance, pixel, vec4(max(lit.rgb + r.rgb, vec3(0.0)), lit.a));
}
