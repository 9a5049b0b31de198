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

layout(constant_id = SPEC_MEDIUM_AREA_LIGHTS) const bool kMediumAreaLights = false;

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

// Lit fraction at P in one shadow view (a cascade the caller chose): one unfiltered lookup.
// 1 outside the view's map.
float mediumShadowInView(ShadowView v, vec3 P) {
    if (!kShadowsEnabled) return 1.0;
    vec4 clip = v.worldToClip * vec4(P, 1.0);
    vec2 uv;
    if (!shadowMapUv(clip, uv)) return 1.0;
    float receiver = shadowViewDepth(v, clip);
    float blocker = shadowBlockerDepth(v, ivec2(floor(v.tile.xy + uv * v.tile.z)));
    float texel = shadowTexelWorld(v, max(receiver, 1e-4));
    return receiver - kShadowDepthBias * texel <= blocker ? 1.0 : 0.0;
}

// Lit fraction of a light at P in the medium: one unfiltered lookup in its map (Vos 2014,
// GPU Pro 5, "Volumetric Light Effects in Killzone: Shadow Fall": the many samples along a ray
// filter it anyway). 1 without a map or outside it.
float mediumShadow(Light light, uint index, vec3 P) {
    if (!kShadowsEnabled) return 1.0;
    ShadowView v;
    if (!shadowViewAt(light, index, P, v)) return 1.0;
    return mediumShadowInView(v, P);
}

bool isMediumAreaLight(Light light) {
    return light.type == LIGHT_TYPE_RECT || light.type == LIGHT_TYPE_DISK;
}

// Irradiance at P from a rect or disk light (issue 15), as Vos's white diffuse surface
// facing the light sees it: the same exact form factor the surfaces' "ltc" diffuse uses
// (area_lights.glsl's areaExactDiffuse) on a surface at P whose normal points at the light's
// centre, times its luminance and falloff window (and the constant-intensity factor of an
// emitter so marked). Zero behind the one-sided emitter.
vec3 areaLightIrradiance(Light light, vec3 P) {
    AreaShape s = areaShapeOf(light);
    vec3 toCenter = s.center - P;
    float window = attenuationWindow(dot(toCenter, toCenter), light.invAttenuationRadius);
    if (window <= 0.0) return vec3(0.0);
    float e = areaExactDiffuse(s, P, safeNormalize(toCenter));
    if ((uint(light.spotOffset) & kAreaEmissionConstantIntensity) != 0u) {
        e *= constantIntensityDiffuseFactor(s, P);
    }
    return light.intensity * (window * e);
}

// Radiance scattered toward the camera per metre at P by one light, per unit sigma_s, before
// its shadow: p(theta) * E * T_light, E the light's irradiance at P (eq. 9 falloff, spot cone;
// rect and disk lights as the area lights they are, areaLightIrradiance) and T_light the
// transmittance from a local light to P (the density at P along the whole leg). toCamera: unit,
// from P to the camera. P stands for a ball of radius `sampleRadius` (a froxel; 0 for a
// point): a point light inside it gets the ball's mean inverse square, 3 / r^2 at its centre,
// instead of a spike that one sample would spread over the whole froxel. areaLights: whether
// rect and disk lights may come (a caller that marches them apart passes false, and its copy
// of this function leaves their code out).
vec3 lightInScatteringUnshadowed(Light light, uint index, vec3 P, vec3 toCamera, float sigmaT,
                                 float sampleRadius, bool areaLights) {
    float scale = lightScales[index];
    if (scale <= 0.0) return vec3(0.0);
    vec3 irradiance;
    vec3 travel;
    if (light.type == kLightDirectional) {
        travel = light.direction;
        irradiance = light.intensity;
    } else if (areaLights && kMediumAreaLights && isMediumAreaLight(light)) {
        vec3 d = P - light.position;
        float distance = length(d);
        travel = distance > 1e-6 ? d / distance : light.direction;
        irradiance = areaLightIrradiance(light, P) * exp(-sigmaT * distance);
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
    return irradiance * (scale * phase);
}

// lightInScatteringUnshadowed with the light's shadow at P (mediumShadow).
vec3 lightInScattering(uint index, vec3 P, vec3 toCamera, float sigmaT, float sampleRadius) {
    if (lightScales[index] <= 0.0) return vec3(0.0);
    Light light = loadLight(index, push.lights.y);
    vec3 lit = lightInScatteringUnshadowed(light, index, P, toCamera, sigmaT, sampleRadius, true);
    if (all(equal(lit, vec3(0.0)))) return lit;
    return lit * mediumShadow(light, index, P);
}

// What the light bins list first (light_bins.h isPlainMediumLight): a local light that is not a
// rect or disk and has no shadow map.
bool isPlainMediumLight(uint index) {
    uint type = uint(lightData[3u * push.lights.y + index].w);
    return type != kLightDirectional && type != LIGHT_TYPE_RECT && type != LIGHT_TYPE_DISK &&
           lightUnshadowed(index);
}

// lightInScattering of a plain light (above): its body compiles neither shadow nor area code.
vec3 plainLightInScattering(uint index, vec3 P, vec3 toCamera, float sigmaT, float sampleRadius) {
    Light light = loadLight(index, push.lights.y);
    return lightInScatteringUnshadowed(light, index, P, toCamera, sigmaT, sampleRadius, false);
}

// The in-scattering at P (a ball of radius sampleRadius) of the batch of lights the push
// constants name (lights.z, the first, and lights.w of them), per metre, and the extinction
// there (1/m) in w.
vec4 mediumAt(vec3 P, vec3 toCamera, float sampleRadius) {
    float density = mediumDensity(P);
    float sigmaT = (push.medium.x + push.medium.y) * density;
    vec3 sum = vec3(0.0);
    if (push.medium.x > 0.0 && density > 0.0) {
        uint end = min(push.lights.z + push.lights.w, push.lights.x);
        for (uint i = push.lights.z; i < end; ++i)
            sum += lightInScattering(i, P, toCamera, sigmaT, sampleRadius);
    }
    return vec4(sum * (push.medium.x * density), sigmaT);
}

#endif
