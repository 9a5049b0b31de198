#version 460
// Hard-input grid over the shared BRDF terms (Karis 2013, "Real Shading in Unreal Engine 4",
// eq. 1-5, Karis 2014, "Physically Based Shading on Mobile" EnvBRDFApprox) and the full
// shadeSurface chain. One invocation = one (roughness, cos view, cos light) triple, looping over
// every azimuth and material; results are tallied, never stored.
#extension GL_GOOGLE_include_directive : require

#include "common/shading_models.glsl"
#include "stability_checks.glsl"

layout(local_size_x = 64) in;

// Must match BrdfMaterialCase in brdf_stability_tests.cpp.
struct MaterialCase {
    vec4 baseColorMetallic;
    vec4 customData;
    float specular;
    uint shadingModel;
    float intensity;  // directional light, lux
    float pad;
};

layout(std430, binding = 1) readonly buffer Axes {
    float axisValues[];  // roughness values, then cosines, then azimuth (cos, sin) pairs
};
layout(std430, binding = 2) readonly buffer Materials {
    MaterialCase materials[];
};

layout(push_constant) uniform Grid {
    uint roughnessCount;
    uint cosineCount;
    uint azimuthCount;
    uint materialCount;
};

// Record order: must match BrdfCheck in brdf_stability_tests.cpp.
const uint kCheckAlpha = 0u;
const uint kCheckD = 1u;
const uint kCheckVisSchlick = 2u;
const uint kCheckVisCorrelated = 3u;
const uint kCheckFresnelSg = 4u;
const uint kCheckFresnelPow5 = 5u;
const uint kCheckLambert = 6u;
const uint kCheckEnvBrdf = 7u;
const uint kCheckEnvBrdfNonmetal = 8u;
const uint kCheckSpecularGgx = 9u;
const uint kCheckShadeSurface = 10u;
const uint kCheckCount = 11u;

// Karis 2014's EnvBRDFApprox at roughness 0, NoV 0 is 1.0442 - 0.0442 F0 (a004 = 1.0425), and its
// non-metal variant 1.0425: a 4.4% overshoot of the physical bound 1 at grazing angles on
// mirrors, inherent in the fit (reported, not a float problem). Anything above is a bug.
const float kEnvBrdfFitMax = 1.04421;

vec3 directionFromCosine(float cosine, vec2 azimuth) {
    float sine = sqrt(max(1.0 - cosine * cosine, 0.0));
    return vec3(sine * azimuth.x, sine * azimuth.y, cosine);
}

void main() {
    uint triple = gl_GlobalInvocationID.x;
    if (triple >= roughnessCount * cosineCount * cosineCount) return;
    uint r = triple / (cosineCount * cosineCount);
    uint v = (triple / cosineCount) % cosineCount;
    uint l = triple % cosineCount;
    float roughness = axisValues[r];
    float cosView = axisValues[roughnessCount + v];
    float cosLight = axisValues[roughnessCount + l];

    Tally t[kCheckCount];
    for (uint c = 0u; c < kCheckCount; ++c) t[c] = newTally();

    const vec3 N = vec3(0.0, 0.0, 1.0);
    vec3 V = directionFromCosine(cosView, vec2(1.0, 0.0));
    float alpha = alphaFromRoughness(roughness);
    float NoV = saturate(dot(N, V));  // callers saturate, as specularGgx does
    const float kMinAlpha = kMinRoughness * kMinRoughness;

    for (uint a = 0u; a < azimuthCount; ++a) {
        uint azimuthBase = roughnessCount + cosineCount + 2u * a;
        vec2 azimuth = vec2(axisValues[azimuthBase], axisValues[azimuthBase + 1u]);
        vec3 L = directionFromCosine(cosLight, azimuth);  // azimuth (-1, 0): V == -L possible
        vec3 H = safeNormalize(V + L);
        float NoL = saturate(dot(N, L));
        float NoH = saturate(dot(N, H));
        float VoH = saturate(dot(V, H));
        for (uint m = 0u; m < materialCount; ++m) {
            uint caseIndex = (triple * azimuthCount + a) * materialCount + m;
            MaterialCase mat = materials[m];
            Surface s;
            s.baseColor = mat.baseColorMetallic.rgb;
            s.metallic = mat.baseColorMetallic.a;
            s.roughness = roughness;
            s.specular = mat.specular;
            s.shadingModel = mat.shadingModel;
            s.customData = mat.customData;
            // A plausible E_ss (Karis 2014's fit; the lighting pass reads the LUT), so the
            // energy-conserving BRDF's compensation is exercised over the whole grid.
            vec2 albedoTerms = envBrdfApproxScaleBias(roughness, NoV);
            s.directionalAlbedo = albedoTerms.x + albedoTerms.y;
            vec3 specularColor = mix(vec3(0.08 * s.specular), s.baseColor, s.metallic);

            tally(t[kCheckAlpha], alpha, kMinAlpha, 1.0, caseIndex);
            tally(t[kCheckD], distributionGgx(alpha * alpha, NoH), 0.0, kNoUpperBound,
                  caseIndex);
            tally(t[kCheckVisSchlick], visibilitySmithSchlick(alpha, NoV, NoL), 0.0,
                  kNoUpperBound, caseIndex);
            tally(t[kCheckVisCorrelated], visibilitySmithGgxCorrelated(alpha, NoV, NoL), 0.0,
                  kNoUpperBound, caseIndex);
            // A reflectance between F0 and 1: never negative, never above one.
            tally3(t[kCheckFresnelSg], fresnelSchlickSg(specularColor, VoH), 0.0, 1.0, caseIndex);
            tally3(t[kCheckFresnelPow5], fresnelSchlickPow5(specularColor, VoH), 0.0, 1.0,
                   caseIndex);
            tally3(t[kCheckLambert], diffuseLambert(s.baseColor), 0.0, 1.0 / PI, caseIndex);
            // The split-sum environment BRDF is a directional albedo, within [0, 1], except
            // that Karis 2014's fit itself overshoots at roughness 0, NoV 0 (see kEnvBrdfFitMax).
            tally3(t[kCheckEnvBrdf], envBrdfApprox(specularColor, roughness, NoV), 0.0,
                   kEnvBrdfFitMax, caseIndex);
            tally(t[kCheckEnvBrdfNonmetal], envBrdfApproxNonmetal(roughness, NoV), 0.0,
                  kEnvBrdfFitMax, caseIndex);

            Light sun = Light(vec3(0.0), 0.0, vec3(mat.intensity), 0.0, -L, 0.0, vec3(0.0, 0.0, 1.0),
                              kLightDirectional, 0.0, 0.0, vec2(0.0));
            LightIncidence incidence = evaluateDirectionalLight(sun, N);
            tally3(t[kCheckSpecularGgx], specularGgx(specularColor, roughness, N, V, incidence),
                   0.0, kNoUpperBound, caseIndex);
            tally3(t[kCheckShadeSurface], shadeSurface(s, N, V, incidence), 0.0,
                   kNoUpperBound, caseIndex);
        }
    }
    for (uint c = 0u; c < kCheckCount; ++c) flushTally(c, t[c]);
}
