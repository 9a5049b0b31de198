// Ambient light of an environment on a surface by the split sum (eq. 7: prefiltered radiance x
// environment BRDF) or seed 001's mobile fit, plus SH diffuse: one function for the deferred
// lighting pass and the forward (transparent) pass, so both surfaces see the same sky.
#ifndef CANDELA_AMBIENT_LIGHTING_GLSL
#define CANDELA_AMBIENT_LIGHTING_GLSL

#include "common/ibl.glsl"
#include "common/shading_models.glsl"

// Radiance (before the sky intensity and occlusion) the environment reflects toward V.
// `sh`: irradiance coefficients (irradiance_sh.comp); `prefilteredCube`: roughness per mip.
vec3 environmentAmbient(Surface s, vec3 N, vec3 V, vec4 sh[9], samplerCube prefilteredCube,
                        float prefilteredMipCount, sampler2D environmentBrdfLut, bool mobile) {
    AmbientTerms t = ambientTermsOf(s);
    vec3 irradiance = shIrradiance(sh, N);
    vec3 diffuse = t.diffuseColor * (1.0 / PI) * irradiance;
    if (any(greaterThan(t.transmittedColor, vec3(0.0)))) {
        diffuse += t.transmittedColor * (1.0 / PI) * shIrradiance(sh, -N);
    }
    float NoV = saturate(dot(N, V));
    vec3 R = reflect(-V, N);
    // The split sum reads the cube and the LUT at this roughness (anisotropic: the lobe's mean).
    float roughness = s.roughness;
    if (kAnisotropyEnabled && s.anisotropy > 0.0) {
        vec2 alpha = anisotropicAlphas(s.roughness, s.anisotropy);
        R = anisotropicReflection(N, V, s.anisotropyT, alpha);
        roughness = anisotropicAmbientRoughness(alpha);
    }
    vec3 prefiltered =
        textureLod(prefilteredCube, R, prefilteredMipOfRoughness(roughness, prefilteredMipCount))
            .rgb;
    vec3 environmentBrdf;
    if (mobile) {
        // G-buffer Specular is 8-bit: 0.5 arrives as 128 / 255.
        bool defaultNonmetal = s.shadingModel == kShadingDefaultLit && s.metallic == 0.0 &&
                               abs(s.specular - 0.5) < 1.0 / 255.0;
        environmentBrdf = environmentBrdfMobile(t.specularColor, roughness, NoV, defaultNonmetal);
    } else {
        environmentBrdf =
            environmentBrdfFromLut(environmentBrdfLut, t.specularColor, roughness, NoV);
    }
    vec3 ambient = diffuse + prefiltered * environmentBrdf;
    if (kEnergyConserving) {
        float albedo = mobile ? envBrdfApproxDirectionalAlbedo(roughness, NoV)
                              : specularDirectionalAlbedo(environmentBrdfLut, roughness, NoV);
        ambient += multipleScatteringEnvironmentBrdf(environmentBrdf, t.specularColor, albedo) *
                   irradiance * (1.0 / PI);
    }
    return ambient;
}

// The clear coat's reflection of the environment by the split sum (or seed 001's fit on the
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
