// The lit inputs' buffers and sky textures (render/src/lit_inputs.h binds them at the numbers of
// common/lit_bindings.h, which the includer's bindings header includes): the cluster lists, the
// frame's slicing ([2] sliceNear, [3] logRatio as float bits, from depth_occupancy.comp: read
// here rather than pushed, so lists assigned on the device need no host round trip) and the
// sky's prefiltered cube (roughness per mip), BRDF LUT and SH irradiance.
#ifndef CANDELA_LIT_INPUTS_GLSL
#define CANDELA_LIT_INPUTS_GLSL

layout(std430, binding = LIT_BINDING_CLUSTER_RANGES) readonly buffer ClusterRanges {
    uint clusterRanges[];
};
layout(std430, binding = LIT_BINDING_LIGHT_INDICES) readonly buffer LightIndices {
    uint lightIndices[];
};
layout(std430, binding = LIT_BINDING_DEPTH_RANGE) readonly buffer DepthRange {
    uint depthRange[];
};
layout(binding = LIT_BINDING_PREFILTERED) uniform samplerCube prefilteredCube;
layout(binding = LIT_BINDING_BRDF_LUT) uniform sampler2D environmentBrdfLut;
layout(std430, binding = LIT_BINDING_IRRADIANCE_SH) readonly buffer IrradianceSh {
    vec4 irradianceSh[9];
};

#endif
