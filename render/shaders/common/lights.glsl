// Light incidence (Karis 2013, "Real Shading in Unreal Engine 4", lighting model): windowed
// inverse-square falloff (eq. 9), sphere lights (eq. 10-14) and tube lights (eq. 16-20), all
// in metres. Every function is finite for
// any finite input: d -> 0, zero radius or length, R parallel to the tube, huge intensities.
#ifndef CANDELA_LIGHTS_GLSL
#define CANDELA_LIGHTS_GLSL

#include "common/light_types.h"
#include "common/math.glsl"
#include "common/sphere_irradiance.glsl"
#include "common/specialization_ids.h"

// Light type codes (common/light_types.h, written by render/src/gpu_light.cpp).
const uint kLightPoint = LIGHT_TYPE_POINT;
const uint kLightSpot = LIGHT_TYPE_SPOT;
const uint kLightDirectional = LIGHT_TYPE_DIRECTIONAL;

// What clustered culling bounds a light type by (common/light_types.h; the render light-type
// table's `bounds`): culling asks for the kind, never for a type.
const uint kLightBoundsEverywhere = LIGHT_BOUNDS_EVERYWHERE;
const uint kLightBoundsFalloff = LIGHT_BOUNDS_FALLOFF;
const uint kLightBoundsCone = LIGHT_BOUNDS_CONE;
const uint kLightBoundsHalfSpace = LIGHT_BOUNDS_HALF_SPACE;
const uint kLightBoundsByType[LIGHT_TYPE_COUNT] = uint[](LIGHT_BOUNDS_BY_TYPE);
uint lightBoundsKind(uint type) {
    return kLightBoundsByType[min(type, uint(LIGHT_TYPE_COUNT) - 1u)];
}
// Directional lights: listed once for every pixel, ahead of the cluster lists.
bool lightInEveryCluster(uint type) {
    return lightBoundsKind(type) == kLightBoundsEverywhere;
}

// Light shapes compiled into this shader variant (SPEC "Model only what a scene needs"); the
// renderer turns off the shapes its scene does not have, and the driver drops their code.
layout(constant_id = SPEC_SPHERE_LIGHTS_ENABLED) const bool kSphereLightsEnabled = true;
layout(constant_id = SPEC_TUBE_LIGHTS_ENABLED) const bool kTubeLightsEnabled = true;
layout(constant_id = SPEC_SPOT_LIGHTS_ENABLED) const bool kSpotLightsEnabled = true;
layout(constant_id = SPEC_RECT_LIGHTS_ENABLED) const bool kRectLightsEnabled = true;
layout(constant_id = SPEC_DISK_LIGHTS_ENABLED) const bool kDiskLightsEnabled = true;
// The renderer's --area-lights (RendererOptions::areaLights): LTC (true) or representative.
layout(constant_id = SPEC_AREA_LIGHTS_LTC) const bool kAreaLightsLtc = true;
// The integration paths the frame's lights take (AREA_PATH_* bits); the others compile out.
layout(constant_id = SPEC_AREA_LIGHT_PATHS) const uint kAreaLightPaths = AREA_PATHS_ALL;
bool areaPathTaken(uint path) {
    return (kAreaLightPaths & path) != 0u;
}

// The "+1" of eq. 9 is 1 cm^2 in UE4's centimetres: 1e-4 m^2 here. Without the conversion a
// light 2 m away would be 20% too dark.
const float kFalloffBias = 1e-4;

// One light as a lighting shader sees it (unpacked from the structure-of-arrays buffers).
struct Light {
    vec3 position;
    float invAttenuationRadius;  // 1 / attenuationRadius
    vec3 intensity;              // colour * candela (lumens / 4 pi); lux for directional
    float sourceRadius;
    vec3 direction;              // spot axis, the direction light travels (directional), or
                                 // the emitting normal (rect, disk: the node's -Z)
    float sourceLength;
    vec3 tubeAxis;               // unit; a tube spans position +- tubeAxis * sourceLength / 2;
                                 // rect, disk: the node's +X
    uint type;
    float spotScale;             // 1 / (cos inner - cos outer)
    float spotOffset;            // -cos outer * spotScale; rect, disk: quality + emission (area_lights.glsl)
    vec2 shape;                  // per-type parameters (render/src/lights/gpu_light_types.h)
};

