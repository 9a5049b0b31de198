#version 460
// Cost of one shared-GLSL function: every invocation evaluates it `iterations` times on
// inputs that change with the loop index (so nothing is hoisted) and keeps a sum (so nothing
// is dropped). The host times whole dispatches; function 0 (input generation only) is the
// loop overhead it subtracts. Loops stay far under llvmpipe's 65,535 iterations per invocation.
#extension GL_GOOGLE_include_directive : require

#include "report_light_texture.glsl"
#include "common/ibl.glsl"
#include "common/lights.glsl"
#include "area_light_integration.glsl"

layout(local_size_x = 64) in;

// Must match CostFunction in shader_cost.h.
const uint kBaseline = 0u;
const uint kFresnelSg = 1u;
const uint kFresnelPow5 = 2u;
const uint kVisSchlick = 3u;
const uint kVisSmithGgx = 4u;
const uint kEnvBrdfApprox = 5u;
const uint kEnvBrdfLut = 6u;
const uint kEnvBrdfMonteCarlo = 7u;
const uint kInverseSquare = 8u;
const uint kWindowedFalloff = 9u;
const uint kSphereRepresentative = 10u;
const uint kSphereMonteCarlo = 11u;
const uint kTubeRepresentative = 12u;
const uint kTubeMonteCarlo = 13u;
const uint kVisSmithGgxFast = 14u;
const uint kMultipleScattering = 15u;
const uint kPointLight = 16u;
const uint kSphereLtc = 17u;
const uint kTubeLtc = 18u;
const uint kTubeCapsuleLtc = 19u;
const uint kPointLightShading = 20u;
const uint kRectRepresentative = 21u;
const uint kRectLtc = 22u;
const uint kDiskRepresentative = 23u;
const uint kDiskLtc = 24u;
const uint kTexturedRectRepresentative = 25u;
const uint kTexturedRectLtc = 26u;
const uint kRectRepresentativeConstantIntensity = 27u;
const uint kRectLtcConstantIntensity = 28u;
const uint kDiskRepresentativeConstantIntensity = 29u;
const uint kDiskLtcConstantIntensity = 30u;
const uint kTubeSegmentLtc = 31u;
const uint kTubeCapsuleLtcShading = 32u;
const uint kTubeRepresentativeShading = 33u;

layout(std430, binding = 0) writeonly buffer Sums {
    float sums[];
};
// The environment BRDF LUT unpacked to (scale, bias), row = roughness, column = NoV.
layout(std430, binding = 1) readonly buffer Lut {
    vec2 lut[];
};

layout(push_constant) uniform Job {
    uint function;
    uint iterations;
    uint samples;     // Monte Carlo samples per evaluation
    uint lutSize;
};

// Bilinear fetch with clamp-to-edge at texel centres, as a linear sampler reads the LUT.
vec2 lutBilinear(float roughness, float NoV) {
    vec2 p = clamp(vec2(NoV, roughness) * float(lutSize) - 0.5, vec2(0.0), vec2(float(lutSize) - 1.0));
    uvec2 i0 = uvec2(p);
    uvec2 i1 = min(i0 + 1u, uvec2(lutSize - 1u));
    vec2 f = p - vec2(i0);
    vec2 top = mix(lut[i0.y * lutSize + i0.x], lut[i0.y * lutSize + i1.x], f.x);
    vec2 bottom = mix(lut[i1.y * lutSize + i0.x], lut[i1.y * lutSize + i1.x], f.x);
    return mix(top, bottom, f.y);
}

Light areaLight(float sourceRadius, float sourceLength) {
    Light light;
    light.position = vec3(0.5, 0.0, 0.866);
    light.invAttenuationRadius = 0.0;
    light.intensity = vec3(1.0);
    light.sourceRadius = sourceRadius;
    light.direction = vec3(0.0, 0.0, -1.0);
    light.sourceLength = sourceLength;
    light.tubeAxis = vec3(0.0, 1.0, 0.0);
    light.type = kLightPoint;
    light.spotScale = 0.0;
    light.spotOffset = 0.0;
    return light;
}

