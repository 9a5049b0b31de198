#version 460
#extension GL_GOOGLE_include_directive : require
#include "scattering_bindings.h"
// Light shafts, steps 2, 4 and 5 (Yusov 2014, GPU Pro 5, "High Performance Outdoor Light Scattering
// Using Epipolar Sampling"; Yusov 2013 section 3.2): ray marching at the epipolar samples, in three
// phases (push batch.y).
// 0: the initial samples, every N-th of each slice (N the initial step) and its last.
// 1: refinement. Shafts run along epipolar lines, so between initial samples the in-scattering
//    changes slowly except across depth edges: the two samples either side of an edge (view
//    distances differing by more than the threshold times the nearer) are marched, and so is
//    every (N/4)-th sample of an interval whose ends' in-scattering differs by more than the
//    threshold times the larger (luminance).
// 2: interpolation. Every other sample is interpolated linearly between the nearest marched
//    samples either side, which no depth edge separates from it (the samples at an edge are
//    marched). The inscatter image's alpha is the view distance d of a marched sample and
//    -d - 1 for an interpolated one.
#include "scattering_march.glsl"

layout(local_size_x = 64) in;

layout(binding = SCATTERING_BINDING_TREE) uniform sampler2D tree;
layout(binding = SCATTERING_BINDING_COORDINATES, rgba32f) uniform readonly image2D coordinates;
layout(binding = SCATTERING_BINDING_INSCATTER, rgba32f) uniform image2D inscatter;
layout(std430, binding = SCATTERING_BINDING_SLICES) readonly buffer Slices {
    SliceInfo slices[];
};

vec3 marchSample(uint slice, vec4 coordinate, inout uint steps) {
    float unused;
    vec3 direction = pixelRay(coordinate.xy, unused);
    return marchEpipolarRay(tree, slices[slice], slice, direction, coordinate.z, steps);
}

float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

bool depthEdge(float a, float b) { return abs(a - b) > push.sun.z * min(a, b); }
float distanceAt(uint i, uint slice) { return imageLoad(coordinates, ivec2(i, slice)).z; }

bool marchedInRefinement(uint slice, uint index, uint first, uint last, uint step) {
    float d = distanceAt(index, slice);
    if (depthEdge(d, distanceAt(index - 1u, slice)) || depthEdge(d, distanceAt(index + 1u, slice)))
        return true;
    uint subStep = max(step / 4u, 1u);
    if ((index - first) % subStep != 0u) return false;
    float la = luminance(imageLoad(inscatter, ivec2(first, slice)).rgb);
    float lb = luminance(imageLoad(inscatter, ivec2(last, slice)).rgb);
    return abs(la - lb) > push.sun.z * max(max(la, lb), 1e-30);
}

void main() {
    uint slice = gl_GlobalInvocationID.y;
    uint samples = push.epipolar.y;
    uint step = max(push.epipolar.z, 1u);
    if (slice >= push.epipolar.x) return;
    uint index;
    if (push.batch.y == 0u) {
        index = min(gl_GlobalInvocationID.x * step, samples - 1u);
        if (gl_GlobalInvocationID.x * step >= samples + step - 1u) return;
    } else {
        index = gl_GlobalInvocationID.x;
        if (index >= samples || index % step == 0u || index == samples - 1u) return;
    }
    vec4 coordinate = imageLoad(coordinates, ivec2(index, slice));
    if (coordinate.w == 0.0) {  // a line off the screen: no pixel reads it
        imageStore(inscatter, ivec2(index, slice), vec4(0.0, 0.0, 0.0, coordinate.z));
        return;
    }
    // An interpolated sample's alpha stays negative (-distance - 1), so phase 2 tells marched
    // samples from the others while it writes them.
    float unmarched = -coordinate.z - 1.0;
    uint first = index / step * step;
    uint last = min(first + step, samples - 1u);
    vec3 radiance;
    uint steps = 0u;
    if (push.batch.y == 0u) {
        radiance = marchSample(slice, coordinate, steps);
    } else if (push.batch.y == 1u) {
        if (!marchedInRefinement(slice, index, first, last, step)) {
            imageStore(inscatter, ivec2(index, slice), vec4(0.0, 0.0, 0.0, unmarched));
            return;
        }
        radiance = marchSample(slice, coordinate, steps);
    } else {
        if (imageLoad(inscatter, ivec2(index, slice)).a >= 0.0) return;  // marched
        uint left = index - 1u;
        while (left > first && imageLoad(inscatter, ivec2(left, slice)).a < 0.0) --left;
        uint right = index + 1u;
        while (right < last && imageLoad(inscatter, ivec2(right, slice)).a < 0.0) ++right;
        float w = float(index - left) / float(right - left);
        radiance = mix(imageLoad(inscatter, ivec2(left, slice)).rgb,
                       imageLoad(inscatter, ivec2(right, slice)).rgb, w);
    }
    if (steps > 0u) {
        atomicAdd(counters.raysMarched, 1u);
        atomicAdd(counters.shadowTests, steps);
    }
    imageStore(inscatter, ivec2(index, slice),
               vec4(radiance, push.batch.y == 2u ? unmarched : coordinate.z));
}
