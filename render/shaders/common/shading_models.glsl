// Shading models selected by the G-buffer's shading-model ID (SPEC "Shading"). Each model is one
// function of (surface, view, light incidence); adding a model means one ID, one function and
// one case in shadeSurface().
#ifndef CANDELA_SHADING_MODELS_GLSL
#define CANDELA_SHADING_MODELS_GLSL

#include "common/specialization_ids.h"
#include "common/brdf.glsl"
#include "common/lights.glsl"

// Must match render/include/candela/render/shading_model.h.
const uint kShadingUnlit = 0u;
const uint kShadingDefaultLit = 1u;
const uint kShadingSubsurface = 2u;
const uint kShadingLegacyDiffuseSpecular = 3u;

// Shading models compiled into this shader variant; the renderer turns off those no material
// in the scene uses. DefaultLit is always present (it is also the fallback).
layout(constant_id = SPEC_SUBSURFACE_ENABLED) const bool kSubsurfaceEnabled = true;
layout(constant_id = SPEC_LEGACY_DIFFUSE_SPECULAR_ENABLED) const bool kLegacyDiffuseSpecularEnabled =
    true;
// Material extensions (KHR_materials_anisotropy, KHR_materials_clearcoat): on only in deferred
// variants whose frame has a material using them, so other frames compile them out (and the
// forward pass, which never sets them, shades blended surfaces without them).
layout(constant_id = SPEC_ANISOTROPY_ENABLED) const bool kAnisotropyEnabled = false;
layout(constant_id = SPEC_CLEAR_COAT_ENABLED) const bool kClearCoatEnabled = false;

// Clear coat: a dielectric of IOR 1.5 (KHR_materials_clearcoat), F0 = 0.04.
const float kClearCoatF0 = 0.04;

struct Surface {
    vec3 baseColor;    // DefaultLit/Subsurface: base colour; Legacy: DiffuseColor
    float metallic;
    float roughness;
    float specular;    // UE4 "Specular", 0.5 -> F0 0.04
    uint shadingModel;
    vec4 customData;   // Subsurface: colour + opacity; Legacy: SpecularColor
    // E_ss of the specular lobe at this view (specularDirectionalAlbedo), read by the energy-
    // conserving BRDF's multiple-scattering compensation; 1 leaves the lobe as it is.
    float directionalAlbedo;
    // Read only by variants with kAnisotropyEnabled / kClearCoatEnabled (surfaceWithout-
    // Extensions sets the neutral values).
    float anisotropy;    // KHR strength: alpha along anisotropyT mix(alpha, 1, strength^2)
    vec3 anisotropyT;    // unit, orthogonal to N
    float clearCoat;     // coat factor
    float clearCoatRoughness;
    vec3 clearCoatN;
};

void clearSurfaceExtensions(inout Surface s) {
    s.anisotropy = 0.0;
    s.anisotropyT = vec3(1.0, 0.0, 0.0);
    s.clearCoat = 0.0;
    s.clearCoatRoughness = 0.0;
    s.clearCoatN = vec3(0.0, 0.0, 1.0);
}

// The anisotropic GGX lobe (brdf.glsl distributionGgxAnisotropic with its height-correlated
// visibility) for the representative direction of the incidence, in the frame (T, B, N).
vec3 specularGgxAnisotropic(vec3 specularColor, Surface s, vec3 N, vec3 V, LightIncidence inc) {
    vec2 alpha = anisotropicAlphas(s.roughness, s.anisotropy);
    vec3 L = inc.specularL;
    vec3 H = safeNormalize(V + L);
    vec3 T = s.anisotropyT;
    vec3 B = cross(N, T);
    float NoV = saturate(dot(N, V));
    float NoL = saturate(dot(N, L));
    float d = distributionGgxAnisotropic(alpha.x, alpha.y, dot(T, H), dot(B, H),
                                         saturate(dot(N, H)));
    float vis = visibilitySmithGgxCorrelatedAnisotropic(alpha.x, alpha.y, dot(T, V), dot(B, V),
                                                        NoV, dot(T, L), dot(B, L), NoL);
    return d * vis * fresnelSchlickSg(specularColor, saturate(dot(V, H))) *
           inc.specularIlluminance;
}

