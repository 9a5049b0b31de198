#version 460
#extension GL_GOOGLE_include_directive : require
#include "volumetrics_bindings.h"
#include "volumetric_view_ray.glsl"
// Froxels, step 1: each froxel of the view-aligned grid (exponential depth slices) lights the
// medium at its centre from the lights that reach it, with shadows, and stores (radiance
// scattered toward the camera per metre, extinction per metre).
//
// Lit from cluster lists: each workgroup is a cluster of 4x4x4 froxels that first lists the
// lights whose range reaches its box (64 lights at a time, one per thread), then each froxel
// evaluates only the listed ones. (The lighting pass's own cluster lists cover the clusters that
// hold surfaces, not the air in front of them, so the grid culls for itself.)
#include "volumetric_medium.glsl"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
const uint kClusterThreads = 64u;

layout(std430, binding = VOLUMETRICS_BINDING_FROXEL_MEDIUM) writeonly buffer FroxelMedium {
    vec4 froxelMedium[];
};

shared vec3 clusterMin;
shared vec3 clusterMax;
// Whether light (batch start + i) reaches the cluster: a flag per thread, read in order so the
// sum's order, and so the result, is the same every frame.
shared bool clusterHit[kClusterThreads];

// World position at view depth d on the ray through the near plane's ndc point.
vec3 pointAt(vec2 ndc, float d) {
    vec4 nearPoint = vec4(unjitteredNearPoint(ndc), 1.0);
    vec3 origin = camera.cameraPosition.xyz;
    return origin + (nearPoint.xyz / nearPoint.w - origin) * (d / push.range.y);
}

// Whether light i lights anything in the cluster's box: the sun always, a local light when
// the sphere of its range touches the box (spots by that sphere too: conservative).
bool lightReachesCluster(uint i) {
    if (lightScales[i] <= 0.0) return false;
    Light light = loadLight(i, push.lights.y);
    if (light.type == kLightDirectional) return true;
    if (light.invAttenuationRadius <= 0.0) return true;
    vec3 nearest = clamp(light.position, clusterMin, clusterMax);
    vec3 d = light.position - nearest;
    return dot(d, d) * light.invAttenuationRadius * light.invAttenuationRadius <= 1.0;
}

void main() {
    uvec3 f = gl_GlobalInvocationID;
    bool inside = all(lessThan(f, push.grid.xyz));
    if (gl_LocalInvocationIndex == 0u) {
        uvec3 lo = gl_WorkGroupID * gl_WorkGroupSize;
        uvec3 hi = min(lo + gl_WorkGroupSize, push.grid.xyz);
        vec2 ndcLo = vec2(lo.xy) / vec2(push.grid.xy) * 2.0 - 1.0;
        vec2 ndcHi = vec2(hi.xy) / vec2(push.grid.xy) * 2.0 - 1.0;
        float dLo = sliceBoundaryDepth(float(lo.z)), dHi = sliceBoundaryDepth(float(hi.z));
        vec3 bMin = vec3(3e38), bMax = vec3(-3e38);
        for (uint c = 0u; c < 8u; ++c) {
            vec2 ndc = vec2((c & 1u) != 0u ? ndcHi.x : ndcLo.x, (c & 2u) != 0u ? ndcHi.y : ndcLo.y);
            vec3 P = pointAt(ndc, (c & 4u) != 0u ? dHi : dLo);
            bMin = min(bMin, P);
            bMax = max(bMax, P);
        }
        clusterMin = bMin;
        clusterMax = bMax;
    }
    barrier();

    uvec3 g = min(f, push.grid.xyz - 1u);
    vec2 ndc = (vec2(g.xy) + 0.5) / vec2(push.grid.xy) * 2.0 - 1.0;
    vec3 origin = camera.cameraPosition.xyz;
    vec4 nearPoint = vec4(unjitteredNearPoint(ndc), 1.0);
    vec3 perDepth = (nearPoint.xyz / nearPoint.w - origin) / push.range.y;
    float near = sliceBoundaryDepth(float(g.z));
    float far = sliceBoundaryDepth(float(g.z + 1u));
    float d = 0.5 * (near + far);
    vec3 P = origin + perDepth * d;
    // Half the froxel's larger side: across (to the next column's ray) or along the view.
    vec4 nextPoint = vec4(unjitteredNearPoint(ndc + vec2(2.0 / float(push.grid.x), 0.0)), 1.0);
    vec3 nextPerDepth = (nextPoint.xyz / nextPoint.w - origin) / push.range.y;
    float radius = 0.5 * max(d * length(nextPerDepth - perDepth), (far - near) * length(perDepth));
    vec3 toCamera = -normalize(perDepth);

    float density = mediumDensity(P);
    float sigmaT = (push.medium.x + push.medium.y) * density;
    vec3 sum = vec3(0.0);
    if (push.medium.x > 0.0) {
        for (uint base = 0u; base < push.lights.x; base += kClusterThreads) {
            uint mine = base + gl_LocalInvocationIndex;
            clusterHit[gl_LocalInvocationIndex] = mine < push.lights.x && lightReachesCluster(mine);
            barrier();
            uint batch = min(kClusterThreads, push.lights.x - base);
            for (uint k = 0u; k < batch; ++k) {
                if (clusterHit[k]) sum += lightInScattering(base + k, P, toCamera, sigmaT, radius);
            }
            barrier();
        }
    }
    if (inside) froxelMedium[froxelIndex(f)] = vec4(sum * (push.medium.x * density), sigmaT);
}