// What a light delivers at a surface point, before the BRDF.
struct LightIncidence {
    vec3 diffuseL;             // unit direction for diffuse (to the light's centre)
    vec3 diffuseIlluminance;   // lux: includes NoL, or the sphere/line irradiance
    vec3 specularL;            // unit direction to the representative point
    vec3 specularIlluminance;  // lux: incl. NoL at specularL and energy normalisation
    vec3 incidentIlluminance;  // lux at normal incidence, no cosine (for wrap/transmission)
    // (magnitude n, Fresnel part f) when specularIlluminance is already the lobe's integral
    // over the light (area lights by LTC, area_lights.glsl): specular = (F0 (n - f) + F90 f) x
    // specularIlluminance. (0, 0): evaluate the BRDF along specularL.
    vec2 specularLtc;
};

// eq. 9 numerator: reaches exactly zero at the attenuation radius, so culling by that radius
// never changes the image.
float attenuationWindow(float distanceSq, float invRadius) {
    float ratio2 = distanceSq * invRadius * invRadius;
    float w = saturate(1.0 - ratio2 * ratio2);
    return w * w;
}

// eq. 9 denominator, metres.
float inverseSquare(float distanceSq) {
    return 1.0 / (distanceSq + kFalloffBias);
}

float spotAttenuation(Light light, vec3 L) {
    float a = saturate(dot(-L, light.direction) * light.spotScale + light.spotOffset);
    return a * a;
}

// eq. 11: point on the sphere closest to the reflection ray (L: to the centre).
vec3 sphereRepresentativePoint(vec3 L, vec3 R, float sourceRadius) {
    vec3 centerToRay = dot(L, R) * R - L;
    float scale = saturate(sourceRadius * inversesqrt(max(dot(centerToRay, centerToRay), 1e-30)));
    return L + centerToRay * scale;
}

// eq. 10 + 14: (alpha / alpha')^2, alpha' widened by the sphere's angular size.
float sphereEnergyNormalization(float alpha, float sourceRadius, float distance) {
    float widened = saturate(alpha + sourceRadius / (3.0 * max(distance, 1e-6)));
    float ratio = alpha / max(widened, 1e-12);
    return ratio * ratio;
}

// eq. 16 in metres (the "+2" is 2 cm^2): mean of cos / d^2 along the segment L0..L1, so the
// tube's intensity spreads uniformly along it. Equals NoL / (d^2 + 1e-4) for L0 == L1.
float lineIrradiance(vec3 N, vec3 L0, vec3 L1) {
    float len0 = length(L0);
    float len1 = length(L1);
    float cosSum = dot(N, L0) / (2.0 * max(len0, 1e-12)) + dot(N, L1) / (2.0 * max(len1, 1e-12));
    // |L0||L1| + L0.L1 cancels when the shaded point is near the segment (L0, L1 opposite):
    // for a 10 km tube 1 m away it came out 0 or negative, giving Inf, NaN or 1e4x too bright
    // (found by tests/render/stability). There the equal |L0 x L1|^2 / (|L0||L1| - L0.L1) is
    // used, with L0 x L1 = L0 x (L1 - L0) free of the cancellation.
    float L0oL1 = dot(L0, L1);
    vec3 L0xL1 = cross(L0, L1 - L0);
    float denominator = L0oL1 >= 0.0 ? len0 * len1 + L0oL1
                                     : dot(L0xL1, L0xL1) / (len0 * len1 - L0oL1);
    return 2.0 * saturate(cosSum) / (denominator + 2.0 * kFalloffBias);
}

// eq. 19: parameter of the point on segment L0 + t * Ld closest to the reflection ray R.
float tubeClosestParameter(vec3 L0, vec3 Ld, vec3 R) {
    float RoLd = dot(R, Ld);
    float LdoLd = dot(Ld, Ld);
    float denominator = LdoLd - RoLd * RoLd;  // |Ld|^2 sin^2: 0 when R is parallel to the tube
    float t = (dot(R, L0) * RoLd - dot(L0, Ld)) / max(denominator, 1e-30);
    return saturate(t);
}

