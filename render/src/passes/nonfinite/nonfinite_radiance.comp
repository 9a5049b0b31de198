#version 460
#extension GL_GOOGLE_include_directive : require
#include "nonfinite_bindings.h"
// Counts the pixels of the frame's scene radiance (the RGBA32F HDR target, read as storage
// like tonemapping reads it, so the check adds no layout change) that are not finite.

layout(binding = NONFINITE_BINDING_IMAGE, rgba32f) uniform readonly image2D radiance;

ivec2 imageSizeOf() {
    return imageSize(radiance);
}

vec4 fetch(ivec2 texel) {
    return imageLoad(radiance, texel);
}

#include "nonfinite_count.glsl"
