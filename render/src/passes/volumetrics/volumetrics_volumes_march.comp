#version 460
#extension GL_GOOGLE_include_directive : require
#include "volumetrics_bindings.h"
#include "volumetric_view_ray.glsl"
// Per-light volumes, step 1 (Vos 2014, GPU Pro 5, "Volumetric Light Effects in Killzone: Shadow
// Fall"), tile-binned: at half resolution, each pixel's view ray (volumes_march.glsl) crosses each
// listed light's volume (a sphere, a cone or, for the sun, the whole screen: light_volume.glsl) and
// marches the segment inside. Stores (in-scattered radiance, view depth) for the bilateral blur and
// upsample.
//
// A light costs only the pixels its volume covers: each 8x8 tile (a workgroup) marches the
// lights listed for it on the CPU (light_bins.h: the volume's box projected to the screen, the
// proxy mesh's coverage at tile granularity), each pixel testing each of them against its own
// ray (a sphere or cone intersection) and marching only the segment inside. (Lists built here,
// a tile's frustum against every light in shared memory, cost 10x more on lavapipe than testing
// every light at every pixel: their barriers outweighed the tests they saved.) The rasterised
// proxies (volumetrics_volumes_proxy.frag) are the other way to the same sums.
#include "light_bins.glsl"
#include "volumes_march.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = VOLUMETRICS_BINDING_VOLUMES_MARCHED, rgba32f) uniform writeonly image2D marched;

void main() {
    ivec2 half_ = ivec2(gl_GlobalInvocationID.xy);
    ivec2 halfSize = (ivec2(camera.frameInfo.xy) + 1) / 2;
    if (half_.x >= halfSize.x || half_.y >= halfSize.y) return;
    VolumeRay ray = volumeRay(half_);
    float steps = float(max(push.grid.w, 1u));
    vec3 radiance = vec3(0.0);
    // A bounded medium is marched only where the ray crosses its box, so every step lands in it.
    vec2 span = mediumSpan(ray.origin, ray.direction, ray.surfaceT);
    if (push.medium.x > 0.0 && span.x < span.y) {
        uvec2 listed = workgroupLightRange();
        for (uint k = listed.x; k < listed.y; ++k) {
            uint i = lightBins[k];
            Light light = loadLight(i, push.lights.y);
            if (light.type == kLightDirectional) {
                radiance += marchSun(i, light, ray.origin, ray.direction, span.x, span.y, steps,
                                     ray.dither);
                continue;
            }
            // Rect and disk lights are marched apart (below), so this loop's copy of the
            // in-scattering leaves their form-factor code out.
            if (kMediumAreaLights && isMediumAreaLight(light)) continue;
            radiance += marchLocalLight(i, light, ray, span, steps, false);
        }
        for (uint k = listed.x; kMediumAreaLights && k < listed.y; ++k) {
            uint i = lightBins[k];
            Light light = loadLight(i, push.lights.y);
            if (!isMediumAreaLight(light)) continue;
            radiance += marchLocalLight(i, light, ray, span, steps, true);
        }
    }
    imageStore(marched, half_, vec4(radiance, ray.viewDepth));
}
