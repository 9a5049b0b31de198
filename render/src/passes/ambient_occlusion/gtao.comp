#version 460
#extension GL_GOOGLE_include_directive : require
#include "ambient_occlusion_bindings.h"
// Ground-truth-based ambient occlusion (Jimenez et al. 2016) from the G-buffer's depth and
// normals: per pixel, `slices` screen-space directions; along each, the highest horizon on
// both sides within `radius` metres; between the two horizons, the cosine-weighted visible
// arc integrated analytically against the normal projected into the slice, and the bent
// normal (the mean visible direction) likewise. Writes (world bent normal, visibility).
#include "common/ambient_occlusion.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = AO_BINDING_DEPTH) uniform sampler2D gbufferDepth;
layout(binding = AO_BINDING_NORMAL) uniform sampler2D gbufferNormalRoughMetal;
layout(binding = AO_BINDING_OUTPUT, rgba16f) uniform writeonly image2D aoOutput;
// The reflection lobe's visibility (see specularVisibility below).
layout(binding = AO_BINDING_SECOND_OUTPUT, r16f) uniform writeonly image2D specularOutput;

layout(push_constant) uniform Push {
    float radius;
    uint slices;
    uint steps;
    float thickness;  // unused here (the reference's)
    // Added to every pixel's slice rotation and step jitter (fractions of their periods):
    // zero without temporal accumulation, a low-discrepancy sequence over frames with it.
    vec2 frameRotation;
    uint specularSlice;  // 1: trace the horizon slice through R (else write 1)
} push;

// cos of the horizon seen from P along one side of the slice: samples farther than the
// radius fade to the side's lowest horizon (the tangent plane's), Jimenez et al.'s falloff.
float horizonCosine(vec3 P, vec3 V, vec2 pixelCentre, vec2 direction, float radiusPixels,
                    float jitter, float lowCosine) {
    float best = lowCosine;
    vec2 size = vec2(camera.frameInfo.xy);
    for (uint j = 0u; j < push.steps; ++j) {
        float s = (float(j) + jitter) / float(push.steps);
        // Quadratic spacing: more samples near the pixel, where contact occlusion lives;
        // at least one pixel away so a pixel never samples itself.
        float offset = max(s * s * radiusPixels, float(j) + 1.0);
        vec2 samplePixel = floor(pixelCentre + direction * offset) + 0.5;
        if (any(lessThan(samplePixel, vec2(0.0))) || any(greaterThanEqual(samplePixel, size)))
            break;
        float depth = texelFetch(gbufferDepth, ivec2(samplePixel), 0).r;
        if (depth <= 0.0) continue;  // sky: no occluder
        vec3 delta = aoWorldFromDepth(samplePixel, depth) - P;
        float distance = length(delta);
        if (distance < 1e-5) continue;
        float sampleCosine = dot(delta / distance, V);
        // Full weight to 0.7 radius, none past the radius.
        float weight = saturate((push.radius - distance) / (0.3 * push.radius));
        best = max(best, mix(lowCosine, sampleCosine, weight));
    }
    return best;
}

// The slice through V along screen direction `direction`: its tangent (perpendicular to V),
// the normal projected into it, that projection's length and its angle n from V.
struct Slice {
    vec3 tangent;
    float projectedLength;
    float n;
    float cosN;
};

Slice sliceOf(vec3 P, vec3 V, vec3 N, vec2 centre, vec2 direction, float depth) {
    Slice slice;
    // The world direction that moving along `direction` on screen takes at P's depth, made
    // perpendicular to V: with V it spans the slice plane.
    vec3 along = aoWorldFromDepth(centre + direction, depth) - P;
    slice.tangent = safeNormalize(along - dot(along, V) * V);
    vec3 axis = safeNormalize(cross(slice.tangent, V));
    vec3 projectedN = N - axis * dot(N, axis);
    slice.projectedLength = length(projectedN);
    slice.cosN = saturate(dot(projectedN, V) / max(slice.projectedLength, 1e-8));
    slice.n = sign(dot(projectedN, slice.tangent)) * acos(slice.cosN);
    return slice;
}

// Length of the overlap of the angle intervals [a0, a1] and [b0, b1].
float overlap(float a0, float a1, float b0, float b1) {
    return max(min(a1, b1) - max(a0, b0), 0.0);
}

