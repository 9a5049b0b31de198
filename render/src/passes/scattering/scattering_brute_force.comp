#version 460
#extension GL_GOOGLE_include_directive : require
#include "scattering_bindings.h"
// Light shafts, the reference (`--scattering brute-force`): every pixel marches its view ray
// in equal steps (push batch.x), each step lit or not by one lookup in the cascade that holds
// its midpoint, and integrated exactly over the step when lit. The steps come in batches, one
// dispatch each (batch.y the first, batch.z how many): lavapipe ends an invocation's loops
// after 65,535 iterations in all (the cascade search loops too). The first batch attenuates
// the frame (hdr T), every batch adds its steps' in-scattering.
#include "scattering_march.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = SCATTERING_BINDING_DEPTH) uniform sampler2D gbufferDepth;
layout(binding = SCATTERING_BINDING_HDR, rgba32f) uniform image2D hdrRadiance;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    uvec2 size = camera.frameInfo.xy;
    if (pixel.x >= int(size.x) || pixel.y >= int(size.y)) return;
    float perDepth;
    vec3 direction = pixelRay(vec2(pixel) + 0.5, perDepth);
    float distance = rayDistance(texelFetch(gbufferDepth, pixel, 0).r, perDepth);
    Light sun = sunLight();
    vec3 source = sunSource(sun, direction);
    vec3 origin = camera.cameraPosition.xyz;
    bool shadowed = kShadowsEnabled && push.lights.w != 0u;
    float dt = distance / float(push.batch.x);
    vec3 radiance = vec3(0.0);
    uint end = min(push.batch.y + push.batch.z, push.batch.x);
    for (uint i = push.batch.y; i < end; ++i) {
        float t0 = float(i) * dt;
        if (!shadowed || sunLightsPoint(sun, origin + direction * (t0 + 0.5 * dt)))
            radiance += litRun(source, t0, t0 + dt);
    }
    if (push.batch.y == 0u) atomicAdd(counters.raysMarched, 1u);
    atomicAdd(counters.shadowTests, end - push.batch.y);
    vec4 surface = imageLoad(hdrRadiance, pixel);
    vec3 attenuated = surface.rgb;
    if (push.batch.y == 0u)  // the first batch: the frame behind, attenuated (or nothing)
        attenuated = push.batch.w == 1u ? vec3(0.0) : surface.rgb * viewTransmittance(distance);
    imageStore(hdrRadiance, pixel, vec4(attenuated + radiance, surface.a));
}
