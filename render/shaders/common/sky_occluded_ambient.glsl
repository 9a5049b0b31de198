// The environment's ambient light on a surface with sky occlusion (render/README.md "Sky
// occlusion"): the sky's diffuse seen around the bent normal, scaled by the share of the sky
// the surface sees, and its specular by the share of the lobe that sees it. One function for
// the deferred lighting pass (without ambient occlusion) and the forward pass's blended
// surfaces, so a pane is occluded exactly as an opaque surface at its place. The includer
// includes common/ambient_lighting.glsl, common/camera.glsl and common/sky_occlusion.glsl.
#ifndef CANDELA_SKY_OCCLUDED_AMBIENT_GLSL
#define CANDELA_SKY_OCCLUDED_AMBIENT_GLSL

vec3 skyOccludedEnvironmentAmbient(Surface s, SkyVisibility sky, vec3 N, vec3 V, vec4 sh[9],
                                   samplerCube prefilteredCube, float prefilteredMipCount,
                                   sampler2D environmentBrdfLut, bool mobile) {
    return occludedEnvironmentAmbient(s, N, sky.bentNormal, V, sh, prefilteredCube,
                                      prefilteredMipCount, environmentBrdfLut, mobile,
                                      vec3(sky.diffuse), sky.specular);
}

#endif
