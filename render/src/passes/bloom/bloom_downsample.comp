#version 460
#extension GL_GOOGLE_include_directive : require
#include "bloom_bindings.h"
// One level of the bloom pyramid: each texel is the mean of the 2x2 texels it covers above
// (fewer at an odd edge), so a level holds the same total radiance per area as the frame.

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = BLOOM_DOWNSAMPLE_BINDING_SOURCE, rgba32f) uniform readonly image2D source;
layout(binding = BLOOM_DOWNSAMPLE_BINDING_TARGET, rgba32f) uniform writeonly image2D target;

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, imageSize(target)))) return;
    ivec2 size = imageSize(source);
    vec3 sum = vec3(0.0);
    float count = 0.0;
    for (int dy = 0; dy < 2; ++dy) {
        for (int dx = 0; dx < 2; ++dx) {
            ivec2 q = 2 * texel + ivec2(dx, dy);
            if (any(greaterThanEqual(q, size))) continue;
            sum += imageLoad(source, q).rgb;
            count += 1.0;
        }
    }
    imageStore(target, texel, vec4(sum / max(count, 1.0), 1.0));
}