// An incidence whose specular is already integrated over the light by LTC (area lights):
// Fresnel as the fit splits it, F0 (n - f) + F90 f, with F90 as fresnelSchlickSg's.
vec3 specularLtcIntegrated(vec3 specularColor, LightIncidence inc) {
    float n = inc.specularLtc.x, f = inc.specularLtc.y;
    return (specularColor * (n - f) + saturate(50.0 * specularColor.g) * f) *
           inc.specularIlluminance;
}

// Cook-Torrance specular (eq. 2) for the representative direction of the incidence: single
// scattering, with the variant's visibility term (visibilitySmith).
vec3 specularGgx(vec3 specularColor, float roughness, vec3 N, vec3 V, LightIncidence inc) {
    float alpha = alphaFromRoughness(roughness);
    vec3 H = safeNormalize(V + inc.specularL);
    float NoV = saturate(dot(N, V));
    float NoL = saturate(dot(N, inc.specularL));
    float NoH = saturate(dot(N, H));
    float VoH = saturate(dot(V, H));
    float d = distributionGgx(alpha * alpha, NoH);
    float vis = visibilitySmith(alpha, NoV, NoL);
    return d * vis * fresnelSchlickSg(specularColor, VoH) * inc.specularIlluminance;
}

// specularGgx plus, for the energy-conserving BRDF, the energy of the further bounces
// (multipleScatteringCompensation): every light shape goes through here.
vec3 specularLobe(Surface s, vec3 specularColor, vec3 N, vec3 V, LightIncidence inc) {
    vec3 specular = inc.specularLtc.x > 0.0 ? specularLtcIntegrated(specularColor, inc)
                    : kAnisotropyEnabled && s.anisotropy > 0.0
                        ? specularGgxAnisotropic(specularColor, s, N, V, inc)
                        : specularGgx(specularColor, s.roughness, N, V, inc);
    if (kEnergyConserving) {
        specular *= multipleScatteringCompensation(specularColor, s.directionalAlbedo);
    }
    return specular;
}

vec3 shadeDefaultLit(Surface s, vec3 N, vec3 V, LightIncidence inc) {
    vec3 diffuseColor = s.baseColor * (1.0 - s.metallic);
    vec3 specularColor = mix(vec3(0.08 * s.specular), s.baseColor, s.metallic);
    return diffuseLambert(diffuseColor) * inc.diffuseIlluminance +
           specularLobe(s, specularColor, N, V, inc);
}

// Thin translucent matter: DefaultLit on the lit side plus light that passes through.
// Transmission = wrapped back-face cosine (wrap grows as opacity falls) plus a forward-scatter
// lobe toward the viewer when the light is behind the surface; both tinted by the subsurface
// colour and scaled by (1 - opacity), so an opaque surface reduces to DefaultLit.
vec3 shadeSubsurface(Surface s, vec3 N, vec3 V, LightIncidence inc) {
    vec3 subsurfaceColor = s.customData.rgb;
    float opacity = s.customData.a;
    float wrap = 1.0 - opacity;
    float backCos = saturate((dot(-N, inc.diffuseL) + wrap) / (1.0 + wrap));
    float forwardScatter = pow(saturate(dot(V, -inc.diffuseL)), 12.0) * mix(3.0, 0.1, opacity);
    vec3 transmitted = subsurfaceColor * (1.0 / PI) * (backCos + forwardScatter) * (1.0 - opacity) *
                       inc.incidentIlluminance;
    return shadeDefaultLit(s, N, V, inc) + transmitted;
}

