// Bindings and workgroup sizes of the atmosphere shaders, shared by them and
// atmosphere_pass.cpp (valid in C++ and GLSL).
#ifndef CANDELA_ATMOSPHERE_BINDINGS_H
#define CANDELA_ATMOSPHERE_BINDINGS_H

// The tables, sampled (bilinear, clamped) by the shaders after the one that writes them.
#define ATMOSPHERE_BINDING_TRANSMITTANCE 1
#define ATMOSPHERE_BINDING_MULTIPLE_SCATTERING 2
#define ATMOSPHERE_BINDING_SKY_VIEW 3
// What a shader writes: a table, or the sky cube's first mip (2D array of six faces).
#define ATMOSPHERE_BINDING_DESTINATION 4
// The background pass: the G-buffer depth (sampled) and the HDR target (storage).
#define ATMOSPHERE_BINDING_DEPTH 5
#define ATMOSPHERE_BINDING_HDR 6

#define ATMOSPHERE_GROUP_SIZE 8

#endif
