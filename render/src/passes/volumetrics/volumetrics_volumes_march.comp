#version 460
#extension GL_GOOGLE_include_directive : require
#include "volumetrics_bindings.h"
#include "volumetric_view_ray.glsl"
// Per-light volumes, step 1 (seed 004 §3), at half resolution: each pixel's view ray (through
// the full-resolution pixel 2q and ending at its depth) crosses each light's volume (a
// sphere, a cone or, for the sun, the whole screen: light_volume.glsl) and marches the
// segment inside in `grid.w` steps starting at the pixel's 4x4 Bayer offset. Each sample is
// lit as the seed's white diffuse surface facing the light gives E (unfiltered shadow),
// scaled by the step and sigma_s with the Henyey-Greenstein phase in place of 1/pi, and by
// the view leg's transmittance to it. Stores (in-scattered radiance, view depth) for the
// bilateral blur and upsample.
//
// A light costs only the pixels its volume covers: each 8x8 tile (a workgroup) marches the
// lights listed for it on the CPU (light_bins.h: the volume's box projected to the screen, the
// proxy mesh's coverage at tile granularity), each pixel testing each of them against its own
// ray (a sphere or cone intersection) and marching only the segment inside. (Lists built here,
// a tile's frustum against every light in shared memory, cost 10x more on lavapipe than testing
// every light at every pixel: their barriers outweighed the tests they saved.)
//
// The sun's volume is the whole screen, marched cascade by cascade (seed 004 §3): the ray is
// cut where it leaves each cascade's sphere, and each piece is marched against that cascade's
// map alone, the rest beyond the last cascade unshadowed. The pieces share the ray's `grid.w`
// steps by length (at least one each): `grid.w` steps per piece cost 11x the demo's march.
#include "light_bins.glsl"
#include "light_volume.glsl"
#include "volumetric_medium.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = VOLUMETRICS_BINDING_DEPTH) uniform sampler2D gbufferDepth;
layout(binding = VOLUMETRICS_BINDING_VOLUMES_MARCHED, rgba32f) uniform writeonly image2D marched;

// 4x4 ordered dither (Bayer), in sixteenths: neighbouring pixels start their march at
// offsets that a 4x4 neighbourhood covers evenly, so the blur turns 16 steps into 256.
const float kBayer4x4[16] =
    float[16](0.0, 8.0, 2.0, 10.0, 12.0, 4.0, 14.0, 6.0, 3.0, 11.0, 1.0, 9.0, 15.0, 7.0, 13.0, 5.0);

// Marches [segment.x, segment.y] of the ray in `steps` steps from the pixel's dither offset,
// each sample lit by light i (its shadow in `view` when cascade >= 0, else unshadowed; or, for
// a local light, mediumShadow).
vec3 marchSegment(uint i, Light light, vec3 origin, vec3 direction, vec2 segment, float steps,
                  float dither, bool inCascade, ShadowView view, bool shadowed, bool areaLight) {
    vec3 radiance = vec3(0.0);
    float dt = (segment.y - segment.x) / steps;
    for (float s = dither; s < steps; s += 1.0) {
        float t = segment.x + s * dt;
        vec3 P = origin + direction * t;
        float density = mediumDensity(P);
        float sigmaT = (push.medium.x + push.medium.y) * density;
        vec3 lit = lightInScatteringUnshadowed(light, i, P, -direction, sigmaT, 0.0, areaLight);
        if (shadowed) lit *= inCascade ? mediumShadowInView(view, P) : mediumShadow(light, i, P);
        radiance +=
            lit * (push.medium.x * density * exp(-viewOpticalDepth(origin, direction, t)) * dt);
    }
    return radiance;
}

// The steps of the ray's piece [t0, t1] of a march `total` metres long: its share of `steps`.
float stepsOfPiece(float t0, float t1, float total, float steps) {
    return max(1.0, ceil(steps * (t1 - t0) / max(total, 1e-6)));
}

