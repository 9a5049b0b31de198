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
// A light costs only the pixels its volume covers: the seed rasterises each light's volume;
// here each workgroup is a screen tile of 8x8 half-resolution pixels (16x16 in the frame)
// that first lists the lights whose volume (the range sphere; a spot's cone by its bounding
// sphere) reaches the tile's frustum up to its farthest surface, 64 lights at a time, one per
// thread, and its pixels then march only those. A tile outside a light's volume pays one test
// per 64 pixels for it, not a ray intersection per pixel.
//
// The sun's volume is the whole screen, marched cascade by cascade (seed 004 §3): the ray is
// cut where it leaves each cascade's sphere, and each piece is marched in `grid.w` steps
// against that cascade's map alone (finer steps near the camera, where the maps are finer),
// the rest beyond the last cascade unshadowed.
#include "light_volume.glsl"
#include "volumetric_medium.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = VOLUMETRICS_BINDING_DEPTH) uniform sampler2D gbufferDepth;
layout(binding = VOLUMETRICS_BINDING_VOLUMES_MARCHED, rgba32f) uniform writeonly image2D marched;

// 4x4 ordered dither (Bayer), in sixteenths: neighbouring pixels start their march at
// offsets that a 4x4 neighbourhood covers evenly, so the blur turns 16 steps into 256.
const float kBayer4x4[16] =
    float[16](0.0, 8.0, 2.0, 10.0, 12.0, 4.0, 14.0, 6.0, 3.0, 11.0, 1.0, 9.0, 15.0, 7.0, 13.0, 5.0);

const uint kTileThreads = 64u;
// The tile's frustum: four planes through the camera (inward normals), and the farthest ray
// length of its pixels.
shared vec3 tilePlanes[4];
shared uint tileFarBits;
// Whether light (batch start + i) reaches the tile: a flag per thread, read in order so the
// sum's order, and so the result, is the same every frame.
shared bool tileHit[kTileThreads];

// World direction (not unit) of the ray through full-resolution pixel coordinate `at`.
vec3 rayThrough(vec2 at, vec2 size) {
    vec2 ndc = at / size * 2.0 - 1.0;
    vec4 nearPoint = vec4(unjitteredNearPoint(ndc), 1.0);
    return nearPoint.xyz / nearPoint.w - camera.cameraPosition.xyz;
}

// A sphere holding the light's volume: its range sphere, or for a spot of half-angle a under
// 90 degrees the smallest sphere around its cone cut by that sphere (apex at the light; for a
// under 45 degrees the sphere through the apex and the cap's rim, else the cap's own circle).
// w <= 0: everywhere (the sun, or no range).
vec4 lightBoundingSphere(Light light) {
    if (light.type == kLightDirectional || light.invAttenuationRadius <= 0.0) {
        return vec4(0.0);
    }
    float range = 1.0 / light.invAttenuationRadius;
    if (light.type == kLightSpot && light.spotScale > 0.0) {
        float cosOuter = -light.spotOffset / light.spotScale;
        if (cosOuter > 0.7071068) {
            float r = range / (2.0 * cosOuter);
            return vec4(light.position + light.direction * r, r);
        }
        if (cosOuter > 0.0) {
            return vec4(light.position + light.direction * (range * cosOuter),
                        range * sqrt(max(1.0 - cosOuter * cosOuter, 0.0)));
        }
    }
    return vec4(light.position, range);
}

// Whether light i lights anything the tile's rays cross before their surfaces.
bool lightReachesTile(uint i) {
    if (lightScales[i] <= 0.0) return false;
    vec4 sphere = lightBoundingSphere(loadLight(i, push.lights.y));
    if (sphere.w <= 0.0 || push.range.w > 0.5) return true;
    vec3 c = sphere.xyz - camera.cameraPosition.xyz;
    for (int k = 0; k < 4; ++k) {
        if (dot(tilePlanes[k], c) < -sphere.w) return false;
    }
    return length(c) - sphere.w < uintBitsToFloat(tileFarBits);
}

