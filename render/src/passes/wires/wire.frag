#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/specialization_ids.h"
#include "wire_bindings.h"
// Wire shading and coverage (Persson 2014, GPU Pro 5, "Wire Antialiasing"). Geometric antialiasing:
// the pixel's coverage of the wire's (clamped) width from its distance to the centre line, a box
// across the wire one pixel step wide, so the coverages down any column sum to exactly the wire's
// cross-section and a moving wire keeps its energy; times wire.vert's fade (real / clamped radius).
// Shading aliasing: a pixel-thin wire shows a pixel several normals at once, so its normal is bent
// toward the camera and its diffuse term is half-Lambert ((N.L / 2 + 1/2)^2), blended into the true
// cylinder normal and Lambert as the wire grows wider on screen. Lit like the forward transparent
// pass: the clustered lights (with shadows) and the sky. Output straight alpha, blended "over".
#include "common/ambient_lighting.glsl"
#include "common/camera.glsl"
#include "common/clusters.glsl"
#include "common/light_buffer.glsl"
#include "common/screen_segment.glsl"
#include "common/shading_models.glsl"
#include "common/shadows.glsl"
#define FROXEL_INTEGRATED_BINDING WIRE_BINDING_FROXEL_INTEGRATED
#include "common/froxel_lookup.glsl"
#include "wire_segment.glsl"

layout(constant_id = SPEC_CLUSTERED) const bool kClustered = true;
// Image-based lighting: 0 none, 1 split sum, 2 mobile.
layout(constant_id = SPEC_IBL_MODE) const uint kIblMode = 0u;

#include "common/lit_inputs.glsl"
#include "common/pixel_lights.glsl"

// Screen widths (pixels) over which the shading turns from bent normals and half-Lambert (a
// wire a pixel or less wide) to the cylinder's own normals and Lambert.
const float kBentBelowPx = 1.0;
const float kCylinderAbovePx = 4.0;

layout(location = 0) flat in vec4 inEndsPx;
layout(location = 1) flat in vec2 inHalfWidthPx;
layout(location = 2) flat in vec2 inFade;
layout(location = 4) flat in uint inSegment;
layout(location = 5) flat in float inPixelStep;

layout(location = 0) out vec4 outRadiance;  // cd/m^2, a = coverage

vec3 lightRadiance(Surface surface, vec3 P, vec3 N, vec3 V, vec3 R, float alpha, float halfLambert,
                   uint index) {
    Light light = loadLight(index, camera.frameInfo.w);
    LightIncidence incidence = evaluateLight(light, P, N, R, alpha);
    float visibility = any(greaterThan(incidence.incidentIlluminance, vec3(0.0)))
                           ? shadowVisibility(light, index, P, N)
                           : 1.0;
    // Half-Lambert (Persson 2014): wraps the diffuse term round the wire, so the few normals a
    // thin wire shows a pixel light it alike; weighted in by thinness.
    float wrapped = 0.5 * dot(N, incidence.diffuseL) + 0.5;
    incidence.diffuseIlluminance =
        mix(incidence.diffuseIlluminance, incidence.incidentIlluminance * (wrapped * wrapped),
            halfLambert);
    incidence.diffuseIlluminance *= visibility;
    incidence.specularIlluminance *= visibility;
    incidence.incidentIlluminance *= visibility;
    return shadeSurface(surface, N, V, incidence);
}

void main() {
    const WireSegment s = segments[inSegment];
    // Coverage of the clamped width (common/screen_segment.glsl), from the pixel centre's
    // distance to the centre line; its place along the segment gives the width and fade
    // (linear on screen, as wire.vert's quad is). The naive line keeps full coverage.
    const vec2 place = pixelPlaceOnSegment(gl_FragCoord.xy, inEndsPx);
    const float distancePx = place.x;
    const float t = place.y;
    const float halfWidthPx = mix(inHalfWidthPx.x, inHalfWidthPx.y, t);
    const float fade = mix(inFade.x, inFade.y, t);
    const float coverage = draw.mode == WIRE_MODE_NAIVE
                               ? 1.0
                               : segmentCoverage(distancePx, halfWidthPx, inPixelStep);
    const float alpha = coverage * fade;
    if (alpha <= 0.0) discard;

    vec3 radiance = s.emissive.rgb;
    if (s.end.w < 0.5) {
        Surface surface;
        clearSurfaceExtensions(surface);
        surface.baseColor = s.baseColor.rgb;
        surface.roughness = s.emissive.a;
        surface.metallic = s.baseColor.a;
        surface.specular = 0.5;
        surface.shadingModel = kShadingDefaultLit;
        surface.customData = vec4(0.0);

        vec2 ndc = gl_FragCoord.xy / draw.targetSize * 2.0 - 1.0;
        vec4 world = camera.inverseViewProjection * vec4(ndc, gl_FragCoord.z, 1.0);
        vec3 P = world.xyz / world.w;
        vec3 V = safeNormalize(camera.cameraPosition.xyz - P);
        vec3 T = safeNormalize(s.end.xyz - s.start.xyz);
        // The normal bent toward the camera: the view direction without its part along T.
        vec3 bent = safeNormalize(V - T * dot(V, T));
        // The cylinder's own normal at this pixel: across the wire by the pixel's signed
        // offset over the real half width, toward the camera by the rest of the unit circle.
        vec3 axisPoint = s.start.xyz + T * dot(P - s.start.xyz, T);
        vec3 side = P - axisPoint;
        side = safeNormalize(side - bent * dot(side, bent));
        float realHalfWidthPx = halfWidthPx * fade;
        float a = clamp(distancePx / max(realHalfWidthPx, 1e-3), 0.0, 1.0);
        vec3 cylinder = safeNormalize(side * a + bent * sqrt(max(1.0 - a * a, 0.0)));
        float thick = smoothstep(kBentBelowPx, kCylinderAbovePx, 2.0 * realHalfWidthPx);
        vec3 N = safeNormalize(mix(bent, cylinder, thick));
        // Degenerate frames (looking along the wire; a pixel on its silhouette whose offset
        // has no part across it): face the camera rather than shade a zero normal.
        if (dot(N, N) < 0.5) N = V;
        float halfLambert = 1.0 - thick;
        vec3 R = reflect(-V, N);
        float roughnessAlpha = alphaFromRoughness(surface.roughness);
        surface.directionalAlbedo =
            specularDirectionalAlbedo(environmentBrdfLut, surface.roughness, saturate(dot(N, V)));

        if (kIblMode != 0u) {
            vec4 sh[9] = irradianceSh;
            radiance +=
                environmentAmbient(surface, N, V, sh, prefilteredCube, draw.prefilteredMipCount,
                                   environmentBrdfLut, kIblMode == 2u) *
                draw.skyIntensity;
        }
        // Local lights from the cluster's list: they reach the wire where an opaque or blended
        // surface shares its cluster (wires do not mark clusters themselves).
        PixelLights lights = pixelLights(kClustered, draw.directionalCount, draw.grid,
                                         uvec2(gl_FragCoord.xy), gl_FragCoord.z);
        for (uint k = 0u; k < pixelLightCount(lights); ++k) {
            uint light = pixelLightAt(lights, k);
            if (light != kNoLight) {
                radiance += lightRadiance(surface, P, N, V, R, roughnessAlpha, halfLambert, light);
            }
        }
    }
    // The fog's froxels, then the air, in front: a fully covered pixel shows what an opaque
    // surface here would.
    radiance = throughMediumAndAir(radiance, gl_FragCoord);
    outRadiance = vec4(radiance, alpha);
}
