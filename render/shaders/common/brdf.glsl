// BRDF terms of Karis 2013, "Real Shading in Unreal Engine 4", "Shading Model" (UE4 shading model).
// Shared by the lighting pass, IBL and the stability tests: change a formula here and every user
// and test sees it.
#ifndef CANDELA_BRDF_GLSL
#define CANDELA_BRDF_GLSL

#include "common/math.glsl"
#include "common/specialization_ids.h"

// The BRDF a variant shades with (`--brdf`, RendererOptions::brdf). false: Karis 2013 exactly
// (Schlick-Smith visibility, single scattering). true: height-correlated Smith visibility and
// multiple-scattering energy compensation (render/README.md "BRDF").
layout(constant_id = SPEC_ENERGY_CONSERVING) const bool kEnergyConserving = true;

// Roughness is clamped to this before alpha = roughness^2, only for analytic lights: at 0 the
// GGX lobe of a point light is a Dirac delta (D = inf at NoH = 1). 0.02 keeps
// D <= 1 / (pi * alpha^2) ~ 2e6, finite in fp32 (not in fp16: see docs/speed-vs-error.md).
const float kMinRoughness = 0.02;

float alphaFromRoughness(float roughness) {
    float r = clamp(roughness, kMinRoughness, 1.0);
    return r * r;
}

// eq. 1
vec3 diffuseLambert(vec3 diffuseColor) {
    return diffuseColor * (1.0 / PI);
}

// eq. 3: GGX / Trowbridge-Reitz. a2 = alpha^2 > 0, so d >= a2 > 0 and D stays finite.
float distributionGgx(float a2, float NoH) {
    float d = (NoH * a2 - NoH) * NoH + 1.0;
    return a2 / (PI * d * d);
}

// eq. 4 folded with the 1 / (4 NoL NoV) of eq. 2: Schlick-Smith with k = alpha / 2.
// Both factors are >= k > 0, so the result is finite for NoV = NoL = 0.
float visibilitySmithSchlick(float alpha, float NoV, float NoL) {
    float k = alpha * 0.5;
    float gv = NoV * (1.0 - k) + k;
    float gl = NoL * (1.0 - k) + k;
    return 0.25 / (gv * gl);
}

// Anisotropic GGX (Karis 2013, "Specular D", Burley 2012's D_GGXaniso): alphaT along the tangent
// T, alphaB along the bitangent B; ToH, BoH, NoH are H in the frame (T, B, N). Karis 2013's
//   D = 1 / (pi aT aB d^2),  d = ToH^2 / aT^2 + BoH^2 / aB^2 + NoH^2
// is multiplied through by aT aB here: D = aT aB / (pi s^2), s = ToH^2 aB/aT + BoH^2 aT/aB +
// aT aB NoH^2. For aT == aB both ratios are exactly 1, so s = ToH^2 + BoH^2 + a2 NoH^2: the
// isotropic D in its tangent-space form (distributionGgxTangent), to the last bit, and no
// 1 - NoH^2 cancellation for narrow lobes. alphaT, alphaB > 0.
float distributionGgxAnisotropic(float alphaT, float alphaB, float ToH, float BoH, float NoH) {
    float s = ToH * ToH * (alphaB / alphaT) + BoH * BoH * (alphaT / alphaB) +
              alphaT * alphaB * NoH * NoH;
    return alphaT * alphaB / (PI * s * s);
}

// Eq. 3 from H's components in the frame (T, B, N): 1 - NoH^2 = ToH^2 + BoH^2 exactly.
float distributionGgxTangent(float a2, float ToH, float BoH, float NoH) {
    float s = ToH * ToH + BoH * BoH + a2 * NoH * NoH;
    return a2 / (PI * s * s);
}

// Height-correlated Smith visibility for the anisotropic GGX (Heitz 2014, eq. 99 folded with
// 1 / (4 NoL NoV)): Lambda of a direction w is (sqrt(1 + (aT^2 w.t^2 + aB^2 w.b^2) / w.n^2) - 1)
// / 2. For aT == aB = a, aT^2 ToV^2 + aB^2 BoV^2 = a^2 (1 - NoV^2): visibilitySmithGgxCorrelated.
float visibilitySmithGgxCorrelatedAnisotropic(float alphaT, float alphaB, float ToV, float BoV,
                                              float NoV, float ToL, float BoL, float NoL) {
    float lambdaV = NoL * length(vec3(alphaT * ToV, alphaB * BoV, NoV));
    float lambdaL = NoV * length(vec3(alphaT * ToL, alphaB * BoL, NoL));
    return 0.5 / max(lambdaV + lambdaL, 1e-12);
}

// KHR_materials_anisotropy's roughness pair: alpha along the anisotropy direction grows with
// the strength, alpha across it stays the material's: (mix(alpha, 1, strength^2), alpha).
vec2 anisotropicAlphas(float roughness, float strength) {
    float alpha = alphaFromRoughness(roughness);
    return vec2(mix(alpha, 1.0, strength * strength), alpha);
}

