// The push constants of every volumetric lighting shader, and the froxel grid's geometry.
#ifndef CANDELA_VOLUMETRICS_PUSH_GLSL
#define CANDELA_VOLUMETRICS_PUSH_GLSL

// Matches VolumetricsPush in volumetrics_pass.cpp.
layout(push_constant) uniform Push {
    vec4 medium;  // x: sigma_s, y: sigma_a (1/m), z: g, w: height falloff (1/m)
    vec4 range;   // x: base height (m), y: near, z: far (view depth, m); w: the volumes'
                  // composite adds only (1: the froxels' composite attenuated the surface)
    uvec4 grid;   // froxels x, y, slices; w: reference steps
    uvec4 lights; // x: count, y: buffer capacity; z, w: the reference's batch (first, count);
                  // z in the froxel lighting and integration: 1 with the sun's channel
    vec4 boundsMin; // xyz: the medium's box (world, m); w: 1 when bounded, 0 when it fills all
    vec4 boundsMax; // xyz: the box's far corner; w: unused
} push;

// View depth (m) of slice boundary b (common/froxel_lookup.glsl's slicing).
float sliceBoundaryDepth(float b) {
    if (b <= 0.0) return 0.0;
    return push.range.y * pow(push.range.z / push.range.y, b / float(push.grid.z));
}

// Index of froxel (x, y, slice) in the froxel buffers.
uint froxelIndex(uvec3 f) {
    return (f.z * push.grid.y + f.y) * push.grid.x + f.x;
}

#endif
