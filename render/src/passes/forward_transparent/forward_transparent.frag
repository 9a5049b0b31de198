#version 460
#extension GL_GOOGLE_include_directive : require
#include "forward_transparent_bindings.h"
#include "common/specialization_ids.h"
// Forward+ shading of alpha-blended (glTF BLEND) surfaces over the deferred result: the same
// material evaluation as the G-buffer pass and the same lights, light code and cluster lists
// as the deferred lighting pass, so a blended surface is lit exactly like an opaque one with
// the same inputs. Output is straight alpha ("over", glTF 2.0 alphaMode BLEND): the pipeline
// blends rgb with SRC_ALPHA, ONE_MINUS_SRC_ALPHA; emissive is part of the surface's colour.
#define MATERIAL_BUFFER_BINDING FORWARD_BINDING_MATERIALS
#define MATERIAL_TEXTURE_BINDING FORWARD_BINDING_FIRST_TEXTURE
#include "common/ambient_lighting.glsl"
#include "common/camera.glsl"
#include "common/clusters.glsl"
#include "common/light_buffer.glsl"
#include "common/material.glsl"
#include "common/motion_vectors.glsl"
#include "common/shading_models.glsl"
#include "common/shadows.glsl"
#define FROXEL_INTEGRATED_BINDING FORWARD_BINDING_FROXEL_INTEGRATED
#include "common/froxel_lookup.glsl"
#include "common/sky_occlusion.glsl"
#include "common/sky_occluded_ambient.glsl"

layout(constant_id = SPEC_CLUSTERED) const bool kClustered = true;
// Image-based lighting as the deferred pass does it: 0 none, 1 split sum, 2 mobile.
layout(constant_id = SPEC_IBL_MODE) const uint kIblMode = 0u;
// Sky occlusion as the lighting pass applies it (off: the full sky).
layout(constant_id = SPEC_SKY_OCCLUSION) const bool kSkyOcclusion = false;

#include "common/lit_inputs.glsl"
#include "common/pixel_lights.glsl"


layout(push_constant) uniform Draw {
    mat4 world;
    uint material;
    uint directionalCount;
    ClusterGridParams grid;
    uvec2 size;             // used by the occupancy variant
    vec2 projectionScale;   // used by the occupancy variant
    float skyIntensity;
    float prefilteredMipCount;
} draw;

layout(location = 0) in vec3 inNormal;
layout(location = 1) in vec4 inTangent;
layout(location = 2) in vec2 inUv0;
layout(location = 3) in vec2 inUv1;
layout(location = 4) in vec4 inColor;
layout(location = 5) in vec4 inCurrentClip;
layout(location = 6) in vec4 inPreviousClip;

layout(location = 0) out vec4 outRadiance;  // cd/m^2, a = coverage
layout(location = 1) out vec4 outMotion;    // gbuffer.motion, blended by the same coverage

vec3 lightRadiance(Surface surface, vec3 P, vec3 N, vec3 V, vec3 R, float alpha, uint index) {
    Light light = loadLight(index, camera.frameInfo.w);
    LightIncidence incidence = evaluateLight(light, P, N, R, alpha);
    // Out of the light's range or cone nothing is lit whatever the map says: no sampling.
    float visibility = any(greaterThan(incidence.incidentIlluminance, vec3(0.0)))
                           ? shadowVisibility(light, index, P, N)
                           : 1.0;
    incidence.diffuseIlluminance *= visibility;
    incidence.specularIlluminance *= visibility;
    incidence.incidentIlluminance *=
        kSubsurfaceEnabled && surface.shadingModel == kShadingSubsurface
            ? subsurfaceTransmittance(light, index, P)
            : visibility;
    return shadeSurface(surface, N, V, incidence);
}

void main() {
    MaterialUv uv = materialGradients(inUv0, inUv1);
    Material m = materials[draw.material];
    vec4 baseColor = materialBaseColor(m, uv, inColor);
    MaterialSample s = evaluateMaterial(m, uv, baseColor, inNormal, inTangent, gl_FrontFacing);

    vec3 radiance = s.emissive;
    if (s.shadingModel != kShadingUnlit) {
        Surface surface;
        clearSurfaceExtensions(surface);
        surface.baseColor = s.baseColor.rgb;
        surface.roughness = s.roughness;
        surface.metallic = s.metallic;
        surface.specular = s.specular;
        surface.shadingModel = s.shadingModel;
        surface.customData = s.customData;

        // The world position from the fragment's depth, as the deferred pass reconstructs it.
        uvec2 size = camera.frameInfo.xy;
        vec2 ndc = gl_FragCoord.xy / vec2(size) * 2.0 - 1.0;
        vec4 world = camera.inverseViewProjection * vec4(ndc, gl_FragCoord.z, 1.0);
        vec3 P = world.xyz / world.w;
        vec3 N = s.N;
        vec3 V = safeNormalize(camera.cameraPosition.xyz - P);
        vec3 R = reflect(-V, N);
        float alpha = alphaFromRoughness(s.roughness);
        surface.directionalAlbedo =
            specularDirectionalAlbedo(environmentBrdfLut, s.roughness, saturate(dot(N, V)));

        if (kIblMode != 0u) {
            vec4 sh[9] = irradianceSh;
            vec3 ambient;
            if (kSkyOcclusion) {
                ambient = skyOccludedEnvironmentAmbient(
                    surface, skyVisibility(P, N, R, s.roughness), N, V, sh, prefilteredCube,
                    draw.prefilteredMipCount, environmentBrdfLut, kIblMode == 2u);
            } else {
                ambient = environmentAmbient(surface, N, V, sh, prefilteredCube,
                                             draw.prefilteredMipCount, environmentBrdfLut,
                                             kIblMode == 2u);
            }
            radiance += ambient * (s.occlusion * draw.skyIntensity);
        }

        // The transparency occupancy pass made sure the fragment's cluster holds every light
        // that reaches this depth, with the fragment's quarter in the masks.
        PixelLights lights = pixelLights(kClustered, draw.directionalCount, draw.grid,
                                         uvec2(gl_FragCoord.xy), gl_FragCoord.z);
        for (uint k = 0u; k < pixelLightCount(lights); ++k) {
            uint light = pixelLightAt(lights, k);
            if (light != kNoLight) radiance += lightRadiance(surface, P, N, V, R, alpha, light);
        }
    }
    // The fog's froxels, then the air, in front: a fully covered pixel shows what an opaque
    // surface here would.
    radiance = throughMediumAndAir(radiance, gl_FragCoord);
    outRadiance = vec4(radiance, saturate(s.baseColor.a));
    outMotion = vec4(screenMotion(inCurrentClip, inPreviousClip), 0.0, outRadiance.a);
}