// Rect and disk lights: diffuse and specular (GGX along the representative direction, or the
// LTC integral with an M^-1 made from the inputs: the two table fetches are not timed), F0 = 1.
// The point light: evaluateLocalLight plus GGX along its direction, the baseline they compare to.
float localLightShading(Light light, vec3 V, float roughness) {
    float alpha = alphaFromRoughness(roughness);
    vec3 N = vec3(0.0, 0.0, 1.0);
    LightIncidence inc = evaluateLocalLight(light, vec3(0.0), N, reflect(-V, N), alpha);
    vec3 H = safeNormalize(V + inc.specularL);
    return inc.diffuseIlluminance.x + distributionGgx(alpha * alpha, saturate(H.z)) *
           visibilitySmithGgxCorrelated(alpha, saturate(V.z), saturate(inc.specularL.z)) *
           inc.specularIlluminance.x;
}

float pointLightShading(vec3 V, float roughness) {
    return localLightShading(areaLight(0.0, 0.0), V, roughness);
}

// A tube by LTC, diffuse + specular (F0 = 1, magnitude 1): the capsule's two integrals.
float tubeLtcShading(Light light, vec3 V, vec4 minvEntries, float magnitude, float roughness) {
    vec3 N = vec3(0.0, 0.0, 1.0);
    mat3 frame = ltcShadingFrame(N, V);
    mat3 minv = ltcInverseMatrix(minvEntries);
    vec3 center = frame * light.position;
    vec3 halfSegment = frame * light.tubeAxis * (0.5 * light.sourceLength);
    vec3 p0 = center - halfSegment, p1 = center + halfSegment;
    vec2 integrals = ltcTubeIntegrals(minv, p0, p1, light.sourceRadius);
    float correction =
        ltcTubeLobeCorrection(minv, magnitude, alphaFromRoughness(roughness), frame * V, p0, p1);
    return light.intensity.x * (integrals.x * correction + PI * integrals.y);
}

AreaShape costShape(bool disk, float size) {
    AreaShape s;
    s.center = vec3(0.5, 0.0, 0.866);
    s.normal = -s.center;
    s.axisX = vec3(0.866, 0.0, -0.5);
    s.axisY = cross(s.axisX, s.normal);
    s.isDisk = disk;
    s.halfSize = vec2(0.5 * size);
    return s;
}

// `slot` 1: a textured rect (report_light_texture.glsl's image, read once per lobe).
float areaShading(bool disk, bool ltc, vec3 V, float roughness, float size, uint slot) {
    AreaShape s = costShape(disk, size);
    vec3 N = vec3(0.0, 0.0, 1.0);
    float alpha = alphaFromRoughness(roughness);
    if (ltc) {
        mat3 minv = ltcInverseMatrix(vec4(1.0, 0.1 * roughness, -0.1 * roughness, 0.5 + roughness));
        if (slot == 0u) {
            return areaExactDiffuse(s, vec3(0.0), N) + areaLtcSpecularIntegral(s, vec3(0.0), N, V, minv);
        }
        vec3 diffuseTexel, specularTexel;
        float diffuse = PI * areaShapeIntegral(s, vec3(0.0), transpose(tangentFrame(N)), mat3(1.0),
                                               slot, false, diffuseTexel);
        float specular = areaShapeIntegral(s, vec3(0.0), ltcShadingFrame(N, V), minv, slot,
                                           true, specularTexel);
        return diffuse * diffuseTexel.x + specular * specularTexel.x;
    }
    vec3 L;
    float diffuse = areaRepresentativeDiffuse(s, vec3(0.0), N, false, L);
    diffuse *= areaRepresentativeDiffuseTexture(s, slot, vec3(0.0), L).x;
    float e = areaRepresentativeSpecular(s, vec3(0.0), N, reflect(-V, N), alpha, L);
    e *= areaRepresentativeSpecularTexture(s, slot, vec3(0.0), L, alpha).x;
    vec3 H = safeNormalize(V + L);
    return diffuse + distributionGgx(alpha * alpha, saturate(H.z)) *
           visibilitySmithGgxCorrelated(alpha, saturate(V.z), saturate(L.z)) * e;
}

