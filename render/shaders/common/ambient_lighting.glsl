// Ambient light of an environment on a surface by the split sum (eq. 7: prefiltered radiance x
// environment BRDF) or Karis 2014's ("Physically Based Shading on Mobile") mobile fit, plus SH
// diffuse: one function for the deferred lighting pass and the forward (transparent) pass, so both
// surfaces see the same sky.
#ifndef CANDELA_AMBIENT_LIGHTING_GLSL
#define CANDELA_AMBIENT_LIGHTING_GLSL

#include "common/ibl.glsl"
#include "common/shading_models.glsl"

// The environment's diffuse (and transmitted) light for a surface lit from around
// `diffuseNormal` (N, or the bent normal of ambient occlusion).
vec3 environmentDiffuse(AmbientTerms t, vec3 diffuseNormal, vec3 N, vec4 sh[9]) {
    vec3 diffuse = t.diffuseColor * (1.0 / PI) * shIrradiance(sh, diffuseNormal);
    if (any(greaterThan(t.transmittedColor, vec3(0.0)))) {
        diffuse += t.transmittedColor * (1.0 / PI) * shIrradiance(sh, -N);
    }
    return diffuse;
}

// The direction and roughness at which the split sum reads the cube and the LUT: R and the
// surface's roughness, or for an anisotropic surface the bent reflection vector and the lobe's
// mean roughness.
struct AmbientSpecularLobe {
    vec3 R;
    float roughness;
};

AmbientSpecularLobe ambientSpecularLobe(Surface s, vec3 N, vec3 V) {
    AmbientSpecularLobe lobe = AmbientSpecularLobe(reflect(-V, N), s.roughness);
    if (kAnisotropyEnabled && s.anisotropy > 0.0) {
        vec2 alpha = anisotropicAlphas(s.roughness, s.anisotropy);
        lobe.R = anisotropicReflection(N, V, s.anisotropyT, alpha);
        lobe.roughness = anisotropicAmbientRoughness(alpha);
    }
    return lobe;
}

// Split-sum (or mobile) specular reflectance of the environment for the lobe at NoV.
vec3 environmentSpecularBrdf(Surface s, AmbientTerms t, AmbientSpecularLobe lobe, float NoV,
                             sampler2D environmentBrdfLut, bool mobile) {
    if (mobile) {
        // G-buffer Specular is 8-bit: 0.5 arrives as 128 / 255.
        bool defaultNonmetal = s.shadingModel == kShadingDefaultLit && s.metallic == 0.0 &&
                               abs(s.specular - 0.5) < 1.0 / 255.0;
        return environmentBrdfMobile(t.specularColor, lobe.roughness, NoV, defaultNonmetal);
    }
    return environmentBrdfFromLut(environmentBrdfLut, t.specularColor, lobe.roughness, NoV);
}

// Multiple scattering the energy-conserving BRDF adds, per unit of irradiance / pi.
vec3 environmentMultipleScattering(AmbientTerms t, AmbientSpecularLobe lobe, vec3 environmentBrdf,
                                   float NoV, sampler2D environmentBrdfLut, bool mobile) {
    float albedo = mobile ? envBrdfApproxDirectionalAlbedo(lobe.roughness, NoV)
                          : specularDirectionalAlbedo(environmentBrdfLut, lobe.roughness, NoV);
    return multipleScatteringEnvironmentBrdf(environmentBrdf, t.specularColor, albedo);
}

vec3 prefilteredRadiance(AmbientSpecularLobe lobe, samplerCube prefilteredCube,
                         float prefilteredMipCount) {
    return textureLod(prefilteredCube, lobe.R,
                      prefilteredMipOfRoughness(lobe.roughness, prefilteredMipCount))
        .rgb;
}

// The three parts of the environment's ambient light on a surface, before the sky intensity
// and occlusion: diffuse (lit from around `diffuseNormal`: N, or AO's bent normal), the split
// sum's single-scattering specular, and the multiple scattering the energy-conserving BRDF
// adds (zero otherwise). environmentAmbient and occludedEnvironmentAmbient each add them in
// their own (unchanged) order, so sharing this changes no image by an ulp.
struct EnvironmentAmbientParts {
    vec3 diffuse;
    vec3 specular;
    vec3 multipleScattering;
};

