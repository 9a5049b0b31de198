// Ambient occlusion shared by the AO passes (positions from the reverse-Z depth) and the
// lighting pass (multi-bounce, specular occlusion). render/README.md "Ambient occlusion".
#ifndef CANDELA_AMBIENT_OCCLUSION_GLSL
#define CANDELA_AMBIENT_OCCLUSION_GLSL

#include "common/camera.glsl"
#include "common/math.glsl"

// The lighting pass's ambient occlusion variants (its SPEC_AMBIENT_OCCLUSION constant; the SSR
// trace's push constant).
const uint kAoOff = 0u;
const uint kAoGtao = 1u;
const uint kAoReference = 2u;
const uint kAoGtaoHorizonSpecular = 3u;  // GTAO, specular occlusion from its horizon slice

vec3 aoWorldFromDepth(vec2 pixelCentre, float depth) {
    vec2 ndc = pixelCentre / vec2(camera.frameInfo.xy) * 2.0 - 1.0;
    vec4 world = camera.inverseViewProjection * vec4(ndc, depth, 1.0);
    return world.xyz / world.w;
}

// Clip-space position: .xy / .w is NDC, .w the view distance along the axis.
vec4 clipOf(vec3 world) {
    return camera.viewProjection * vec4(world, 1.0);
}

// Deterministic per-pixel numbers in [0, 1) (the same image every run).
vec2 aoPixelNoise(ivec2 pixel) {
    uvec2 v = uvec2(pixel) * uvec2(1664525u, 1013904223u);
    v.x += v.y * 1664525u;
    v.y += v.x * 1013904223u;
    v ^= v >> 16u;
    return vec2(v & 0xFFFFu) / 65536.0;
}

// Jimenez et al. 2016's fit of multi-bounce occlusion: light that an occluder of the same
// albedo bounces back brightens the occlusion of bright surfaces (never below `visibility`).
vec3 multiBounceOcclusion(float visibility, vec3 albedo) {
    vec3 a = 2.0404 * albedo - 0.3324;
    vec3 b = -4.7951 * albedo + 0.6417;
    vec3 c = 2.7552 * albedo + 0.6903;
    vec3 x = vec3(visibility);
    return max(x, ((x * a + b) * x + c) * x);
}

// Specular occlusion from the visibility alone (Lagarde and de Rousiers 2014): the lobe of a
// smooth surface seen head-on is occluded like the hemisphere, grazing and rough lobes less.
// Measured against the reference's lobe rays (docs/speed-vs-error.md) it errs no more than the
// cone-cone approximation around the bent normal, which darkened the rims of unoccluded
// glossy spheres (their grazing reflection falls outside any cone narrower than the
// hemisphere) and, with a visibility of 1, leaves specular untouched exactly.
float specularOcclusionFromVisibility(float visibility, float NoV, float roughness) {
    return saturate(pow(NoV + visibility, exp2(-16.0 * roughness - 1.0)) - 1.0 + visibility);
}

// The visibility the lighting pass gives the environment's specular (its split sum and the
// multiple scattering with it): the material's `occlusion` without ambient occlusion; with it,
// the reference's lobe visibility, or the visibility form above, for GTAO with horizons
// blended in for smooth lobes (GTAO's horizons in the slice that holds R: right for lobes
// narrow enough to stay in that slice, too dark for rough ones, which the visibility form
// handles better; measured, render/README.md "Ambient occlusion"), each at `aoIntensity`,
// then the minimum with the material's occlusion (both see the same nearby geometry: a crease
// is not darkened twice). aoVisibility: the AO image's w; horizonVisibility: the specular
// occlusion image's r (unused by plain GTAO).
float environmentSpecularVisibility(uint aoMode, float aoIntensity, float aoVisibility,
                                    float horizonVisibility, float NoV, float roughness,
                                    float occlusion) {
    if (aoMode == kAoOff) return occlusion;
    float specularVisibility;
    if (aoMode == kAoReference) {
        specularVisibility = mix(1.0, saturate(horizonVisibility), aoIntensity);
    } else {
        float visibility = mix(1.0, saturate(aoVisibility), aoIntensity);
        specularVisibility = specularOcclusionFromVisibility(visibility, NoV, roughness);
        if (aoMode == kAoGtaoHorizonSpecular) {
            float fromHorizons = mix(1.0, saturate(horizonVisibility), aoIntensity);
            specularVisibility =
                mix(fromHorizons, specularVisibility, smoothstep(0.35, 0.65, roughness));
        }
    }
    return min(specularVisibility, occlusion);
}

#endif
