#version 460
#extension GL_GOOGLE_include_directive : require
#include "ssr_bindings.h"
// Pre-convolution of the lit scene (Uludag 2014, GPU Pro 5, "Hi-Z Screen-Space Cone-Traced
// Reflections", pass 4): level 0 copies the HDR radiance, each coarser level averages the 2x2 finer
// texels it covers (the last texel of an odd size repeats its one neighbour, so its average is of
// the texels it really covers), the same layout as the Hi-Z pyramid (ssr_levels.glsl). A level is
// the scene blurred over 2^level pixels: what a cone of that footprint gathers (ssr_trace.comp
// picks it per roughness).
#include "ssr_levels.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = SSR_BINDING_HDR, rgba32f) uniform readonly image2D hdrRadiance;
layout(binding = SSR_BINDING_COLOR, rgba16f) uniform image2D colorPyramid;

layout(push_constant) uniform Push {
    uint level;
} push;

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    SsrLevel here = ssrLevel(push.level);
    if (any(greaterThanEqual(texel, here.size))) return;
    if (push.level == 0u) {
        // Half floats hold up to 65504: clamp so a very bright texel blurs as bright, not Inf.
        vec3 c = min(imageLoad(hdrRadiance, texel).rgb, vec3(65000.0));
        imageStore(colorPyramid, texel, vec4(max(c, vec3(0.0)), 1.0));
        return;
    }
    SsrLevel finer = ssrLevel(push.level - 1u);
    ivec2 a = texel * 2;
    ivec2 b = min(a + 1, finer.size - 1);
    vec3 sum = imageLoad(colorPyramid, finer.origin + a).rgb +
               imageLoad(colorPyramid, finer.origin + ivec2(b.x, a.y)).rgb +
               imageLoad(colorPyramid, finer.origin + ivec2(a.x, b.y)).rgb +
               imageLoad(colorPyramid, finer.origin + b).rgb;
    imageStore(colorPyramid, here.origin + texel, vec4(sum * 0.25, 1.0));
}
