#version 460
#extension GL_GOOGLE_include_directive : require
#include "volumetrics_bindings.h"
#include "volumetric_view_ray.glsl"
// Per-light volumes, step 3 (Vos 2014, GPU Pro 5, "Volumetric Light Effects in Killzone: Shadow
// Fall"): a bilateral upsample of the blurred half-resolution in-scattering onto the frame, and the
// view leg's transmittance on the surface behind: hdr = hdr * T + L. Half-resolution pixel q holds
// full-resolution pixel 2q's ray, so pixel p sits at p / 2 among them; the four around it weigh
// bilinearly and by depth likeness. Froxels with the sun marched per pixel (range.w = 1): the march
// holds the sun alone, added over the froxels' composite, which already attenuated the surface by
// the whole medium.
#include "volumetrics_push.glsl"
#include "common/camera.glsl"
#include "volumetric_density.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = VOLUMETRICS_BINDING_DEPTH) uniform sampler2D gbufferDepth;
layout(binding = VOLUMETRICS_BINDING_HDR, rgba32f) uniform image2D hdrRadiance;
layout(binding = VOLUMETRICS_BINDING_VOLUMES_BLURRED, rgba32f) uniform readonly image2D blurred;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(camera.frameInfo.xy);
    if (pixel.x >= size.x || pixel.y >= size.y) return;
    ivec2 halfSize = (size + 1) / 2;
    float depth = texelFetch(gbufferDepth, pixel, 0).r;
    float viewDepth = depth > 0.0 ? min(push.range.y / depth, push.range.z) : push.range.z;
    vec2 at = vec2(pixel) * 0.5;
    ivec2 base = ivec2(floor(at));
    vec2 f = at - vec2(base);
    vec3 sum = vec3(0.0);
    float weights = 0.0;
    vec3 nearest = vec3(0.0);
    float nearestGap = 1e30;
    for (int y = 0; y <= 1; ++y) {
        for (int x = 0; x <= 1; ++x) {
            ivec2 n = min(base + ivec2(x, y), halfSize - 1);
            vec4 v = imageLoad(blurred, n);
            float bilinear = (x == 0 ? 1.0 - f.x : f.x) * (y == 0 ? 1.0 - f.y : f.y);
            float gap = abs(v.a - viewDepth);
            float r = gap / (0.05 * viewDepth + 1e-3);
            float w = bilinear * exp(-r * r);
            sum += v.rgb * w;
            weights += w;
            if (bilinear > 0.0 && gap < nearestGap) {
                nearestGap = gap;
                nearest = v.rgb;
            }
        }
    }
    // No neighbour at this depth (a thin edge): the nearest in depth.
    vec3 radiance = weights > 1e-4 ? sum / weights : nearest;
    vec2 ndc = (vec2(pixel) + 0.5) / vec2(size) * 2.0 - 1.0;
    vec3 origin = camera.cameraPosition.xyz;
    vec4 nearPoint = vec4(unjitteredNearPoint(ndc), 1.0);
    vec3 perDepth = (nearPoint.xyz / nearPoint.w - origin) / push.range.y;
    float transmittance =
        push.range.w > 0.5
            ? 1.0
            : exp(-viewOpticalDepth(origin, normalize(perDepth), viewDepth * length(perDepth)));
    vec4 surface = imageLoad(hdrRadiance, pixel);
    imageStore(hdrRadiance, pixel, vec4(surface.rgb * transmittance + radiance, surface.a));
}