// Non-photoreal projects: artist DiffuseColor and SpecularColor used as they are, no metallic.
// At roughness 1 the "fully rough" fold of Karis 2014, "Physically Based Shading on Mobile" moves
// the specular into the diffuse (EnvBRDFApprox(SpecularColor, 1, 1) ~ 0.45 * SpecularColor) and
// skips the GGX lobe.
vec3 shadeLegacyDiffuseSpecular(Surface s, vec3 N, vec3 V, LightIncidence inc) {
    vec3 diffuseColor = s.baseColor;
    vec3 specularColor = s.customData.rgb;
    if (s.roughness >= 1.0) {
        return diffuseLambert(diffuseColor + specularColor * 0.45) * inc.diffuseIlluminance;
    }
    return diffuseLambert(diffuseColor) * inc.diffuseIlluminance +
           specularLobe(s, specularColor, N, V, inc);
}

// What a shading model reflects of an environment: the same colours its direct lighting uses,
// so ambient and direct light agree. The IBL mode (split sum, mobile, reference) decides how
// the environment is integrated against them.
struct AmbientTerms {
    vec3 diffuseColor;      // times irradiance / pi
    vec3 specularColor;     // F0 for the environment BRDF
    vec3 transmittedColor;  // times the irradiance from behind / pi (Subsurface)
};

AmbientTerms ambientTermsOf(Surface s) {
    AmbientTerms t;
    t.diffuseColor = s.baseColor * (1.0 - s.metallic);
    t.specularColor = mix(vec3(0.08 * s.specular), s.baseColor, s.metallic);
    t.transmittedColor = vec3(0.0);
    if (kSubsurfaceEnabled && s.shadingModel == kShadingSubsurface) {
        t.transmittedColor = s.customData.rgb * (1.0 - s.customData.a);
    } else if (kLegacyDiffuseSpecularEnabled && s.shadingModel == kShadingLegacyDiffuseSpecular) {
        t.diffuseColor = s.baseColor;
        t.specularColor = s.customData.rgb;
        if (s.roughness >= 1.0) {  // the fully-rough fold, as shadeLegacyDiffuseSpecular
            t.diffuseColor += t.specularColor * 0.45;
            t.specularColor = vec3(0.0);
        }
    }
    return t;
}

// The clear coat's own lobe, for an incidence evaluated at its normal (s.clearCoatN) and
// roughness: the coat factor times a dielectric GGX lobe with the variant's visibility. What
// it reflects it takes from the layers below: they are scaled by clearCoatAttenuation.
vec3 clearCoatLobe(Surface s, vec3 V, LightIncidence coatIncidence) {
    vec3 coat = coatIncidence.specularLtc.x > 0.0
                    ? specularLtcIntegrated(vec3(kClearCoatF0), coatIncidence)
                    : specularGgx(vec3(kClearCoatF0), s.clearCoatRoughness, s.clearCoatN, V,
                                  coatIncidence);
    return s.clearCoat * coat;
}

// What reaches the base through the coat and back: 1 - factor x the coat's directional albedo
// E_c(NoV) (the split sum's F0 A + B at the coat's roughness, `coatScaleBias` = (A, B)), so
// base + coat never reflect more than the base alone could (a white furnace gives at most
// (1 - c E_c) + c E_c = 1; tests/render/ibl_tests.cpp ClearCoatFurnace).
float clearCoatAttenuation(Surface s, vec2 coatScaleBias) {
    return 1.0 - s.clearCoat * saturate(kClearCoatF0 * coatScaleBias.x + coatScaleBias.y);
}

vec3 shadeSurface(Surface s, vec3 N, vec3 V, LightIncidence inc) {
    if (s.shadingModel == kShadingUnlit) return vec3(0.0);  // emissive only (G-buffer pass)
    if (kSubsurfaceEnabled && s.shadingModel == kShadingSubsurface) {
        return shadeSubsurface(s, N, V, inc);
    }
    if (kLegacyDiffuseSpecularEnabled && s.shadingModel == kShadingLegacyDiffuseSpecular) {
        return shadeLegacyDiffuseSpecular(s, N, V, inc);
    }
    return shadeDefaultLit(s, N, V, inc);
}

#endif
