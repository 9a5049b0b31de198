#version 460
#extension GL_GOOGLE_include_directive : require
#include "fxaa_bindings.h"
// Post-process antialiasing after tonemapping (FXAA's approach, written for this engine):
// per pixel, find the local contrast from the sRGB-encoded luma of the 3x3 neighbourhood;
// where it is high, decide whether the edge runs horizontally or vertically, walk along it
// both ways until the luma leaves the edge's average, and blend with the neighbour across the
// edge by how far the pixel sits from the nearer end (long, shallow staircases get a ramp).
// A sub-pixel term blends single-pixel features towards their neighbourhood.
// The blend itself is done in linear light: both colours are taken back through the sRGB
// encoding and the ACES curve to exposed radiance, mixed, and shown again, so a half-covered
// pixel gets the same value a supersampled frame resolved in linear light (and TAA) gives it.
// Mixing the encoded values instead (a bilinear fetch) leaves edges against bright surfaces
// visibly too dark.
#include "common/color.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = FXAA_BINDING_INPUT) uniform sampler2D tonemapped;
layout(binding = FXAA_BINDING_OUTPUT, rgba8) uniform writeonly image2D ldrOutput;

const float kContrastThreshold = 0.0312;  // absolute: ignore the darkest edges
const float kRelativeThreshold = 0.125;   // ... and those below 1/8 of the local maximum
const float kSubpixelStrength = 0.75;
// The walk along an edge: unit steps first (short staircases end within a few pixels and their
// ends must be found exactly), then coarser ones, 38.5 texels each way in all. Near-vertical
// silhouettes of tall geometry step only every few dozen rows; a reach of 26.5 (FXAA 3.11's
// schedule) left the colonnade at 512x384 at 0.51x of the unantialiased edge error, this one
// 0.48x, and changed the smaller frames by under 0.01x (render/README.md "Antialiasing").
const int kSearchSteps = 17;
const float kStepScale[kSearchSteps] = float[](1.0, 1.0, 1.0, 1.0, 1.0, 1.5, 2.0, 2.0, 2.0, 2.0,
                                               2.0, 2.0, 2.0, 2.0, 4.0, 4.0, 8.0);

vec3 srgbToLinear(vec3 encoded) {
    vec3 low = encoded / 12.92;
    vec3 high = pow((encoded + 0.055) / 1.055, vec3(2.4));
    return mix(high, low, lessThanEqual(encoded, vec3(0.04045)));
}

// The inverse of tonemapAcesFit (a quadratic per channel), for y below its shoulder's top.
vec3 inverseAcesFit(vec3 y) {
    y = clamp(y, 0.0, 0.999);
    const float a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
    vec3 qa = y * c - a;
    vec3 qb = y * d - b;
    vec3 qc = y * e;
    return (-qb - sqrt(max(qb * qb - 4.0 * qa * qc, 0.0))) / (2.0 * qa);
}

vec3 exposedRadiance(vec3 encoded) {
    return inverseAcesFit(srgbToLinear(encoded));
}

float luma(vec3 encoded) {
    return dot(encoded, vec3(0.299, 0.587, 0.114));
}

float lumaAt(vec2 uv) {
    return luma(textureLod(tonemapped, uv, 0.0).rgb);
}

float lumaOffset(ivec2 pixel, ivec2 offset, ivec2 size) {
    return luma(texelFetch(tonemapped, clamp(pixel + offset, ivec2(0), size - 1), 0).rgb);
}

