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
    vec3 prefiltered =
        textureLod(prefilteredCube, R, prefilteredMipOfRoughness(s.roughness, prefilteredMipCount))
            .rgb;
    vec3 environmentBrdf;
    if (mobile) {
        // G-buffer Specular is 8-bit: 0.5 arrives as 128 / 255.
        bool defaultNonmetal = s.shadingModel == kShadingDefaultLit && s.metallic == 0.0 &&
                               abs(s.specular - 0.5) < 1.0 / 255.0;
        environmentBrdf = environmentBrdfMobile(t.specularColor, s.roughness, NoV, defaultNonmetal);
    } else {
        environmentBrdf =
            environmentBrdfFromLut(environmentBrdfLut, t.specularColor, s.roughness, NoV);
    }
    vec3 ambient = diffuse + prefiltered * environmentBrdf;
    if (kEnergyConserving) {
        float albedo = mobile ? envBrdfApproxDirectionalAlbedo(s.roughness, NoV)
                              : specularDirectionalAlbedo(environmentBrdfLut, s.roughness, NoV);
        ambient += multipleScatteringEnvironmentBrdf(environmentBrdf, t.specularColor, albedo) *
                   irradiance * (1.0 / PI);
    }
    return ambient;
}

#endif
