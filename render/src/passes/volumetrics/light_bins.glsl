// The lights whose volume reaches this workgroup's screen tile or froxel cluster, listed on the
// CPU (light_bins.h): for B workgroups in the dispatch, B + 1 offsets, then the lists, each in
// ascending light index. A bin per workgroup, numbered as the dispatch numbers them.
#ifndef CANDELA_LIGHT_BINS_GLSL
#define CANDELA_LIGHT_BINS_GLSL

layout(std430, binding = VOLUMETRICS_BINDING_LIGHT_BINS) readonly buffer LightBins {
    uint lightBins[];
};

// [first, end) in lightBins of this workgroup's lights.
uvec2 workgroupLightRange() {
    uvec3 n = gl_NumWorkGroups;
    uint bin = (gl_WorkGroupID.z * n.y + gl_WorkGroupID.y) * n.x + gl_WorkGroupID.x;
    uint lists = n.x * n.y * n.z + 1u;
    return uvec2(lightBins[bin], lightBins[bin + 1u]) + lists;
}

#endif
