#version 460
#extension GL_GOOGLE_include_directive : require
#include "volumetrics_bindings.h"
#include "volumetric_view_ray.glsl"
// Froxels, step 2: each column of the grid integrates its froxels front to back, storing at
// each slice's far boundary the radiance scattered toward the camera from the near plane to
// there and the transmittance over that distance; with the sun's channel (push lights.z 1,
// volumetrics_froxel_light.comp), the sun's radiance too, through the same extinction, in the
// boundaries after the fog's (common/froxel_grid.glsl).
#include "common/camera.glsl"
#include "common/froxel_grid.glsl"
#include "volumetric_step.glsl"
#include "volumetrics_push.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = VOLUMETRICS_BINDING_FROXEL_MEDIUM) readonly buffer FroxelMedium {
    vec4 froxelMedium[];
};
layout(std430, binding = VOLUMETRICS_BINDING_FROXEL_INTEGRATED) writeonly buffer FroxelIntegrated {
    FroxelGrid froxelParams;  // read by common/froxel_lookup.glsl
    AerialGrid aerialParams;  // "no air" here; the air's pass, when the frame has one, runs
                              // after this one and writes its own
    vec4 froxelIntegrated[];
};

void main() {
    uvec2 column = gl_GlobalInvocationID.xy;
    bool sunChannel = push.lights.z == 1u;
    if (all(equal(column, uvec2(0u)))) {
        froxelParams =
            FroxelGrid(uvec4(push.grid.xyz, sunChannel ? 2u : 1u), vec4(push.range.yz, 0.0, 0.0));
        aerialParams.grid = uvec4(0u);
    }
    if (any(greaterThanEqual(column, push.grid.xy))) return;
    vec2 ndc = (vec2(column) + 0.5) / vec2(push.grid.xy) * 2.0 - 1.0;
    vec4 nearPoint = vec4(unjitteredNearPoint(ndc), 1.0);
    // Metres along the ray per metre of view depth.
    float stretch = length(nearPoint.xyz / nearPoint.w - camera.cameraPosition.xyz) / push.range.y;
    vec3 radiance = vec3(0.0);
    float transmittance = 1.0;
    vec3 sunRadiance = vec3(0.0);
    uint froxels = push.grid.x * push.grid.y * push.grid.z;
    for (uint z = 0u; z < push.grid.z; ++z) {
        uint index = froxelIndex(uvec3(column, z));
        float dt = (sliceBoundaryDepth(float(z + 1u)) - sliceBoundaryDepth(float(z))) * stretch;
        vec4 m = froxelMedium[index];
        if (sunChannel) {
            float before = transmittance;  // the same step for the sun's radiance
            integrateStep(vec4(froxelMedium[froxels + index].rgb, m.w), dt, sunRadiance, before);
            froxelIntegrated[froxels + index] = vec4(sunRadiance, 0.0);
        }
        integrateStep(m, dt, radiance, transmittance);
        froxelIntegrated[index] = vec4(radiance, transmittance);
    }
}
