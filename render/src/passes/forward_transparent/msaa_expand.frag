#version 460
#extension GL_GOOGLE_include_directive : require
#include "forward_transparent_bindings.h"
// Forward MSAA: copies the single-sample deferred result (lit HDR, motion, depth) into every
// sample of the multisampled targets the forward pass then draws into. Runs once per pixel
// (no sample shading), so all samples of a pixel get the pixel's value; gl_FragDepth writes
// the depth of every sample too (the pipeline's depth test is ALWAYS).
layout(binding = MSAA_EXPAND_BINDING_HDR) uniform sampler2D hdr;
layout(binding = MSAA_EXPAND_BINDING_MOTION) uniform sampler2D motion;
layout(binding = MSAA_EXPAND_BINDING_DEPTH) uniform sampler2D depth;

layout(location = 0) out vec4 outHdr;
layout(location = 1) out vec2 outMotion;

void main() {
    const ivec2 pixel = ivec2(gl_FragCoord.xy);
    outHdr = texelFetch(hdr, pixel, 0);
    outMotion = texelFetch(motion, pixel, 0).xy;
    gl_FragDepth = texelFetch(depth, pixel, 0).r;
}
