#version 460
#extension GL_GOOGLE_include_directive : require
#include "taa_bindings.h"
// Temporal antialiasing resolve, in HDR before exposure and tonemapping:
//   1. the history is read where this pixel was last frame (uv - motion, bilinear);
//   2. it is clipped towards the 3x3 neighbourhood of this frame's samples, an axis-aligned
//      box in YCoCg of the exposed radiance (luma and chroma apart: the box is tight along
//      luma, where edges differ), which removes what the history holds that is no longer
//      there (ghosts, disocclusions);
//   3. history and the current sample are blended with weights divided by 1 + the exposed
//      luminance (tonemapped weights: a bright sample cannot dominate the average, which
//      would make edges against a bright sky or a bulb alias again).
// The blend factor starts at 1 / (samples + 1) per pixel (history alpha counts them) so a
// static image converges to the plain mean of the jitter sequence, and never falls below
// push.minimumBlend so a moving one keeps responding. A history texel that is not finite is
// dropped as a missing history would be, so one bad frame cannot live on in every later one.
#include "common/color.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = TAA_BINDING_CURRENT, rgba32f) uniform readonly image2D current;
layout(binding = TAA_BINDING_MOTION) uniform sampler2D motion;
layout(binding = TAA_BINDING_HISTORY) uniform sampler2D history;
layout(binding = TAA_BINDING_RESOLVED, rgba32f) uniform writeonly image2D resolved;

layout(push_constant) uniform Push {
    float exposure;       // exposureFromEv100: clipping and weights work on exposed values
    float minimumBlend;   // lowest weight of the current sample
    uint historyValid;    // 0: first frame, resize, camera cut: take the current sample
    float sharpness;      // 0: off; else the strength of a 3x3 unsharp mask on the current
} push;

float luminance(vec3 c) {
    return dot(c, vec3(0.2126, 0.7152, 0.0722));
}

vec3 toYCoCg(vec3 c) {
    return vec3(0.25 * c.r + 0.5 * c.g + 0.25 * c.b, 0.5 * c.r - 0.5 * c.b,
                -0.25 * c.r + 0.5 * c.g - 0.25 * c.b);
}

// The scale the box and the weights work in: the exposure, capped at 1e12 (an EV100 near -40)
// where every texel a tonemapper can tell from black is long saturated, so that an absurd
// exposure (EV100 near -127: a scale near the largest float) cannot overflow the box's sums
// to Inf - Inf. Ordinary exposures (EV100 -10 to 20) pass through bit for bit.
float workingScale() {
    return min(push.exposure, 1.0e12);
}

vec3 exposed(vec3 radiance) {
    return radiance * workingScale();
}

vec3 fromYCoCg(vec3 c) {
    return vec3(c.x + c.y - c.z, c.x + c.z, c.x - c.y - c.z);
}

// Moves `value` along the line to the box's centre until it is inside the box.
vec3 clipToBox(vec3 value, vec3 boxMin, vec3 boxMax) {
    vec3 centre = 0.5 * (boxMax + boxMin);
    vec3 halfExtent = 0.5 * (boxMax - boxMin) + 1e-5;
    vec3 offset = value - centre;
    vec3 units = abs(offset / halfExtent);
    float largest = max(units.x, max(units.y, units.z));
    return largest > 1.0 ? centre + offset / largest : value;
}

void main() {
    ivec2 size = imageSize(current);
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, size))) return;

    vec3 centre = imageLoad(current, pixel).rgb;
    vec3 boxMin = vec3(3.0e38);
    vec3 boxMax = vec3(-3.0e38);
    vec3 crossSum = vec3(0.0);
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 q = clamp(pixel + ivec2(dx, dy), ivec2(0), size - 1);
            vec3 c = imageLoad(current, q).rgb;
            vec3 y = toYCoCg(exposed(c));
            boxMin = min(boxMin, y);
            boxMax = max(boxMax, y);
            if ((dx == 0) != (dy == 0)) crossSum += c;
        }
    }
    if (push.sharpness > 0.0) {
        // Unsharp mask against the 4-neighbour mean (no negative radiance); the clip below
        // still bounds the history by the unsharpened neighbourhood.
        vec3 sharpened = centre + push.sharpness * (centre - 0.25 * crossSum);
        centre = max(sharpened, vec3(0.0));
    }

    vec2 uv = (vec2(pixel) + 0.5) / vec2(size);
    vec2 previousUv = uv - texelFetch(motion, pixel, 0).xy;
    bool onScreen = all(greaterThanEqual(previousUv, vec2(0.0))) &&
                    all(lessThanEqual(previousUv, vec2(1.0)));
    vec4 previous = textureLod(history, previousUv, 0.0);
    bool finiteHistory = !any(isnan(previous)) && !any(isinf(previous));
    if (push.historyValid == 0u || !onScreen || !finiteHistory) {
        imageStore(resolved, pixel, vec4(centre, 1.0));
        return;
    }
    vec3 clipped = clipToBox(toYCoCg(exposed(max(previous.rgb, vec3(0.0)))), boxMin, boxMax);
    vec3 historyRadiance = fromYCoCg(clipped) / workingScale();
    float samples = max(previous.a, 1.0);
    float blend = max(1.0 / (samples + 1.0), push.minimumBlend);
    float currentWeight = blend / (1.0 + luminance(centre) * workingScale());
    float historyWeight = (1.0 - blend) / (1.0 + luminance(historyRadiance) * workingScale());
    vec3 result = (currentWeight * centre + historyWeight * historyRadiance) /
                  (currentWeight + historyWeight);
    imageStore(resolved, pixel, vec4(result, min(samples + 1.0, 1.0 / push.minimumBlend)));
}
