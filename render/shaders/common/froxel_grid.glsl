// The head of the integrated froxel buffer: the fog's grid shape (passes/volumetrics) and the
// air's aerial-perspective grid (passes/scattering), each written by the pass that fills its
// part of the buffer, so a reader needs one binding for both media (the forward pass is at
// lavapipe's 32 descriptors). The fog's boundaries follow the head; in frames whose sun is
// marched per pixel over the froxels and that have blended surfaces, wires or hair, the sun's
// own boundaries follow them (grid.w 2: its in-scattering, which the fog's leave out, for those
// readers only); the air's follow, at aerialParams.range.y. A buffer of zeros says "no medium".
// Matches VolumetricsPass::kFroxelHeaderBytes.
#ifndef CANDELA_FROXEL_GRID_GLSL
#define CANDELA_FROXEL_GRID_GLSL

struct FroxelGrid {
    uvec4 grid;  // froxels x, y, slices; w: 0 no froxels, 1 the fog's, 2 then the sun's too
    vec4 range;  // x: near, y: far (view depth, m)
};

// The atmosphere's air in front of blended surfaces (render/README.md "Aerial perspective"):
// per column and slice boundary, the sun's visibility-weighted path integral
// W = integral of vis(t) exp(-sigma_t t) dt from the camera (rgb, 1/m units times m); the
// in-scattered radiance is W times the sun's source for the reader's own view direction, and
// the transmittance exp(-sigma_t distance) is exact (the air is uniform over a scene).
struct AerialGrid {
    uvec4 grid;        // columns x, y, slices; w: 1 when the frame has the air's grid, else 0
    vec4 range;        // x: far (view depth, m), y: first boundary (vec4 index), z: near plane
    vec4 extinction;   // rgb: sigma_t (1/m); w: Mie anisotropy g
    vec4 sunRayleigh;  // rgb: the sun's illuminance times Rayleigh scattering
    vec4 sunMie;       // rgb: the sun's illuminance times Mie scattering
    vec4 towardSun;    // xyz: unit direction toward the sun
};

#endif
