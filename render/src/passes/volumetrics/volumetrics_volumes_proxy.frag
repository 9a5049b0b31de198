#version 460
#extension GL_GOOGLE_include_directive : require
#include "volumetrics_bindings.h"
// Per-light volumes, rasterised (Vos 2014, GPU Pro 5, "Volumetric Light Effects in Killzone: Shadow
// Fall"): a fragment of light i's proxy mesh at half-resolution pixel q marches the part of q's
// view ray inside the light's volume (the exact sphere or cone segment, cut at the surface's depth
// and the medium's box), exactly as the tile-binned march does (volumes_march.glsl), and adds it to
// the target (additive blending; alpha, the view depth the full-screen pass stored, is kept). A
// proxy the camera is outside draws its front faces tested against the half-resolution depth, so a
// volume behind the surfaces costs no fragments; one that holds the camera or reaches the near
// plane draws its back faces untested. Rect and disk lights draw in their own variant
// (SPEC_MEDIUM_AREA_LIGHTS: their form-factor code, present but unrun, made the march 10x slower on
// lavapipe).
#include "volumes_march.glsl"

layout(location = 0) flat in uint lightIndex;
layout(location = 0) out vec4 scattered;

void main() {
    VolumeRay ray = volumeRay(ivec2(gl_FragCoord.xy));
    vec3 radiance = vec3(0.0);
    vec2 span = mediumSpan(ray.origin, ray.direction, ray.surfaceT);
    if (push.medium.x > 0.0 && span.x < span.y) {
        Light light = loadLight(lightIndex, push.lights.y);
        radiance = marchLocalLight(lightIndex, light, ray, span, float(max(push.grid.w, 1u)),
                                   kMediumAreaLights);
    }
    scattered = vec4(radiance, 0.0);
}