// A constant-intensity rect or disk (Drobot's (2014, GPU Pro 5, "Physically Based Area Lights")
// variant): the same shading with the pre-integrated diffuse and specular factors
// (area_light_constant_intensity.glsl).
float areaShadingConstantIntensity(bool disk, bool ltc, vec3 V, float roughness, float size) {
    AreaShape s = costShape(disk, size);
    vec3 N = vec3(0.0, 0.0, 1.0);
    vec3 R = reflect(-V, N);
    float alpha = alphaFromRoughness(roughness);
    float diffuseFactor = constantIntensityDiffuseFactor(s, vec3(0.0));
    float specularFactor = constantIntensitySpecularFactor(s, vec3(0.0), R, alpha);
    if (ltc) {
        mat3 minv = ltcInverseMatrix(vec4(1.0, 0.1 * roughness, -0.1 * roughness, 0.5 + roughness));
        return areaExactDiffuse(s, vec3(0.0), N) * diffuseFactor +
               areaLtcSpecularIntegral(s, vec3(0.0), N, V, minv) * specularFactor;
    }
    vec3 L;
    float diffuse = areaRepresentativeDiffuse(s, vec3(0.0), N, false, L);
    float e = areaRepresentativeSpecular(s, vec3(0.0), N, R, alpha, L);
    vec3 H = safeNormalize(V + L);
    return diffuse * diffuseFactor + distributionGgx(alpha * alpha, saturate(H.z)) *
           visibilitySmithGgxCorrelated(alpha, saturate(V.z), saturate(L.z)) * e * specularFactor;
}

// Each function gets its own loop (the switch is outside it, so no case pays for the others'
// branches): `iterations` evaluations on inputs x, y, z in [1e-3, 0.999] that change every
// iteration (golden-ratio steps per invocation), summed so nothing is dropped.
#define TIMED_LOOP(EXPRESSION)                                      \
    for (uint i = 0u; i < iterations; ++i) {                        \
        u = fract(u + vec3(0.6180340, 0.7548777, 0.5698403));       \
        vec3 v = clamp(u, vec3(1e-3), vec3(0.999));                 \
        float x = v.x, y = v.y, z = v.z;                            \
        sum += (EXPRESSION);                                        \
    }

// A view over the surface (N = +Z) and the light's size, from the loop's inputs.
#define AREA_VIEW normalize(vec3(-0.5 + 0.2 * x, 0.2 * y, 0.866))
#define SPHERE_LIGHT areaLight(0.1 + 0.2 * z, 0.0)
#define TUBE_LIGHT areaLight(0.0, 0.5 + z)
#define THICK_TUBE_LIGHT areaLight(0.1, 0.5 + z)
// An M^-1 of the table's shape that changes with the inputs (the table fetch itself, two
// texture reads in a renderer, is not timed), and the same point light shaded the same way.
#define LTC_MINV vec4(0.5 + 0.5 * y, 0.1 * x, -0.1 * x, 0.3 + 0.7 * y)
// Its magnitude and roughness (a tube's lobe correction runs from roughness 0.2 up).
#define LTC_MAGNITUDE (0.3 + 0.6 * y)
#define LTC_ROUGHNESS (0.1 + 0.9 * y)
#define POINT_LIGHT areaLight(0.0, 0.0)