// The sun's in-scattering along [startT, farT] (the ray's part in the medium), cascade by
// cascade (see the top).
vec3 marchSun(uint i, Light light, vec3 origin, vec3 direction, float startT, float farT,
              float steps, float dither) {
    float total = farT - startT;
    ShadowView none;
    uvec2 entry = kShadowsEnabled ? shadowLights[i] : uvec2(SHADOW_NO_VIEW, 0u);
    if (entry.x == SHADOW_NO_VIEW) {
        return marchSegment(i, light, origin, direction, vec2(startT, farT), steps, dither,
                            false, none, false, false);
    }
    vec3 radiance = vec3(0.0);
    float covered = startT;
    for (uint c = 0u; c < entry.y && covered < farT; ++c) {
        ShadowView view = shadowViews[entry.x + c];
        float exit = raySphereSegment(origin, direction, view.sphere.xyz, view.sphere.w).y;
        float end = min(exit, farT);
        if (end <= covered) continue;
        radiance += marchSegment(i, light, origin, direction, vec2(covered, end),
                                 stepsOfPiece(covered, end, total, steps), dither, true, view, true,
                                 false);
        covered = end;
    }
    if (covered < farT) {
        radiance += marchSegment(i, light, origin, direction, vec2(covered, farT),
                                 stepsOfPiece(covered, farT, total, steps), dither, false, none,
                                 false, false);
    }
    return radiance;
}

void main() {
    ivec2 half_ = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(camera.frameInfo.xy);
    ivec2 halfSize = (size + 1) / 2;
    if (half_.x >= halfSize.x || half_.y >= halfSize.y) return;
    ivec2 pixel = min(half_ * 2, size - 1);
    vec2 ndc = (vec2(pixel) + 0.5) / vec2(size) * 2.0 - 1.0;
    vec3 origin = camera.cameraPosition.xyz;
    vec4 nearPoint = vec4(unjitteredNearPoint(ndc), 1.0);
    vec3 perDepth = (nearPoint.xyz / nearPoint.w - origin) / push.range.y;
    float depth = texelFetch(gbufferDepth, pixel, 0).r;
    // Reverse-Z: view depth = near / depth; 0 is the background, marched to the far distance.
    float viewDepth = depth > 0.0 ? min(push.range.y / depth, push.range.z) : push.range.z;
    float surfaceT = viewDepth * length(perDepth);
    vec3 direction = normalize(perDepth);
    float dither = (kBayer4x4[(half_.y & 3) * 4 + (half_.x & 3)] + 0.5) / 16.0;
    float steps = float(max(push.grid.w, 1u));
    vec3 radiance = vec3(0.0);
    ShadowView none;
    // A bounded medium is marched only where the ray crosses its box, so every step lands in it.
    vec2 span = mediumSpan(origin, direction, surfaceT);
    if (push.medium.x > 0.0 && span.x < span.y) {
        uvec2 listed = workgroupLightRange();
        for (uint k = listed.x; k < listed.y; ++k) {
            uint i = lightBins[k];
            Light light = loadLight(i, push.lights.y);
            if (light.type == kLightDirectional) {
                radiance += marchSun(i, light, origin, direction, span.x, span.y, steps, dither);
                continue;
            }
            // Rect and disk lights are marched apart (below), so this loop's copy of the
            // in-scattering leaves their form-factor code out.
            if (kMediumAreaLights && isMediumAreaLight(light)) continue;
            vec2 segment = lightVolumeSegment(light, origin, direction, surfaceT);
            segment = vec2(max(segment.x, span.x), min(segment.y, span.y));
            if (segment.x >= segment.y) continue;
            radiance += marchSegment(i, light, origin, direction, segment, steps, dither, false,
                                     none, true, false);
        }
        for (uint k = listed.x; kMediumAreaLights && k < listed.y; ++k) {
            uint i = lightBins[k];
            Light light = loadLight(i, push.lights.y);
            if (!isMediumAreaLight(light)) continue;
            vec2 segment = lightVolumeSegment(light, origin, direction, surfaceT);
            segment = vec2(max(segment.x, span.x), min(segment.y, span.y));
            if (segment.x >= segment.y) continue;
            radiance += marchSegment(i, light, origin, direction, segment, steps, dither, false,
                                     none, true, true);
        }
    }
    imageStore(marched, half_, vec4(radiance, viewDepth));
}
