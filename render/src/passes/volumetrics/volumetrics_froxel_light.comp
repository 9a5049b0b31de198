#version 460
#extension GL_GOOGLE_include_directive : require
#include "volumetrics_bindings.h"
#include "volumetric_view_ray.glsl"
// Froxels, step 1: each froxel of the view-aligned grid (exponential depth slices) lights the
// medium at its centre from the lights that reach it, with shadows, and stores (radiance
// scattered toward the camera per metre, extinction per metre).
//
// Lit from cluster lists: each workgroup is a cluster of 4x4x4 froxels whose lights (those whose
// volume's box, projected, covers its columns and slices) the CPU listed (light_bins.h), and
// each froxel evaluates only those. (The lighting pass's own cluster lists cover the clusters
// that hold surfaces, not the air in front of them. Lists built here, each cluster testing every
// light in shared memory between barriers, made this pass 2.2x dearer at 16 lights and 6.7x
// at 4,096 on lavapipe: render/README.md "Volumetric lighting".)
//
// The sun's channel (push lights.z 1): in frames whose sun is marched per pixel over the
// froxels and that have blended surfaces, wires or hair, the cluster lists hold the directional
// lights too, and their in-scattering goes to a second array after the first (rgb per metre),
// integrated beside it for those readers only: the opaque composite leaves the sun to its march.
#include "light_bins.glsl"
#include "volumetric_medium.glsl"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(std430, binding = VOLUMETRICS_BINDING_FROXEL_MEDIUM) writeonly buffer FroxelMedium {
    vec4 froxelMedium[];
};

void main() {
    uvec3 f = gl_GlobalInvocationID;
    if (any(greaterThanEqual(f, push.grid.xyz))) return;
    vec2 ndc = (vec2(f.xy) + 0.5) / vec2(push.grid.xy) * 2.0 - 1.0;
    vec3 origin = camera.cameraPosition.xyz;
    vec4 nearPoint = vec4(unjitteredNearPoint(ndc), 1.0);
    vec3 perDepth = (nearPoint.xyz / nearPoint.w - origin) / push.range.y;
    float near = sliceBoundaryDepth(float(f.z));
    float far = sliceBoundaryDepth(float(f.z + 1u));
    float d = 0.5 * (near + far);
    vec3 P = origin + perDepth * d;
    // Half the froxel's larger side: across (to the next column's ray) or along the view.
    vec4 nextPoint = vec4(unjitteredNearPoint(ndc + vec2(2.0 / float(push.grid.x), 0.0)), 1.0);
    vec3 nextPerDepth = (nextPoint.xyz / nextPoint.w - origin) / push.range.y;
    float radius = 0.5 * max(d * length(nextPerDepth - perDepth), (far - near) * length(perDepth));
    vec3 toCamera = -normalize(perDepth);

    // A bounded medium: the froxel's share of its column ray that lies in the box, lit at that
    // share's middle, so a box face cuts the medium within a froxel rather than at its centre.
    float density = mediumDensity(P);
    if (mediumBounded()) {
        float scale = length(perDepth);
        vec2 span = mediumSpan(origin, perDepth / scale, far * scale);
        float t0 = max(span.x, near * scale);
        float t1 = min(span.y, far * scale);
        density = 0.0;
        if (t0 < t1) {
            P = origin + perDepth / scale * (0.5 * (t0 + t1));
            density = mediumDensity(P) * (t1 - t0) / ((far - near) * scale);
        }
    }
    float sigmaT = (push.medium.x + push.medium.y) * density;
    bool sunChannel = push.lights.z == 1u;
    vec3 sum = vec3(0.0);
    vec3 sunSum = vec3(0.0);
    if (push.medium.x > 0.0 && density > 0.0) {
        uvec2 listed = workgroupLightRange();
        uint k = listed.x;
        // The plain lights lead the list (light_bins.h): a body without shadow or area code.
        for (; k < listed.y; ++k) {
            uint index = lightBins[k];
            if (!isPlainMediumLight(index)) break;
            sum += plainLightInScattering(index, P, toCamera, sigmaT, radius);
        }
        for (; k < listed.y; ++k) {
            uint index = lightBins[k];
            vec3 lit = lightInScattering(index, P, toCamera, sigmaT, radius);
            if (sunChannel && uint(lightData[3u * push.lights.y + index].w) == kLightDirectional)
                sunSum += lit;
            else
                sum += lit;
        }
    }
    uint index = froxelIndex(f);
    froxelMedium[index] = vec4(sum * (push.medium.x * density), sigmaT);
    if (sunChannel) {
        uint froxels = push.grid.x * push.grid.y * push.grid.z;
        froxelMedium[froxels + index] = vec4(sunSum * (push.medium.x * density), 0.0);
    }
}
