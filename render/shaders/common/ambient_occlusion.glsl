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

// Solid angle shared by two spherical caps (cosines of their half-angles) whose axes are
// `cosDistance` apart, divided by the smaller cap's: Oat and Sander 2007's smoothstep fit of
// the lens between the two.
float capOverlapFraction(float cosCap1, float cosCap2, float cosDistance) {
    float r1 = acos(clamp(cosCap1, -1.0, 1.0));
    float r2 = acos(clamp(cosCap2, -1.0, 1.0));
    float d = acos(clamp(cosDistance, -1.0, 1.0));
    if (min(r1, r2) <= max(r1, r2) - d) return 1.0;  // one cap inside the other
    if (r1 + r2 <= d) return 0.0;                    // apart
    float delta = abs(r1 - r2);
    float x = 1.0 - saturate((d - delta) / max(r1 + r2 - delta, 1e-6));
    return smoothstep(0.0, 1.0, x);
}

// Specular occlusion by the cone-cone approximation (Jimenez et al. 2016): the visible part of
// the hemisphere as a cone around the bent normal whose cosine-weighted solid angle is the
// visibility (sin^2 of its half-angle), the reflection lobe as a cone around R holding most
// of GGX's energy (its half-angle grows with alpha); the occlusion is the share of the lobe's
// cone inside the visible one.
float coneConeSpecularOcclusion(vec3 bentNormal, float visibility, vec3 R, float roughness) {
    float cosVisible = sqrt(saturate(1.0 - visibility));
    float alpha = max(roughness * roughness, 1e-3);
    // Half-angle of the cone around R: ~atan(alpha) for GGX's central lobe, widened so a
    // fully rough lobe covers the hemisphere.
    float cosLobe = cos(min(atan(alpha) * 1.57, 0.5 * PI));
    float lobeCap = 1.0 - cosLobe;
    float visibleCap = 1.0 - cosVisible;
    float overlap = capOverlapFraction(cosVisible, cosLobe, dot(bentNormal, R));
    // The overlap is a share of the smaller cap: as a share of the lobe's cap.
    return saturate(overlap * min(lobeCap, visibleCap) / max(lobeCap, 1e-6));
}

#endif
