// Bindings of the light-shaft shaders (passes/scattering), shared by the GLSL and
// scattering_pass.cpp (valid in C++ and GLSL). Camera and lights: common/shared_bindings.h.
#ifndef CANDELA_SCATTERING_BINDINGS_H
#define CANDELA_SCATTERING_BINDINGS_H

#include "common/shared_bindings.h"

#define SCATTERING_BINDING_DEPTH 2
#define SCATTERING_BINDING_HDR 3
// Per epipolar slice: its end points on the screen and, per cascade, the line its plane cuts
// from the cascade's map (SliceInfo in scattering_march.glsl).
#define SCATTERING_BINDING_SLICES 4
// Per epipolar sample (x: sample, y: slice): pixel position, view distance, valid.
#define SCATTERING_BINDING_COORDINATES 5
// Per slice and cascade (row slice * 4 + cascade): the 1D min/max tree of blocker depths.
#define SCATTERING_BINDING_TREE 6
// Per epipolar sample: in-scattered radiance, view distance.
#define SCATTERING_BINDING_INSCATTER 11
// Rays marched and shadow tests taken (--stats scattering_samples).
#define SCATTERING_BINDING_COUNTERS 12
// The integrated froxel buffer (common/froxel_grid.glsl), whose air part the aerial
// perspective fills.
#define SCATTERING_BINDING_AERIAL_PERSPECTIVE 13
// Shadows (common/shadows.glsl, passes/shadows/shadow_pass.h).
#define SCATTERING_BINDING_SHADOW_ATLAS 7
#define SCATTERING_BINDING_SHADOW_VIEWS 8
#define SCATTERING_BINDING_SHADOW_LIGHTS 9
#define SCATTERING_BINDING_SHADOW_ATLAS_COMPARE 10

#endif
