// The push constants of every light-shaft shader.
#ifndef CANDELA_SCATTERING_PUSH_GLSL
#define CANDELA_SCATTERING_PUSH_GLSL

// Matches ScatteringPush in scattering_pass.cpp.
layout(push_constant) uniform Push {
    vec4 rayleigh;    // rgb: Rayleigh scattering (1/m); w: Mie anisotropy g
    vec4 mie;         // rgb: Mie scattering (1/m); w: near plane (m)
    vec4 extinction;  // rgb: extinction (1/m); w: distance marched for the sky (m)
    vec4 sun;         // xy: the sun's (or anti-sun's) position in pixels; z: refinement
                      // threshold; w: the aerial-perspective grid's far view depth (m)
    uvec4 epipolar;   // slices, samples per slice, initial step, tree leaves M (power of two)
    uvec4 lights;     // sun's light index, light buffer capacity, tree levels (0: no tree), 1:
                      // the frame has shadow maps
    uvec4 batch;      // brute force: steps per pixel, first step, steps in this dispatch;
                      // epipolar: y the samples' phase; w: 1, write the in-scattering
                      // alone (measurement); aerial perspective: x the air's first boundary
                      // in the froxel buffer (vec4 index), y 1 when the fog's grid is there
    uvec4 aerial;     // aerial perspective: columns x, rows, slices, steps per slice
} push;

#endif
