// Specular of a sphere or tube light on a surface at the origin with N = +Z, F0 = 1 (Fresnel
// exactly 1, so only the light's integration is compared): the engine's representative point
// (evaluateLocalLight + specularGgx's D and Vis) and Monte Carlo over the light's surface with
// the same D and Vis, for the report's cost rows.
#ifndef CANDELA_REPORT_AREA_LIGHT_INTEGRATION_GLSL
#define CANDELA_REPORT_AREA_LIGHT_INTEGRATION_GLSL

#include "common/brdf.glsl"
#include "common/ibl.glsl"
#include "common/lights.glsl"
#include "common/ltc_area_lights.glsl"

const vec3 kSurfaceNormal = vec3(0.0, 0.0, 1.0);

// D Vis NoL E for light direction L (unit) and illuminance E at normal incidence.
float specularTimesNoL(vec3 V, vec3 L, float alpha) {
    vec3 H = safeNormalize(V + L);
    float NoV = saturate(V.z);
    float NoL = saturate(L.z);
    float NoH = saturate(H.z);
    return distributionGgx(alpha * alpha, NoH) * visibilitySmithSchlick(alpha, NoV, NoL) * NoL;
}

// The lighting pass's specular (shading_models.glsl specularGgx) with F = 1, with Karis 2013's
// ("Real Shading in Unreal Engine 4") Schlick-Smith visibility or (correlated) the
// energy-conserving BRDF's height-correlated Smith.
float representativePointSpecular(Light light, vec3 V, float roughness, bool correlated) {
    float alpha = alphaFromRoughness(roughness);
    vec3 N = kSurfaceNormal;
    vec3 R = reflect(-V, N);
    LightIncidence inc = evaluateLocalLight(light, vec3(0.0), N, R, alpha);
    vec3 H = safeNormalize(V + inc.specularL);
    float NoV = saturate(dot(N, V));
    float NoL = saturate(dot(N, inc.specularL));
    float NoH = saturate(dot(N, H));
    float visibility = correlated ? visibilitySmithGgxCorrelated(alpha, NoV, NoL)
                                  : visibilitySmithSchlick(alpha, NoV, NoL);
    return distributionGgx(alpha * alpha, NoH) * visibility * inc.specularIlluminance.x;
}

float representativePointSpecular(Light light, vec3 V, float roughness) {
    return representativePointSpecular(light, V, roughness, false);
}

// --area-lights ltc: the unit-magnitude LTC's integral over the sphere or tube, times the
// light's luminance (sphere, I / (pi r^2)) or intensity (tube); the caller multiplies by the
// table's magnitude. minvEntries: the table's M^-1 (00, 02, 20, 22) for this roughness and view,
// magnitude its lobe magnitude. A tube by its capsule (ltcTubeIntegral times
// ltcTubeLobeCorrection, the renderer's), or with `segmentOnly` by the bare segment's isotropic
// line integral (the renderer's before the capsule).
float ltcSpecular(Light light, vec3 V, vec4 minvEntries, bool segmentOnly, float magnitude,
                  float roughness) {
    mat3 frame = ltcShadingFrame(kSurfaceNormal, V);
    mat3 minv = ltcInverseMatrix(minvEntries);
    vec3 center = frame * light.position;
    if (light.sourceLength > 0.0) {
        vec3 halfSegment = frame * light.tubeAxis * (0.5 * light.sourceLength);
        if (segmentOnly) {
            return light.intensity.x * ltcLineIntegral(minv, center - halfSegment, center + halfSegment);
        }
        vec3 p0 = center - halfSegment, p1 = center + halfSegment;
        return light.intensity.x * ltcTubeIntegral(minv, p0, p1, light.sourceRadius) *
               ltcTubeLobeCorrection(minv, magnitude, alphaFromRoughness(roughness), frame * V, p0, p1);
    }
    float luminance = light.intensity.x / (PI * light.sourceRadius * light.sourceRadius);
    return luminance * ltcSphereIntegral(minv, center, light.sourceRadius);
}

// Uniform sampling of the cone the sphere subtends (pdf 1 / (2 pi (1 - cos sigma))) times its
// luminance I / (pi r^2). `offset` decorrelates evaluations.
float sphereSpecularMonteCarlo(Light light, vec3 V, float roughness, uint sampleCount, uint offset) {
    float alpha = alphaFromRoughness(roughness);
    float distance = length(light.position);
    vec3 c = light.position / distance;
    float sinSigma = min(light.sourceRadius / distance, 1.0);
    float cosSigma = sqrt(max(1.0 - sinSigma * sinSigma, 0.0));
    mat3 frame = tangentFrame(c);
    float luminance = light.intensity.x / (PI * light.sourceRadius * light.sourceRadius);
    float solidAngle = 2.0 * PI * (1.0 - cosSigma);
    vec2 shift = fract(vec2(float(offset) * 0.7548777, float(offset) * 0.5698403));
    float sum = 0.0;
    for (uint i = 0u; i < sampleCount; ++i) {
        vec2 xi = hammersley(i, sampleCount, shift);
        float cosPsi = 1.0 - xi.x * (1.0 - cosSigma);
        float sinPsi = sqrt(max(1.0 - cosPsi * cosPsi, 0.0));
        float phi = 2.0 * PI * xi.y;
        vec3 L = frame * vec3(sinPsi * cos(phi), sinPsi * sin(phi), cosPsi);
        sum += specularTimesNoL(V, L, alpha);
    }
    return luminance * solidAngle * sum / float(sampleCount);
}

// The tube's intensity spread evenly along its segment (as lineIrradiance assumes): the mean
// over stratified points of a point light's specular.
float tubeSpecularMonteCarlo(Light light, vec3 V, float roughness, uint sampleCount, uint offset) {
    float alpha = alphaFromRoughness(roughness);
    vec3 L0 = light.position - light.tubeAxis * (0.5 * light.sourceLength);
    vec3 Ld = light.tubeAxis * light.sourceLength;
    float shift = fract(float(offset) * 0.6180340);
    float sum = 0.0;
    for (uint i = 0u; i < sampleCount; ++i) {
        vec3 P = L0 + Ld * ((float(i) + shift) / float(sampleCount));
        float distanceSq = dot(P, P);
        sum += specularTimesNoL(V, P * inversesqrt(distanceSq), alpha) * inverseSquare(distanceSq);
    }
    return light.intensity.x * sum / float(sampleCount);
}

#endif
