#version 460
#extension GL_GOOGLE_include_directive : require
#include "volumetrics_bindings.h"
#include "volumetric_view_ray.glsl"
// Reference volumetric lighting, for measurement (render/README.md "Volumetric lighting"):
// every pixel marches its view ray from the camera to the surface (or the far distance) in
// `grid.w` equal steps, each lit by every light with its shadow, and attenuates the lit
// surface behind: hdr = hdr * T + L. The lights come in batches, one dispatch each (push
// lights.z, lights.w): the first applies T and adds its lights' L, the others add theirs.
#include "volumetric_medium.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = VOLUMETRICS_BINDING_DEPTH) uniform sampler2D gbufferDepth;
layout(binding = VOLUMETRICS_BINDING_HDR, rgba32f) uniform image2D hdrRadiance;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    uvec2 size = camera.frameInfo.xy;
    if (pixel.x >= int(size.x) || pixel.y >= int(size.y)) return;
    vec2 ndc = (vec2(pixel) + 0.5) / vec2(size) * 2.0 - 1.0;
    vec3 origin = camera.cameraPosition.xyz;
    vec4 nearPoint = vec4(unjitteredNearPoint(ndc), 1.0);
    // Per metre of view depth (its view depth is the near plane's).
    vec3 perDepth = (nearPoint.xyz / nearPoint.w - origin) / push.range.y;
    float depth = texelFetch(gbufferDepth, pixel, 0).r;
    // Reverse-Z: view depth = near / depth; 0 is the background, marched to the far distance.
    float viewDepth = depth > 0.0 ? min(push.range.y / depth, push.range.z) : push.range.z;
    float distance = viewDepth * length(perDepth);
    vec3 direction = normalize(perDepth);
    float dt = distance / float(push.grid.w);
    vec3 radiance = vec3(0.0);
    float transmittance = 1.0;
    for (uint i = 0u; i < push.grid.w; ++i) {
        vec3 P = origin + direction * ((float(i) + 0.5) * dt);
        integrateStep(mediumAt(P, -direction, 0.0), dt, radiance, transmittance);
    }
    vec4 surface = imageLoad(hdrRadiance, pixel);
    if (push.lights.z > 0u) transmittance = 1.0;  // a later batch: T is applied already
    imageStore(hdrRadiance, pixel, vec4(surface.rgb * transmittance + radiance, surface.a));
}
