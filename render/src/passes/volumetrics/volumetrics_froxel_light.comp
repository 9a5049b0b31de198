#version 460
#extension GL_GOOGLE_include_directive : require
#include "volumetrics_bindings.h"
// Froxels, step 1: each froxel of the view-aligned grid (exponential depth slices) lights the
// medium at its centre from every light that reaches it, with shadows, and stores (radiance
// scattered toward the camera per metre, extinction per metre).
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
    vec4 nearPoint = camera.inverseViewProjection * vec4(ndc, 1.0, 1.0);
    vec3 perDepth = (nearPoint.xyz / nearPoint.w - origin) / push.range.y;
    float near = sliceBoundaryDepth(float(f.z));
    float far = sliceBoundaryDepth(float(f.z + 1u));
    float d = 0.5 * (near + far);
    vec3 P = origin + perDepth * d;
    // Half the froxel's larger side: across (to the next column's ray) or along the view.
    vec4 nextPoint = camera.inverseViewProjection *
                     vec4(ndc + vec2(2.0 / float(push.grid.x), 0.0), 1.0, 1.0);
    vec3 nextPerDepth = (nextPoint.xyz / nextPoint.w - origin) / push.range.y;
    float radius = 0.5 * max(d * length(nextPerDepth - perDepth), (far - near) * length(perDepth));
    froxelMedium[froxelIndex(f)] = mediumAt(P, -normalize(perDepth), radius);
}
