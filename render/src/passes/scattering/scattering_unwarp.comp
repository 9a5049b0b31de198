#version 460
#extension GL_GOOGLE_include_directive : require
#include "scattering_bindings.h"
// Light shafts, step 6 (Yusov 2014, GPU Pro 5, "High Performance Outdoor Light Scattering Using
// Epipolar Sampling"; Yusov 2013 section 3.3): from epipolar samples back to pixels. A pixel lies
// between two slices and, on each, between two samples: the four are weighted bilinearly and by how
// close their view distances are to the pixel's (a sample across a depth edge gets none), and the
// frame behind is attenuated by the air in front: hdr = hdr T + L. A pixel whose four samples all
// lie across depth edges is marched itself, through the trees of its nearer slice.
#include "scattering_epipolar.glsl"
#include "scattering_march.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = SCATTERING_BINDING_DEPTH) uniform sampler2D gbufferDepth;
layout(binding = SCATTERING_BINDING_HDR, rgba32f) uniform image2D hdrRadiance;
layout(binding = SCATTERING_BINDING_TREE) uniform sampler2D tree;
layout(binding = SCATTERING_BINDING_INSCATTER, rgba32f) uniform readonly image2D inscatter;
layout(std430, binding = SCATTERING_BINDING_SLICES) readonly buffer Slices {
    SliceInfo slices[];
};

// A sample's distance counts fully within 5% of the pixel's and not at all past 15%.
const float kDepthTolerance = 0.05;

float depthWeight(float sampleDistance, float pixelDistance) {
    float relative = abs(sampleDistance - pixelDistance) / max(pixelDistance, 1e-4);
    return saturate(1.5 - relative / (2.0 * kDepthTolerance));
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    uvec2 frame = camera.frameInfo.xy;
    if (pixel.x >= int(frame.x) || pixel.y >= int(frame.y)) return;
    vec2 size = vec2(frame);
    vec2 position = vec2(pixel) + 0.5;
    float perDepth;
    vec3 direction = pixelRay(position, perDepth);
    float distance = rayDistance(texelFetch(gbufferDepth, pixel, 0).r, perDepth);
    uint sliceCount = push.epipolar.x;
    uint samples = push.epipolar.y;
    float s = pixelSlice(position, sliceCount, push.sun.xy, size);
    float sliceFloor = floor(s);
    float sliceWeight = s - sliceFloor;
    vec3 sum = vec3(0.0);
    float weights = 0.0;
    for (int k = 0; k < 2; ++k) {
        uint slice = uint(int(sliceFloor) + k + int(sliceCount)) % sliceCount;
        SliceInfo info = slices[slice];
        if (info.flags.w == 0.0) continue;
        vec2 entry = info.endpoints.xy, exitPoint = info.endpoints.zw;
        vec2 line = exitPoint - entry;
        float along = saturate(dot(position - entry, line) / max(dot(line, line), 1e-12));
        float f = along * float(samples - 1u);
        float i0 = min(floor(f), float(samples - 2u));
        float w1 = f - i0;
        float ws = k == 0 ? 1.0 - sliceWeight : sliceWeight;
        for (int j = 0; j < 2; ++j) {
            vec4 value = imageLoad(inscatter, ivec2(int(i0) + j, int(slice)));
            float sampleDistance = value.a >= 0.0 ? value.a : -value.a - 1.0;  // see samples
            float w = ws * (j == 0 ? 1.0 - w1 : w1) * depthWeight(sampleDistance, distance);
            sum += value.rgb * w;
            weights += w;
        }
    }
    vec3 radiance;
    if (weights > 1e-3) {
        radiance = sum / weights;
    } else {
        uint nearer = uint(int(sliceFloor) + (sliceWeight < 0.5 ? 0 : 1) + int(sliceCount)) %
                      sliceCount;
        uint steps = 0u;
        radiance = marchEpipolarRay(tree, slices[nearer], nearer, direction, distance, steps);
        atomicAdd(counters.raysMarched, 1u);
        atomicAdd(counters.shadowTests, steps);
    }
    vec4 surface = imageLoad(hdrRadiance, pixel);
    vec3 behind = push.batch.w == 1u ? vec3(0.0) : surface.rgb * viewTransmittance(distance);
    imageStore(hdrRadiance, pixel, vec4(behind + radiance, surface.a));
}