EnvironmentAmbientParts environmentAmbientParts(Surface s, vec3 diffuseNormal, vec3 N, vec3 V,
                                                vec4 sh[9], samplerCube prefilteredCube,
                                                float prefilteredMipCount,
                                                sampler2D environmentBrdfLut, bool mobile) {
    EnvironmentAmbientParts parts;
    AmbientTerms t = ambientTermsOf(s);
    parts.diffuse = environmentDiffuse(t, diffuseNormal, N, sh);
    float NoV = saturate(dot(N, V));
    AmbientSpecularLobe lobe = ambientSpecularLobe(s, N, V);
    vec3 prefiltered = prefilteredRadiance(lobe, prefilteredCube, prefilteredMipCount);
    vec3 environmentBrdf = environmentSpecularBrdf(s, t, lobe, NoV, environmentBrdfLut, mobile);
    parts.specular = prefiltered * environmentBrdf;
    parts.multipleScattering = vec3(0.0);
    if (kEnergyConserving) {
        parts.multipleScattering = environmentMultipleScattering(t, lobe, environmentBrdf, NoV,
                                                                 environmentBrdfLut, mobile) *
                                   shIrradiance(sh, N) * (1.0 / PI);
    }
    return parts;
}

// Radiance (before the sky intensity and occlusion) the environment reflects toward V.
// `sh`: irradiance coefficients (irradiance_sh.comp); `prefilteredCube`: roughness per mip.
vec3 environmentAmbient(Surface s, vec3 N, vec3 V, vec4 sh[9], samplerCube prefilteredCube,
                        float prefilteredMipCount, sampler2D environmentBrdfLut, bool mobile) {
    EnvironmentAmbientParts parts = environmentAmbientParts(
        s, N, N, V, sh, prefilteredCube, prefilteredMipCount, environmentBrdfLut, mobile);
    vec3 ambient = parts.diffuse + parts.specular;
    if (kEnergyConserving) ambient += parts.multipleScattering;
    return ambient;
}

// environmentAmbient under ambient occlusion: the diffuse light arrives around the bent normal
// and is scaled by `diffuseVisibility` (multi-bounce corrected), the specular (and its
// multiple scattering, which leaves the same lobe) by `specularVisibility`.
vec3 occludedEnvironmentAmbient(Surface s, vec3 N, vec3 bentNormal, vec3 V, vec4 sh[9],
                                samplerCube prefilteredCube, float prefilteredMipCount,
                                sampler2D environmentBrdfLut, bool mobile,
                                vec3 diffuseVisibility, float specularVisibility) {
    EnvironmentAmbientParts parts =
        environmentAmbientParts(s, bentNormal, N, V, sh, prefilteredCube, prefilteredMipCount,
                                environmentBrdfLut, mobile);
    vec3 specular = parts.specular;
    if (kEnergyConserving) specular += parts.multipleScattering;
    return parts.diffuse * diffuseVisibility + specular * specularVisibility;
}

// The clear coat's reflection of the environment by the split sum (or Karis 2014's fit on the
// mobile path): factor x prefiltered radiance at the coat's reflection vector and roughness x
// its environment BRDF. The caller scales the layers below by clearCoatAttenuation.
vec3 clearCoatAmbient(Surface s, vec3 V, samplerCube prefilteredCube, float prefilteredMipCount,
                      sampler2D environmentBrdfLut, bool mobile) {
    vec3 N = s.clearCoatN;
    float NoV = saturate(dot(N, V));
    vec3 prefiltered =
        textureLod(prefilteredCube, reflect(-V, N),
                   prefilteredMipOfRoughness(s.clearCoatRoughness, prefilteredMipCount))
            .rgb;
    vec3 coatBrdf =
        mobile ? envBrdfApprox(vec3(kClearCoatF0), s.clearCoatRoughness, NoV)
               : environmentBrdfFromLut(environmentBrdfLut, vec3(kClearCoatF0),
                                        s.clearCoatRoughness, NoV);
    return s.clearCoat * prefiltered * coatBrdf;
}

#endif
