#version 460
#extension GL_GOOGLE_include_directive : require
#include "volumetrics_bindings.h"
// Per-light volumes, rasterised, first draw: the whole screen, the sun's volume (Vos 2014,
// GPU Pro 5, "Volumetric Light Effects in Killzone: Shadow Fall"), marched cascade by cascade
// (volumes_march.glsl) for each directional light in the instance list's head (push.lights.z of
// them). It stores (in-scattered radiance, view depth) at every half-resolution pixel, which the
// proxies then add to, and the scene's depth at full-resolution pixel 2q (the sample the rays end
// at) for their depth test.
#include "volumes_march.glsl"

layout(std430, binding = VOLUMETRICS_BINDING_PROXY_INSTANCES) readonly buffer ProxyInstances {
    uint proxyLights[];
};

layout(location = 0) out vec4 scattered;

void main() {
    ivec2 half_ = ivec2(gl_FragCoord.xy);
    VolumeRay ray = volumeRay(half_);
    ivec2 size = ivec2(camera.frameInfo.xy);
    gl_FragDepth = texelFetch(gbufferDepth, min(half_ * 2, size - 1), 0).r;
    vec3 radiance = vec3(0.0);
    vec2 span = mediumSpan(ray.origin, ray.direction, ray.surfaceT);
    if (push.medium.x > 0.0 && span.x < span.y) {
        float steps = float(max(push.grid.w, 1u));
        for (uint k = 0u; k < push.lights.z; ++k) {
            uint i = proxyLights[k];
            radiance += marchSun(i, loadLight(i, push.lights.y), ray.origin, ray.direction,
                                 span.x, span.y, steps, ray.dither);
        }
    }
    scattered = vec4(radiance, ray.viewDepth);
}