// eq. 20: alpha / alpha', widened along one axis by half the tube's angular length
// (by analogy with eq. 10, where the widening is a third of the angular radius).
float tubeEnergyNormalization(float alpha, float sourceLength, float distance) {
    float widened = saturate(alpha + 0.5 * sourceLength / (3.0 * max(distance, 1e-6)));
    return alpha / max(widened, 1e-12);
}

// Full incidence of a punctual (point/spot, sphere, tube) light. alpha is the GGX alpha of
// the surface (for the energy normalisations), R the reflection vector.
LightIncidence evaluateLocalLight(Light light, vec3 P, vec3 N, vec3 R, float alpha) {
    LightIncidence o;
    vec3 toCenter = light.position - P;
    float centerDistSq = dot(toCenter, toCenter);
    o.diffuseL = safeNormalize(toCenter);

    vec3 closestOnTube = toCenter;
    float diffuseFactor;  // lux per candela, with cosine
    float energy = 1.0;
    vec3 specularPoint = toCenter;
    if (kTubeLightsEnabled && light.sourceLength > 0.0) {
        vec3 halfSegment = light.tubeAxis * (0.5 * light.sourceLength);
        vec3 L0 = toCenter - halfSegment;
        vec3 L1 = toCenter + halfSegment;
        vec3 Ld = L1 - L0;
        // Window distance: to the nearest point of the segment, matching the capsule bound.
        float tNearest = saturate(-dot(L0, Ld) / max(dot(Ld, Ld), 1e-30));
        closestOnTube = L0 + tNearest * Ld;
        diffuseFactor = lineIrradiance(N, L0, L1);
        specularPoint = L0 + tubeClosestParameter(L0, Ld, R) * Ld;
        energy *= tubeEnergyNormalization(alpha, light.sourceLength, length(specularPoint));
    } else if (kSphereLightsEnabled && light.sourceRadius > 0.0) {
        float sinSigmaSq = light.sourceRadius * light.sourceRadius / max(centerDistSq, 1e-30);
        // Sphere luminance = I / (pi r^2); irradiance = luminance * factor, i.e. per candela
        // factor / (pi sin^2 sigma) / d^2. A sphere whose sin^2 sigma underflows (radius under
        // ~1e-15 of the distance) is a point: dividing by its r^2 gave 0 / 0 = NaN (found by
        // tests/render/stability).
        float cosTheta = dot(N, o.diffuseL);
        float relativeToPoint = sinSigmaSq > 1e-30
                                    ? sphereIrradianceFactor(cosTheta, sinSigmaSq) / (PI * sinSigmaSq)
                                    : saturate(cosTheta);
        // Far away the factor equals NoL / d^2; the +1e-4 bias keeps the point-light limit.
        diffuseFactor = relativeToPoint * inverseSquare(centerDistSq);
    } else {
        diffuseFactor = saturate(dot(N, o.diffuseL)) * inverseSquare(centerDistSq);
    }
    if (kSphereLightsEnabled && light.sourceRadius > 0.0) {
        float specularDist = length(specularPoint);
        specularPoint = sphereRepresentativePoint(specularPoint, R, light.sourceRadius);
        energy *= sphereEnergyNormalization(alpha, light.sourceRadius, specularDist);
    }

    float window = attenuationWindow(dot(closestOnTube, closestOnTube), light.invAttenuationRadius);
    vec3 intensity = light.intensity * window;
    if (kSpotLightsEnabled && light.type == kLightSpot) intensity *= spotAttenuation(light, o.diffuseL);

    o.specularL = safeNormalize(specularPoint);
    float specularDistSq = max(dot(specularPoint, specularPoint), 0.0);
    float NoLs = saturate(dot(N, o.specularL));
    o.diffuseIlluminance = intensity * diffuseFactor;
    o.specularIlluminance = intensity * (NoLs * inverseSquare(specularDistSq) * energy);
    o.incidentIlluminance = intensity * inverseSquare(centerDistSq);
    o.specularLtc = vec2(0.0);
    return o;
}