void main() {
    ivec2 size = textureSize(tonemapped, 0);
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, size))) return;
    vec2 texel = 1.0 / vec2(size);
    vec2 uv = (vec2(pixel) + 0.5) * texel;
    vec4 centreColour = texelFetch(tonemapped, pixel, 0);

    float m = luma(centreColour.rgb);
    float n = lumaOffset(pixel, ivec2(0, -1), size);
    float s = lumaOffset(pixel, ivec2(0, 1), size);
    float e = lumaOffset(pixel, ivec2(1, 0), size);
    float w = lumaOffset(pixel, ivec2(-1, 0), size);
    float highest = max(m, max(max(n, s), max(e, w)));
    float lowest = min(m, min(min(n, s), min(e, w)));
    float range = highest - lowest;
    if (range < max(kContrastThreshold, kRelativeThreshold * highest)) {
        imageStore(ldrOutput, pixel, vec4(centreColour.rgb, 1.0));
        return;
    }
    float nw = lumaOffset(pixel, ivec2(-1, -1), size);
    float ne = lumaOffset(pixel, ivec2(1, -1), size);
    float sw = lumaOffset(pixel, ivec2(-1, 1), size);
    float se = lumaOffset(pixel, ivec2(1, 1), size);

    // Second differences across each direction: the larger one is across the edge.
    float across = 2.0 * abs(n + s - 2.0 * m) + abs(ne + se - 2.0 * e) + abs(nw + sw - 2.0 * w);
    float along = 2.0 * abs(e + w - 2.0 * m) + abs(ne + nw - 2.0 * n) + abs(se + sw - 2.0 * s);
    bool horizontal = across >= along;  // the edge runs along x; blend across y

    float before = horizontal ? n : w;
    float after = horizontal ? s : e;
    float gradientBefore = abs(before - m);
    float gradientAfter = abs(after - m);
    bool towardsBefore = gradientBefore >= gradientAfter;
    float gradient = max(gradientBefore, gradientAfter);
    float neighbour = towardsBefore ? before : after;
    float stepAcross = (horizontal ? texel.y : texel.x) * (towardsBefore ? -1.0 : 1.0);

    // Walk along the edge, half a texel towards the neighbour's side.
    vec2 edgeUv = uv + (horizontal ? vec2(0.0, 0.5 * stepAcross) : vec2(0.5 * stepAcross, 0.0));
    vec2 stepAlong = horizontal ? vec2(texel.x, 0.0) : vec2(0.0, texel.y);
    float edgeAverage = 0.5 * (m + neighbour);
    float threshold = 0.25 * gradient;
    vec2 uvNegative = edgeUv - stepAlong;
    vec2 uvPositive = edgeUv + stepAlong;
    float endNegative = lumaAt(uvNegative) - edgeAverage;
    float endPositive = lumaAt(uvPositive) - edgeAverage;
    bool doneNegative = abs(endNegative) >= threshold;
    bool donePositive = abs(endPositive) >= threshold;
    float lastStepNegative = kStepScale[0], lastStepPositive = kStepScale[0];
    for (int i = 1; i < kSearchSteps && !(doneNegative && donePositive); ++i) {
        if (!doneNegative) {
            uvNegative -= stepAlong * kStepScale[i];
            lastStepNegative = kStepScale[i];
            endNegative = lumaAt(uvNegative) - edgeAverage;
            doneNegative = abs(endNegative) >= threshold;
        }
        if (!donePositive) {
            uvPositive += stepAlong * kStepScale[i];
            lastStepPositive = kStepScale[i];
            endPositive = lumaAt(uvPositive) - edgeAverage;
            donePositive = abs(endPositive) >= threshold;
        }
    }
    float distanceNegative = horizontal ? uv.x - uvNegative.x : uv.y - uvNegative.y;
    float distancePositive = horizontal ? uvPositive.x - uv.x : uvPositive.y - uv.y;
    // The staircase's riser lies between the last sample still on the edge and the first one
    // off it: half a step short of where the walk stopped, not at that sample (FXAA measures
    // to the sample, which makes every ramp too shallow: a pixel next to the riser of a run of
    // L texels got 0.5 - 1/(L + 1) instead of 0.5 - 1/(2L)). MLAA's revectorisation puts the
    // riser there too. Colonnade at 512x384: 0.527x → 0.506x with the old reach.
    float texelAlong = horizontal ? texel.x : texel.y;
    if (doneNegative) distanceNegative -= 0.5 * lastStepNegative * texelAlong;
    if (donePositive) distancePositive -= 0.5 * lastStepPositive * texelAlong;
    bool negativeNearer = distanceNegative < distancePositive;
    float nearest = min(distanceNegative, distancePositive);
    float edgeLength = distanceNegative + distancePositive;
    // Blend only when the nearer end turns the way this pixel's side of the edge does
    // (otherwise this pixel is on the far side of the staircase step).
    bool centreBelow = m < edgeAverage;
    float nearerEnd = negativeNearer ? endNegative : endPositive;
    float edgeBlend = ((nearerEnd < 0.0) != centreBelow) ? 0.5 - nearest / edgeLength : 0.0;
    // A staircase continues one row over past its step: there the row on this pixel's other
    // side still looks like this pixel. Where it does not, the edge turned a corner (a box's
    // bottom meeting its side), which FXAA's ramp would round off: no edge blend then.
    vec2 nearerUv = negativeNearer ? uvNegative : uvPositive;
    vec2 opposite = horizontal ? vec2(0.0, -1.5 * stepAcross) : vec2(-1.5 * stepAcross, 0.0);
    float beyond = lumaAt(nearerUv + opposite);
    if ((beyond < edgeAverage) != centreBelow) edgeBlend = 0.0;

    float average = (2.0 * (n + s + e + w) + nw + ne + sw + se) / 12.0;
    float subpixel = clamp(abs(average - m) / range, 0.0, 1.0);
    subpixel = (-2.0 * subpixel + 3.0) * subpixel * subpixel;
    float subpixelBlend = subpixel * subpixel * kSubpixelStrength;

    ivec2 toNeighbour =
        horizontal ? ivec2(0, towardsBefore ? -1 : 1) : ivec2(towardsBefore ? -1 : 1, 0);
    vec3 other = texelFetch(tonemapped, clamp(pixel + toNeighbour, ivec2(0), size - 1), 0).rgb;
    vec3 mixed = mix(exposedRadiance(centreColour.rgb), exposedRadiance(other), edgeBlend);
    // Sub-pixel features (thin gaps, distant detail) blend towards the neighbourhood's mean
    // radiance, weighted like `average`, not towards one neighbour.
    vec3 mean = vec3(0.0);
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            if (dx == 0 && dy == 0) continue;
            float weight = (dx == 0 || dy == 0) ? 2.0 : 1.0;
            ivec2 at = clamp(pixel + ivec2(dx, dy), ivec2(0), size - 1);
            mean += weight * exposedRadiance(texelFetch(tonemapped, at, 0).rgb);
        }
    }
    mixed = mix(mixed, mean / 12.0, subpixelBlend);
    imageStore(ldrOutput, pixel, vec4(linearToSrgb(tonemapAcesFit(mixed)), 1.0));
}
