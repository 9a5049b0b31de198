// The per-light volumes' march (Vos 2014, GPU Pro 5, "Volumetric Light Effects in Killzone: Shadow
// Fall"), shared by the tile-binned compute march (volumetrics_volumes_march.comp) and the
// rasterised proxies (volumetrics_volumes_proxy.frag, volumetrics_volumes_sun.frag): one
// half-resolution pixel's view ray, its 4x4 Bayer start offset, and the march of a light's segment
// along it. Each sample is lit as Vos's white diffuse surface facing the light gives E (unfiltered
// shadow), scaled by the step and sigma_s with the Henyey-Greenstein phase in place of 1/pi, and by
// the view leg's transmittance to it.
//
// The sun's volume is the whole screen, marched cascade by cascade (Vos 2014): the ray is
// cut where it leaves each cascade's sphere, and each piece is marched against that cascade's
// map alone, the rest beyond the last cascade unshadowed. The pieces share the ray's `grid.w`
// steps by length (at least one each): `grid.w` steps per piece cost 11x the demo's march.
#ifndef CANDELA_VOLUMES_MARCH_GLSL
#define CANDELA_VOLUMES_MARCH_GLSL

#include "light_volume.glsl"
#include "volumetric_medium.glsl"
#include "volumetric_view_ray.glsl"

layout(binding = VOLUMETRICS_BINDING_DEPTH) uniform sampler2D gbufferDepth;

// 4x4 ordered dither (Bayer), in sixteenths: neighbouring pixels start their march at
// offsets that a 4x4 neighbourhood covers evenly, so the blur turns 16 steps into 256.
const float kBayer4x4[16] =
    float[16](0.0, 8.0, 2.0, 10.0, 12.0, 4.0, 14.0, 6.0, 3.0, 11.0, 1.0, 9.0, 15.0, 7.0, 13.0, 5.0);

// Half-resolution pixel q's view ray: through the full-resolution pixel 2q (unjittered), ending
// at its depth or the far distance.
struct VolumeRay {
    vec3 origin;
    vec3 direction;
    float surfaceT;   // metres along the ray to the surface (or the far distance)
    float viewDepth;  // the surface's view depth (m), stored for the bilateral blur
    float dither;     // the pixel's start offset, in steps
};

VolumeRay volumeRay(ivec2 half_) {
    ivec2 size = ivec2(camera.frameInfo.xy);
    ivec2 pixel = min(half_ * 2, size - 1);
    vec2 ndc = (vec2(pixel) + 0.5) / vec2(size) * 2.0 - 1.0;
    VolumeRay ray;
    ray.origin = camera.cameraPosition.xyz;
    vec4 nearPoint = vec4(unjitteredNearPoint(ndc), 1.0);
    vec3 perDepth = (nearPoint.xyz / nearPoint.w - ray.origin) / push.range.y;
    float depth = texelFetch(gbufferDepth, pixel, 0).r;
    // Reverse-Z: view depth = near / depth; 0 is the background, marched to the far distance.
    ray.viewDepth = depth > 0.0 ? min(push.range.y / depth, push.range.z) : push.range.z;
    ray.surfaceT = ray.viewDepth * length(perDepth);
    ray.direction = normalize(perDepth);
    ray.dither = (kBayer4x4[(half_.y & 3) * 4 + (half_.x & 3)] + 0.5) / 16.0;
    return ray;
}

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

// A local light's in-scattering along the ray: the segment inside its volume (light_volume.glsl)
// and the medium's span, marched in `steps`; zero when they do not meet.
vec3 marchLocalLight(uint i, Light light, VolumeRay ray, vec2 span, float steps, bool areaLight) {
    vec2 segment = lightVolumeSegment(light, ray.origin, ray.direction, ray.surfaceT);
    segment = vec2(max(segment.x, span.x), min(segment.y, span.y));
    if (segment.x >= segment.y) return vec3(0.0);
    ShadowView none;
    return marchSegment(i, light, ray.origin, ray.direction, segment, steps, ray.dither, false,
                        none, true, areaLight);
}

#endif