// evaluateLocalLight of a point or spot light without a size (isPlainLocalLight): the same
// operations without the sphere and tube code, which lavapipe would run for it anyway.
LightIncidence evaluatePlainLocalLight(Light light, vec3 P, vec3 N) {
    LightIncidence o;
    vec3 toCenter = light.position - P;
    float centerDistSq = dot(toCenter, toCenter);
    o.diffuseL = safeNormalize(toCenter);
    float diffuseFactor = saturate(dot(N, o.diffuseL)) * inverseSquare(centerDistSq);
    float window = attenuationWindow(dot(toCenter, toCenter), light.invAttenuationRadius);
    vec3 intensity = light.intensity * window;
    if (kSpotLightsEnabled && light.type == kLightSpot) intensity *= spotAttenuation(light, o.diffuseL);
    o.specularL = safeNormalize(toCenter);
    float specularDistSq = max(dot(toCenter, toCenter), 0.0);
    float NoLs = saturate(dot(N, o.specularL));
    o.diffuseIlluminance = intensity * diffuseFactor;
    o.specularIlluminance = intensity * (NoLs * inverseSquare(specularDistSq) * 1.0);
    o.incidentIlluminance = intensity * inverseSquare(centerDistSq);
    o.specularLtc = vec2(0.0);
    return o;
}

// A point or spot light without a size: what evaluatePlainLocalLight takes.
bool isPlainLocalLight(Light light) {
    return (light.type == LIGHT_TYPE_POINT || light.type == kLightSpot) &&
           !(light.sourceRadius > 0.0) && !(light.sourceLength > 0.0);
}

LightIncidence evaluateDirectionalLight(Light light, vec3 N) {
    LightIncidence o;
    o.diffuseL = -light.direction;
    o.specularL = o.diffuseL;
    float NoL = saturate(dot(N, o.diffuseL));
    o.diffuseIlluminance = light.intensity * NoL;
    o.specularIlluminance = o.diffuseIlluminance;
    o.incidentIlluminance = light.intensity;
    o.specularLtc = vec2(0.0);
    return o;
}

#include "common/area_lights.glsl"

// Per-light `quality` of a point or spot light (sphere, tube): Light.shape.x (gpu_light.cpp),
// coded as an area light's (kAreaQuality*).
bool localLightRepresentative(Light light) {
    uint quality = uint(light.shape.x);
    return quality == kAreaQualityRepresentative || (quality == kAreaQualityDefault && !kAreaLightsLtc);
}

#ifdef AREA_LIGHT_LTC_MATRIX_BINDING
// A sphere (sourceRadius > 0, sourceLength 0) or tube (sourceLength > 0) light whose
// specular is its fitted LTC integrated over the light (issue 15, report "area lights by LTC":
// the representative point is off by 222 % at roughness 0.1, sin sigma 0.4, LTC within a few
// %): the sphere as the disk facing P with the same cone (ltcSphereIntegral) at luminance
// I / (pi r^2), the tube as the Lambertian capsule of the same lumens (ltcTubeIntegrals: a thin
// one the closed-form Lambertian line, a thick one the outline of its cone). A tube's diffuse is
// the same capsule's irradiance (the integral with M^-1 = identity), 4 / pi brighter across its
// axis than lineIrradiance's isotropic segment of the same lumens; a sphere's stays
// evaluateLocalLight's (exact). Falloff window, spot cone and incident illuminance stay `o`'s, so
// evaluateLocalLight runs once per light whatever the mode.
LightIncidence withLtcIntegrals(LightIncidence o, Light light, vec3 P, vec3 N, vec3 R, float alpha) {
    vec3 toCenter = light.position - P;
    vec3 halfSegment = light.tubeAxis * (0.5 * light.sourceLength);
    vec3 L0 = toCenter - halfSegment;
    vec3 Ld = 2.0 * halfSegment;
    bool tube = kTubeLightsEnabled && light.sourceLength > 0.0;
    // The window's distance as evaluateLocalLight measures it (nearest point of the segment).
    vec3 windowPoint = tube ? L0 + saturate(-dot(L0, Ld) / max(dot(Ld, Ld), 1e-30)) * Ld : toCenter;
    vec3 intensity =
        light.intensity * attenuationWindow(dot(windowPoint, windowPoint), light.invAttenuationRadius);
    if (kSpotLightsEnabled && light.type == kLightSpot) intensity *= spotAttenuation(light, o.diffuseL);

    vec3 V = 2.0 * dot(N, R) * N - R;  // R = reflect(-V, N)
    vec2 uv = ltcTableUv(sqrt(alpha), saturate(dot(N, V)));
    mat3 frame = ltcShadingFrame(N, V);
    mat3 minv = ltcInverseMatrix(texture(ltcMatrixTable, uv));
    o.specularLtc = texture(ltcMagnitudeTable, uv).xy;
    float integral;  // the unit-magnitude lobe's integral per candela
    if (tube) {
        vec3 p0 = frame * L0, p1 = frame * (L0 + Ld);
        vec2 integrals = ltcTubeIntegrals(minv, p0, p1, light.sourceRadius);
        integral = integrals.x * ltcTubeLobeCorrection(minv, o.specularLtc.x, alpha, frame * V, p0, p1);
        o.diffuseIlluminance = intensity * (PI * integrals.y);
    } else {
        float radius = light.sourceRadius;
        integral = ltcSphereIntegral(minv, frame * toCenter, radius) / (PI * radius * radius);
    }
    o.specularL = R;
    o.specularIlluminance = intensity * integral;
    return o;
}
#endif

