// Bindings of the wire shaders (wire.vert, wire.frag), shared with wire_pass.cpp (valid in C++
// and GLSL). Camera and lights: common/shared_bindings.h.
#ifndef CANDELA_WIRE_BINDINGS_H
#define CANDELA_WIRE_BINDINGS_H

#include "common/shared_bindings.h"

// The frame's segments, world space (wire.vert; WireSegment in wire_pass.cpp).
#define WIRE_BINDING_SEGMENTS 2
#define WIRE_BINDING_CLUSTER_RANGES 3
#define WIRE_BINDING_LIGHT_INDICES 4
#define WIRE_BINDING_DEPTH_RANGE 5
#define WIRE_BINDING_PREFILTERED 6
#define WIRE_BINDING_BRDF_LUT 7
#define WIRE_BINDING_IRRADIANCE_SH 8
// Shadows (common/shadows.glsl, passes/shadows/shadow_pass.h).
#define WIRE_BINDING_SHADOW_ATLAS 9
#define WIRE_BINDING_SHADOW_VIEWS 10
#define WIRE_BINDING_SHADOW_LIGHTS 11
#define WIRE_BINDING_SHADOW_ATLAS_COMPARE 12
// The area lights' LTC table (lights/ltc_table_texture.h, common/area_lights.glsl).
#define WIRE_BINDING_LTC_MATRIX 13
#define WIRE_BINDING_LTC_MAGNITUDE 14
#define AREA_LIGHT_LTC_MATRIX_BINDING WIRE_BINDING_LTC_MATRIX
#define AREA_LIGHT_LTC_MAGNITUDE_BINDING WIRE_BINDING_LTC_MAGNITUDE
// The integrated froxel grid, its shape at its head (common/froxel_lookup.glsl;
// passes/volumetrics).
#define WIRE_BINDING_FROXEL_INTEGRATED 16

// wire.vert's modes (the push block's `mode`): Persson's clamp with coverage, or the naive
// line a pixel wide at full alpha that it replaces (for measurement).
#define WIRE_MODE_COVERAGE 0
#define WIRE_MODE_NAIVE 1

#endif
