// What every volumetric lighting shader shares (render/README.md "Volumetric lighting"): the
// medium (Fog component), the Henyey-Greenstein phase function and one light's in-scattering
// at a point, with the camera, light buffer and shadow declarations they need.
#ifndef CANDELA_VOLUMETRIC_MEDIUM_GLSL
#define CANDELA_VOLUMETRIC_MEDIUM_GLSL

#include "common/camera.glsl"
#include "common/light_buffer.glsl"
#include "common/math.glsl"
#define SHADOW_ATLAS_BINDING VOLUMETRICS_BINDING_SHADOW_ATLAS
#define SHADOW_ATLAS_COMPARE_BINDING VOLUMETRICS_BINDING_SHADOW_ATLAS_COMPARE
#define SHADOW_VIEWS_BINDING VOLUMETRICS_BINDING_SHADOW_VIEWS
#define SHADOW_LIGHTS_BINDING VOLUMETRICS_BINDING_SHADOW_LIGHTS
#include "common/shadows.glsl"
#include "volumetric_step.glsl"
#include "volumetrics_push.glsl"
#include "volumetric_density.glsl"

layout(std430, binding = VOLUMETRICS_BINDING_LIGHT_SCALES) readonly buffer LightScales {
    float lightScales[];
};


// Henyey-Greenstein phase function (1/sr), cosTheta between the light's travel and the
// direction scattered toward the camera; 1 / (4 pi) at g = 0.
float henyeyGreenstein(float cosTheta, float g) {
    float g2 = g * g;
    float denominator = max(1.0 + g2 - 2.0 * g * cosTheta, 1e-6);
    return (1.0 - g2) / (4.0 * PI * denominator * sqrt(denominator));
}

// Lit fraction of a light at P in the medium: one unfiltered lookup in its map (seed 004 §3:
// the many samples along a ray filter it anyway). 1 without a map or outside it.
float mediumShadow(Light light, uint index, vec3 P) {
    if (!kShadowsEnabled) return 1.0;
    ShadowView v;
    float receiver, blocker;
    if (!shadowMapLookup(light, index, P, v, receiver, blocker)) return 1.0;
    float texel = shadowTexelWorld(v, max(receiver, 1e-4));
    return receiver - kShadowDepthBias * texel <= blocker ? 1.0 : 0.0;
}

// Radiance scattered toward the camera per metre at P by one light, per unit sigma_s:
// p(theta) * E * T_light, E the light's irradiance at P (eq. 9 falloff, spot cone; sources
// as points) and T_light the transmittance from a local light to P (the density at P along
// the whole leg). toCamera: unit, from P to the camera. P stands for a ball of radius
// `sampleRadius` (a froxel; 0 for a point): a light inside it gets the ball's mean inverse
// square, 3 / r^2 at its centre, instead of a spike that one sample would spread over the
// whole froxel.
vec3 lightInScattering(uint index, vec3 P, vec3 toCamera, float sigmaT, float sampleRadius) {
    float scale = lightScales[index];
    if (scale <= 0.0) return vec3(0.0);
    Light light = loadLight(index, push.lights.y);
    vec3 irradiance;
    vec3 travel;
    if (light.type == kLightDirectional) {
        travel = light.direction;
        irradiance = light.intensity;
    } else {
        vec3 d = P - light.position;
        float distanceSq = dot(d, d);
        float window = attenuationWindow(distanceSq, light.invAttenuationRadius);
        if (window <= 0.0) return vec3(0.0);
        travel = d * inversesqrt(max(distanceSq, 1e-12));
        float spreadSq = max(distanceSq, sampleRadius * sampleRadius / 3.0);
        irradiance = light.intensity * (window * inverseSquare(spreadSq) *
                                        exp(-sigmaT * sqrt(distanceSq)));
        if (light.type == kLightSpot) irradiance *= spotAttenuation(light, -travel);
    }
    float phase = henyeyGreenstein(dot(travel, toCamera), push.medium.z);
    return irradiance * (scale * phase * mediumShadow(light, index, P));
}

// The in-scattering at P (a ball of radius sampleRadius) of the batch of lights the push
// constants name (lights.z, the first, and lights.w of them), per metre, and the extinction
// there (1/m) in w.
vec4 mediumAt(vec3 P, vec3 toCamera, float sampleRadius) {
    float density = mediumDensity(P);
    float sigmaT = (push.medium.x + push.medium.y) * density;
    vec3 sum = vec3(0.0);
    if (push.medium.x > 0.0) {
        uint end = min(push.lights.z + push.lights.w, push.lights.x);
        for (uint i = push.lights.z; i < end; ++i)
            sum += lightInScattering(i, P, toCamera, sigmaT, sampleRadius);
    }
    return vec4(sum * (push.medium.x * density), sigmaT);
}

#endif