// Exact height-correlated Smith GGX visibility, the reference eq. 4 approximates.
float visibilitySmithGgxCorrelated(float alpha, float NoV, float NoL) {
    float a2 = alpha * alpha;
    float lambdaV = NoL * sqrt(NoV * NoV * (1.0 - a2) + a2);
    float lambdaL = NoV * sqrt(NoL * NoL * (1.0 - a2) + a2);
    return 0.5 / max(lambdaV + lambdaL, 1e-12);
}

// The visibility term of the variant's BRDF: exact height-correlated Smith when energy-
// conserving (docs/speed-vs-error.md compares the candidates), else eq. 4.
float visibilitySmith(float alpha, float NoV, float NoL) {
    if (kEnergyConserving) return visibilitySmithGgxCorrelated(alpha, NoV, NoL);
    return visibilitySmithSchlick(alpha, NoV, NoL);
}

// Hammon 2017's linear form of the height-correlated term (Filament's "fast" visibility): the
// sqrt of each Lambda replaced by its linear interpolation in alpha. Measured only.
float visibilitySmithGgxCorrelatedFast(float alpha, float NoV, float NoL) {
    float lambdaV = NoL * (NoV * (1.0 - alpha) + alpha);
    float lambdaL = NoV * (NoL * (1.0 - alpha) + alpha);
    return 0.5 / max(lambdaV + lambdaL, 1e-12);
}

// Multiple-scattering energy compensation of a single-scattering specular lobe (Kulla and
// Conty 2017; the form of Fdez-Aguera 2019 and Filament): a white lobe whose directional albedo
// is E_ss loses 1 - E_ss to the bounces single scattering ignores; scaling it by 1 / E_ss puts
// that energy back, and for a coloured F0 the scale 1 + F0 (1 / E_ss - 1) grows with F0, so
// every bounce is tinted again and coloured metals keep (and deepen) their hue.
// directionalAlbedo: E_ss at the surface's NoV and roughness, F0 = 1 (the LUT's scale + bias).
vec3 multipleScatteringCompensation(vec3 specularColor, float directionalAlbedo) {
    return 1.0 + specularColor * (1.0 / max(directionalAlbedo, 1e-3) - 1.0);
}

// eq. 5: Schlick Fresnel with the spherical-Gaussian exponent. A specular colour under 2%
// reflectance is treated as pre-baked shadowing (saturate(50 * F0.g)), as UE4 does.
vec3 fresnelSchlickSg(vec3 specularColor, float VoH) {
    float fc = exp2((-5.55473 * VoH - 6.98316) * VoH);
    return saturate(50.0 * specularColor.g) * fc + (1.0 - fc) * specularColor;
}

// Classic pow5 Schlick, the reference eq. 5 approximates.
vec3 fresnelSchlickPow5(vec3 specularColor, float VoH) {
    float m = 1.0 - VoH;
    float fc = (m * m) * (m * m) * m;
    return saturate(50.0 * specularColor.g) * fc + (1.0 - fc) * specularColor;
}

// Karis 2014's ("Physically Based Shading on Mobile") fit of the environment BRDF's (scale, bias),
// replacing the eq. 8 LUT.
vec2 envBrdfApproxScaleBias(float roughness, float NoV) {
    const vec4 c0 = vec4(-1.0, -0.0275, -0.572, 0.022);
    const vec4 c1 = vec4(1.0, 0.0425, 1.04, -0.04);
    vec4 r = roughness * c0 + c1;
    float a004 = min(r.x * r.x, exp2(-9.28 * NoV)) * r.x + r.y;
    return vec2(-1.04, 1.04) * a004 + r.zw;
}

// Karis 2014: analytic environment BRDF for mobile, replacing the eq. 8 LUT.
vec3 envBrdfApprox(vec3 specularColor, float roughness, float NoV) {
    vec2 ab = envBrdfApproxScaleBias(roughness, NoV);
    // max(): toward roughness 1 and NoV 1 the fit's bias goes negative (Karis 2014:
    // EnvBRDFApprox(F0, 1, 1) = 0.4524 F0 - 0.0024), i.e. a negative reflectance for any F0
    // channel under 0.0053 (Specular 0, dark or saturated metals). Found by
    // tests/render/stability.
    return max(specularColor * ab.x + ab.y, vec3(0.0));
}

// Karis 2014: EnvBRDFApprox(0.04, roughness, NoV) for default non-metals.
float envBrdfApproxNonmetal(float roughness, float NoV) {
    const vec2 c0 = vec2(-1.0, -0.0275);
    const vec2 c1 = vec2(1.0, 0.0425);
    vec2 r = roughness * c0 + c1;
    return min(r.x * r.x, exp2(-9.28 * NoV)) * r.x + r.y;
}

#endif