// Marches [segment.x, segment.y] of the ray in `steps` steps from the pixel's dither offset,
// each sample lit by light i (its shadow in `view` when cascade >= 0, else unshadowed; or, for
// a local light, mediumShadow).
vec3 marchSegment(uint i, Light light, vec3 origin, vec3 direction, vec2 segment, float steps,
                  float dither, bool inCascade, ShadowView view, bool shadowed) {
    vec3 radiance = vec3(0.0);
    float dt = (segment.y - segment.x) / steps;
    for (float s = dither; s < steps; s += 1.0) {
        float t = segment.x + s * dt;
        vec3 P = origin + direction * t;
        float density = mediumDensity(P);
        float sigmaT = (push.medium.x + push.medium.y) * density;
        vec3 lit = lightInScatteringUnshadowed(light, i, P, -direction, sigmaT, 0.0);
        if (shadowed) lit *= inCascade ? mediumShadowInView(view, P) : mediumShadow(light, i, P);
        radiance +=
            lit * (push.medium.x * density * exp(-viewOpticalDepth(origin, direction, t)) * dt);
    }
    return radiance;
}

// The sun's in-scattering along [0, farT], cascade by cascade (see the top).
vec3 marchSun(uint i, Light light, vec3 origin, vec3 direction, float farT, float steps,
              float dither) {
    ShadowView none;
    uvec2 entry = kShadowsEnabled ? shadowLights[i] : uvec2(SHADOW_NO_VIEW, 0u);
    if (entry.x == SHADOW_NO_VIEW) {
        return marchSegment(i, light, origin, direction, vec2(0.0, farT), steps, dither, false,
                            none, false);
    }
    vec3 radiance = vec3(0.0);
    float covered = 0.0;
    for (uint c = 0u; c < entry.y && covered < farT; ++c) {
        ShadowView view = shadowViews[entry.x + c];
        float exit = raySphereSegment(origin, direction, view.sphere.xyz, view.sphere.w).y;
        float end = min(exit, farT);
        if (end <= covered) continue;
        radiance += marchSegment(i, light, origin, direction, vec2(covered, end), steps, dither,
                                 true, view, true);
        covered = end;
    }
    if (covered < farT) {
        radiance += marchSegment(i, light, origin, direction, vec2(covered, farT), steps, dither,
                                 false, none, false);
    }
    return radiance;
}

void main() {
    ivec2 half_ = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(camera.frameInfo.xy);
    ivec2 halfSize = (size + 1) / 2;
    bool inside = half_.x < halfSize.x && half_.y < halfSize.y;
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

    if (gl_LocalInvocationIndex == 0u) {
        // The tile's full-resolution pixel edges (2 lo to 2 hi) hold all its rays.
        vec2 lo = vec2(gl_WorkGroupID.xy * gl_WorkGroupSize.xy) * 2.0;
        vec2 hi = lo + vec2(gl_WorkGroupSize.xy) * 2.0;
        vec3 c00 = rayThrough(lo, vec2(size)), c10 = rayThrough(vec2(hi.x, lo.y), vec2(size));
        vec3 c11 = rayThrough(hi, vec2(size)), c01 = rayThrough(vec2(lo.x, hi.y), vec2(size));
        vec3 centre = c00 + c10 + c11 + c01;
        vec3 planes[4] = vec3[4](normalize(cross(c00, c10)), normalize(cross(c10, c11)),
                                 normalize(cross(c11, c01)), normalize(cross(c01, c00)));
        for (int k = 0; k < 4; ++k)
            tilePlanes[k] = dot(planes[k], centre) < 0.0 ? -planes[k] : planes[k];
        tileFarBits = 0u;
    }
    barrier();
    // Positive floats order as their bits.
    if (inside) atomicMax(tileFarBits, floatBitsToUint(surfaceT));
    barrier();

    float dither = (kBayer4x4[(half_.y & 3) * 4 + (half_.x & 3)] + 0.5) / 16.0;
    float steps = float(max(push.grid.w, 1u));
    vec3 radiance = vec3(0.0);
    ShadowView none;
    if (push.medium.x > 0.0) {
        for (uint base = 0u; base < push.lights.x; base += kTileThreads) {
            uint mine = base + gl_LocalInvocationIndex;
            tileHit[gl_LocalInvocationIndex] = mine < push.lights.x && lightReachesTile(mine);
            barrier();
            uint batch = min(kTileThreads, push.lights.x - base);
            for (uint k = 0u; k < batch && inside; ++k) {
                if (!tileHit[k]) continue;
                uint i = base + k;
                Light light = loadLight(i, push.lights.y);
                if (light.type == kLightDirectional) {
                    radiance += marchSun(i, light, origin, direction, surfaceT, steps, dither);
                    continue;
                }
                vec2 segment = lightVolumeSegment(light, origin, direction, surfaceT);
                if (segment.x >= segment.y) continue;
                radiance += marchSegment(i, light, origin, direction, segment, steps, dither, false,
                                         none, true);
            }
            barrier();
        }
    }
    if (inside) imageStore(marched, half_, vec4(radiance, viewDepth));
}
