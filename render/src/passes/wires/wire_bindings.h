// Bindings of the wire shaders (wire.vert, wire.frag), shared with wire_pass.cpp (valid in C++
// and GLSL). wire.frag also binds the lit inputs (common/lit_bindings.h).
#ifndef CANDELA_WIRE_BINDINGS_H
#define CANDELA_WIRE_BINDINGS_H

#include "common/lit_bindings.h"

// The frame's segments, world space (wire.vert; WireSegment in wire_pass.cpp).
#define WIRE_BINDING_SEGMENTS 2
// The integrated froxel grid, its shape at its head (common/froxel_lookup.glsl;
// passes/volumetrics).
#define WIRE_BINDING_FROXEL_INTEGRATED 16

// wire.vert's modes (the push block's `mode`): Persson's clamp with coverage, or the naive
// line a pixel wide at full alpha that it replaces (for measurement).
#define WIRE_MODE_COVERAGE 0
#define WIRE_MODE_NAIVE 1

#endif
