#version 460
#extension GL_GOOGLE_include_directive : require
#include "ssr_bindings.h"
// Temporal filtering of the traced reflection: last frame's filtered result, reprojected with
// the G-buffer's motion vectors, blended with this frame's. History that the reprojection
// takes off the screen, or that falls outside the range of this frame's 3x3 neighbourhood
// (a surface uncovered this frame, or a reflected object that moved away), is rejected or
// clamped into that range, and history whose ray hit where this frame's missed (or missed
// where it hits) is dropped, so nothing trails behind or lags a moving object.
#include "common/camera.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = SSR_BINDING_REFLECTION) uniform sampler2D current;
layout(binding = SSR_BINDING_MOTION) uniform sampler2D motion;
layout(binding = SSR_BINDING_HISTORY) uniform sampler2D history;
layout(binding = SSR_BINDING_HISTORY_OUTPUT, rgba32f) uniform writeonly image2D filtered;

layout(push_constant) uniform Push {
    uint historyValid;
    float blend;  // weight of this frame's reflection
} push;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(camera.frameInfo.xy);
    if (any(greaterThanEqual(pixel, size))) return;
    vec4 now = texelFetch(current, pixel, 0);
    vec4 result = now;
    vec2 previous = (vec2(pixel) + 0.5) / vec2(size) - texelFetch(motion, pixel, 0).xy;
    if (push.historyValid != 0u && all(greaterThanEqual(previous, vec2(0.0))) &&
        all(lessThan(previous, vec2(1.0)))) {
        vec4 lo = now, hi = now;
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                vec4 c = texelFetch(current, clamp(pixel + ivec2(dx, dy), ivec2(0), size - 1), 0);
                lo = min(lo, c);
                hi = max(hi, c);
            }
        }
        vec4 past = texelFetch(history, ivec2(previous * vec2(size)), 0);
        // A ray that hits now but missed then (or the other way round) sees something new
        // (the leading or trailing edge of a moving reflected object, an uncovered surface):
        // this frame alone, or the edge would lag and trail.
        bool sameHit = abs(past.a - now.a) < 0.5;
        if (sameHit && all(lessThan(abs(past), vec4(3e38)))) {  // never carry NaN or Inf on
            result = mix(clamp(past, lo, hi), now, push.blend);
        }
    }
    imageStore(filtered, pixel, result);
}