// Specular occlusion from the horizons of one more slice, the one along the normal's screen
// direction: it holds V, N and so the reflection vector R, at angle 2n from V. The reflection
// lobe is taken as the arc of half-width w around R in that slice (w: twice the GGX median
// half-vector angle, atan(alpha)); its visible share is the part between the two horizons,
// divided by the part above the tangent plane, so an unoccluded surface keeps all of its
// specular (a grazing lobe that dips under the surface is the split sum's business, not
// occlusion). Rougher lobes spread outside the slice; one slice still sees where the lobe's
// core goes, which is what the visibility-only estimate cannot know.
float specularVisibility(vec3 P, vec3 V, vec3 N, vec2 centre, float depth, float radiusPixels,
                         float jitter, float roughness) {
    vec2 screenN = (clipOf(P + N * 0.01).xy / clipOf(P + N * 0.01).w -
                    clipOf(P).xy / clipOf(P).w) * vec2(camera.frameInfo.xy);
    vec2 direction = dot(screenN, screenN) > 1e-12 ? normalize(screenN) : vec2(1.0, 0.0);
    Slice slice = sliceOf(P, V, N, centre, direction, depth);
    if (slice.projectedLength < 1e-4) return 1.0;
    float n = slice.n;
    float cosPositive =
        horizonCosine(P, V, centre, direction, radiusPixels, jitter, cos(n + 0.5 * PI));
    float cosNegative =
        horizonCosine(P, V, centre, -direction, radiusPixels, jitter, cos(n - 0.5 * PI));
    float h1 = n + clamp(acos(clamp(cosPositive, -1.0, 1.0)) - n, -0.5 * PI, 0.5 * PI);
    float h0 = n + clamp(-acos(clamp(cosNegative, -1.0, 1.0)) - n, -0.5 * PI, 0.5 * PI);
    float alpha = roughness * roughness;
    float w = max(2.0 * atan(alpha), 0.01);
    float r = 2.0 * n;
    float aboveSurface = overlap(r - w, r + w, n - 0.5 * PI, n + 0.5 * PI);
    if (aboveSurface <= 1e-6) return 1.0;
    return saturate(overlap(r - w, r + w, h0, h1) / aboveSurface);
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    uvec2 size = camera.frameInfo.xy;
    if (pixel.x >= int(size.x) || pixel.y >= int(size.y)) return;
    float depth = texelFetch(gbufferDepth, pixel, 0).r;
    vec4 normalRoughMetal = texelFetch(gbufferNormalRoughMetal, pixel, 0);
    vec3 N = octDecode(normalRoughMetal.xy);
    float roughness = normalRoughMetal.z;
    if (depth <= 0.0) {
        imageStore(aoOutput, pixel, vec4(N, 1.0));
        imageStore(specularOutput, pixel, vec4(1.0));
        return;
    }
    vec2 centre = vec2(pixel) + 0.5;
    vec3 P = aoWorldFromDepth(centre, depth);
    vec3 V = safeNormalize(camera.cameraPosition.xyz - P);
    // One pixel's width at P's depth, for the radius in pixels.
    float pixelWorld = length(aoWorldFromDepth(centre + vec2(1.0, 0.0), depth) - P);
    float radiusPixels = push.radius / max(pixelWorld, 1e-8);
    vec2 noise = fract(aoPixelNoise(pixel) + push.frameRotation);

    float visibility = 0.0;
    vec3 bent = vec3(0.0);
    float weightSum = 0.0;
    for (uint i = 0u; i < push.slices; ++i) {
        float phi = (float(i) + noise.x) * PI / float(push.slices);
        vec2 direction = vec2(cos(phi), sin(phi));
        Slice slice = sliceOf(P, V, N, centre, direction, depth);
        vec3 sliceTangent = slice.tangent;
        float projectedLength = slice.projectedLength;
        if (projectedLength < 1e-4) continue;
        float cosN = slice.cosN;
        float n = slice.n;
        // Horizons as angles from V, positive toward +direction; never below the tangent
        // plane's (n +- pi/2).
        float cosPositive = horizonCosine(P, V, centre, direction, radiusPixels, noise.y,
                                          cos(n + 0.5 * PI));
        float cosNegative = horizonCosine(P, V, centre, -direction, radiusPixels, noise.y,
                                          cos(n - 0.5 * PI));
        float h1 = acos(clamp(cosPositive, -1.0, 1.0));
        float h0 = -acos(clamp(cosNegative, -1.0, 1.0));
        h0 = n + clamp(h0 - n, -0.5 * PI, 0.5 * PI);
        h1 = n + clamp(h1 - n, -0.5 * PI, 0.5 * PI);
        float sinN = sin(n);
        // Cosine-weighted visible arc: the integral of cos(h - n) |sin h| over [h0, h1].
        float arc0 = (cosN + 2.0 * h0 * sinN - cos(2.0 * h0 - n)) * 0.25;
        float arc1 = (cosN + 2.0 * h1 * sinN - cos(2.0 * h1 - n)) * 0.25;
        visibility += projectedLength * (arc0 + arc1);
        // Mean visible direction in the slice, in (sliceTangent, V) coordinates.
        float t0 = (6.0 * sin(h0 - n) - sin(3.0 * h0 - n) + 6.0 * sin(h1 - n) - sin(3.0 * h1 - n) +
                    16.0 * sinN - 3.0 * (sin(h0 + n) + sin(h1 + n))) / 12.0;
        float t1 = (-cos(3.0 * h0 - n) - cos(3.0 * h1 - n) + 8.0 * cos(n) -
                    3.0 * (cos(h0 + n) + cos(h1 + n))) / 12.0;
        bent += (sliceTangent * t0 + V * t1) * projectedLength;
        weightSum += projectedLength;
    }
    // Not clamped to 1 here: a few slices over- and underestimate an open plane seen at an
    // angle, and the denoise's average of both is unbiased only if neither is clipped.
    visibility = weightSum > 0.0 ? max(visibility / float(push.slices), 0.0) : 1.0;
    // A bent normal behind the surface (grazing views) would light it from below: keep it
    // in N's hemisphere.
    bent = safeNormalize(bent);
    if (dot(bent, N) < 0.05 || weightSum <= 0.0) bent = N;
    imageStore(aoOutput, pixel, vec4(bent, visibility));
    float specular = push.specularSlice != 0u ? specularVisibility(P, V, N, centre, depth,
                                                                   radiusPixels, noise.y,
                                                                   roughness)
                                              : 1.0;
    imageStore(specularOutput, pixel, vec4(specular));
}
