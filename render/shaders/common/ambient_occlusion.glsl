// Ambient occlusion shared by the AO passes (positions from the reverse-Z depth) and the
// lighting pass (multi-bounce, specular occlusion). render/README.md "Ambient occlusion".
#ifndef CANDELA_AMBIENT_OCCLUSION_GLSL
#define CANDELA_AMBIENT_OCCLUSION_GLSL

#include "common/camera.glsl"
#include "common/math.glsl"

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

#endif
