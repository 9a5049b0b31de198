#version 460
#extension GL_GOOGLE_include_directive : require
#include "nonfinite_bindings.h"
// Counts the texels of a sampled image whose value is not finite into one slot of a
// host-visible buffer (the slot's range is what the descriptor binds): the probes of a
// diagnosis frame, after each pass that writes a float image.

layout(binding = NONFINITE_BINDING_IMAGE) uniform sampler2D image;

ivec2 imageSizeOf() {
    return textureSize(image, 0);
}

vec4 fetch(ivec2 texel) {
    return texelFetch(image, texel, 0);
}

#include "nonfinite_count.glsl"