// Sphere and tube lights go by LTC when the shader binds the table, the light's quality (or
// the renderer's default) says ltc, and the sphere is not so small against its distance that
// its luminance I / (pi r^2) loses precision (sin sigma under 1e-3: a point, where the
// representative point is exact). A tube's specular and diffuse are its capsule's (ltc_tube.glsl).
bool localLightByLtc(Light light, vec3 P) {
#ifdef AREA_LIGHT_LTC_MATRIX_BINDING
    if (!areaPathTaken(AREA_PATH_PUNCTUAL_LTC) || localLightRepresentative(light)) return false;
    if (kTubeLightsEnabled && light.sourceLength > 0.0) return true;
    if (!kSphereLightsEnabled || !(light.sourceRadius > 0.0)) return false;
    vec3 toCenter = light.position - P;
    return light.sourceRadius * light.sourceRadius > 1e-6 * dot(toCenter, toCenter);
#else
    return false;
#endif
}

// A point, spot, sphere or tube light: evaluateLight without the rect and disk code (a loop of
// such lights leaves that code out, lavapipe running it for every light otherwise).
LightIncidence evaluatePunctualLight(Light light, vec3 P, vec3 N, vec3 R, float alpha) {
    LightIncidence o = evaluateLocalLight(light, P, N, R, alpha);
#ifdef AREA_LIGHT_LTC_MATRIX_BINDING
    if (localLightByLtc(light, P)) o = withLtcIntegrals(o, light, P, N, R, alpha);
#endif
    return o;
}

// The incidence of any light: one function per light type, chosen by its type code. A new type
// adds its function above and its case here (render/README.md "Adding a light type").
LightIncidence evaluateLight(Light light, vec3 P, vec3 N, vec3 R, float alpha) {
    if (light.type == kLightDirectional) return evaluateDirectionalLight(light, N);
    if ((kRectLightsEnabled && light.type == LIGHT_TYPE_RECT) ||
        (kDiskLightsEnabled && light.type == LIGHT_TYPE_DISK)) {
        // The per-light "quality" wins over the renderer's default.
        uint code = uint(light.spotOffset);
        uint quality = code & 3u;
        bool representative = quality == kAreaQualityRepresentative ||
                              (quality == kAreaQualityDefault && !kAreaLightsLtc);
        // A path no light of the frame takes is a constant, and its code drops out.
        if (!areaPathTaken(AREA_PATH_LTC)) representative = true;
        if (!areaPathTaken(AREA_PATH_REPRESENTATIVE)) representative = false;
        bool constantIntensity = areaPathTaken(AREA_PATH_CONSTANT_INTENSITY) &&
                                 (code & kAreaEmissionConstantIntensity) != 0u;
        return evaluateAreaLight(light, P, N, R, alpha, representative, constantIntensity);
    }
    return evaluatePunctualLight(light, P, N, R, alpha);
}

#endif
