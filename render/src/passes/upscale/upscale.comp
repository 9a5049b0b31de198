#version 460
#extension GL_GOOGLE_include_directive : require
#include "upscale_bindings.h"
// Radiance rendered at a fraction of the output's size (RendererOptions::renderScale) brought
// up to the output's size before tonemapping, by one bilinear tap per output pixel.
// A Catmull-Rom filter (5 bilinear taps, Jimenez 2016, "Filmic SMAA", SIGGRAPH course, with a
// clamp against ringing) kept edges sharper, but cost 3x as much on lavapipe (5.7 against
// 1.8 ms at 640x360) for little less error: orb game 7.5 against 8.8% mean relative error in
// luminance against the full-size frame, minimal game 3.0 against 3.1% (docs/frame-budget.md).

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = UPSCALE_BINDING_INPUT) uniform sampler2D source;
layout(binding = UPSCALE_BINDING_OUTPUT, rgba32f) uniform writeonly image2D target;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 targetSize = imageSize(target);
    if (any(greaterThanEqual(pixel, targetSize))) return;
    // Pixel centres map onto the source's continuous coordinates, so both images cover the
    // same area whatever the rounding of the render size.
    vec2 uv = (vec2(pixel) + 0.5) / vec2(targetSize);
    imageStore(target, pixel, vec4(textureLod(source, uv, 0.0).rgb, 1.0));
}
