// The head of the integrated froxel buffer (passes/volumetrics): the grid's shape, written by
// the integration with the froxels that follow it, so a reader needs no second binding for it
// (the forward pass is at lavapipe's 32 descriptors). A buffer of zeros says "no medium".
// Matches VolumetricsPass::kFroxelHeaderBytes.
#ifndef CANDELA_FROXEL_GRID_GLSL
#define CANDELA_FROXEL_GRID_GLSL

struct FroxelGrid {
    uvec4 grid;  // froxels x, y, slices; w: 1 when the frame has froxels, else 0
    vec4 range;  // x: near, y: far (view depth, m)
};

#endif