void main() {
    uint id = gl_GlobalInvocationID.x;
    vec3 u = fract(vec3(0.1234, 0.5678, 0.9012) + float(id) * vec3(0.0001357, 0.0002468, 0.0003579));
    float sum = 0.0;
    switch (function) {
        case kBaseline: TIMED_LOOP(x + y + z); break;
        case kFresnelSg: TIMED_LOOP(fresnelSchlickSg(vec3(y), x).x); break;
        case kFresnelPow5: TIMED_LOOP(fresnelSchlickPow5(vec3(y), x).x); break;
        case kVisSchlick: TIMED_LOOP(visibilitySmithSchlick(y * y + 4e-4, x, z)); break;
        case kVisSmithGgx: TIMED_LOOP(visibilitySmithGgxCorrelated(y * y + 4e-4, x, z)); break;
        case kEnvBrdfApprox: TIMED_LOOP(envBrdfApprox(vec3(z), y, x).x); break;
        case kEnvBrdfLut: TIMED_LOOP(dot(lutBilinear(y, x), vec2(z, 1.0))); break;
        case kEnvBrdfMonteCarlo:
            TIMED_LOOP(dot(integrateEnvironmentBrdf(y, x, samples), vec2(z, 1.0)));
            break;
        case kInverseSquare: TIMED_LOOP(inverseSquare(x * 100.0)); break;
        case kWindowedFalloff:
            TIMED_LOOP(attenuationWindow(x * 100.0, 0.1) * inverseSquare(x * 100.0));
            break;
        case kSphereRepresentative:
            TIMED_LOOP(representativePointSpecular(SPHERE_LIGHT, AREA_VIEW, 0.1 + 0.9 * y));
            break;
        case kSphereMonteCarlo:
            TIMED_LOOP(sphereSpecularMonteCarlo(SPHERE_LIGHT, AREA_VIEW, 0.1 + 0.9 * y, samples, i));
            break;
        case kTubeRepresentative:
            TIMED_LOOP(representativePointSpecular(TUBE_LIGHT, AREA_VIEW, 0.1 + 0.9 * y));
            break;
        case kTubeMonteCarlo:
            TIMED_LOOP(tubeSpecularMonteCarlo(TUBE_LIGHT, AREA_VIEW, 0.1 + 0.9 * y, samples, i));
            break;
        case kVisSmithGgxFast:
            TIMED_LOOP(visibilitySmithGgxCorrelatedFast(y * y + 4e-4, x, z));
            break;
        case kMultipleScattering:
            TIMED_LOOP(multipleScatteringCompensation(vec3(z), 0.3 + 0.7 * y).x);
            break;
        case kPointLight:
            TIMED_LOOP(representativePointSpecular(POINT_LIGHT, AREA_VIEW, 0.1 + 0.9 * y, true));
            break;
        case kSphereLtc: TIMED_LOOP(ltcSpecular(SPHERE_LIGHT, AREA_VIEW, LTC_MINV, false, LTC_MAGNITUDE, LTC_ROUGHNESS)); break;
        case kTubeLtc: TIMED_LOOP(ltcSpecular(TUBE_LIGHT, AREA_VIEW, LTC_MINV, false, LTC_MAGNITUDE, LTC_ROUGHNESS)); break;
        case kTubeCapsuleLtc:
            TIMED_LOOP(ltcSpecular(THICK_TUBE_LIGHT, AREA_VIEW, LTC_MINV, false, LTC_MAGNITUDE, LTC_ROUGHNESS));
            break;
        case kTubeSegmentLtc: TIMED_LOOP(ltcSpecular(TUBE_LIGHT, AREA_VIEW, LTC_MINV, true, LTC_MAGNITUDE, LTC_ROUGHNESS)); break;
        case kPointLightShading: TIMED_LOOP(pointLightShading(AREA_VIEW, 0.1 + 0.9 * y)); break;
        case kTubeCapsuleLtcShading: TIMED_LOOP(tubeLtcShading(THICK_TUBE_LIGHT, AREA_VIEW, LTC_MINV, LTC_MAGNITUDE, LTC_ROUGHNESS)); break;
        case kTubeRepresentativeShading:
            TIMED_LOOP(localLightShading(THICK_TUBE_LIGHT, AREA_VIEW, 0.1 + 0.9 * y));
            break;
        case kRectRepresentative:
            TIMED_LOOP(areaShading(false, false, AREA_VIEW, 0.1 + 0.9 * y, 0.1 + z, 0u));
            break;
        case kRectLtc: TIMED_LOOP(areaShading(false, true, AREA_VIEW, 0.1 + 0.9 * y, 0.1 + z, 0u)); break;
        case kDiskRepresentative:
            TIMED_LOOP(areaShading(true, false, AREA_VIEW, 0.1 + 0.9 * y, 0.1 + z, 0u));
            break;
        case kDiskLtc: TIMED_LOOP(areaShading(true, true, AREA_VIEW, 0.1 + 0.9 * y, 0.1 + z, 0u)); break;
        case kTexturedRectRepresentative:
            TIMED_LOOP(areaShading(false, false, AREA_VIEW, 0.1 + 0.9 * y, 0.1 + z, 1u));
            break;
        case kTexturedRectLtc:
            TIMED_LOOP(areaShading(false, true, AREA_VIEW, 0.1 + 0.9 * y, 0.1 + z, 1u));
            break;
        case kRectRepresentativeConstantIntensity:
            TIMED_LOOP(areaShadingConstantIntensity(false, false, AREA_VIEW, 0.1 + 0.9 * y, 0.1 + z));
            break;
        case kRectLtcConstantIntensity:
            TIMED_LOOP(areaShadingConstantIntensity(false, true, AREA_VIEW, 0.1 + 0.9 * y, 0.1 + z));
            break;
        case kDiskRepresentativeConstantIntensity:
            TIMED_LOOP(areaShadingConstantIntensity(true, false, AREA_VIEW, 0.1 + 0.9 * y, 0.1 + z));
            break;
        case kDiskLtcConstantIntensity:
            TIMED_LOOP(areaShadingConstantIntensity(true, true, AREA_VIEW, 0.1 + 0.9 * y, 0.1 + z));
            break;
        default: break;
    }
    sums[id] = sum;
}
