// Bindings of the transparency shaders (forward_transparent.frag, transparent_occupancy.frag,
// transparent_occupancy_merge.comp, msaa_expand.frag), shared by them and
// forward_transparent_pass.cpp (valid in C++ and GLSL). forward_transparent.frag also binds the
// lit inputs (common/lit_bindings.h): with its textures it is at lavapipe's 32 push descriptors.
#ifndef CANDELA_FORWARD_TRANSPARENT_BINDINGS_H
#define CANDELA_FORWARD_TRANSPARENT_BINDINGS_H

#include "common/lit_bindings.h"

// forward_transparent.frag. Materials: common/material.glsl, the array then one sampler per
// TextureSlot (FORWARD_BINDING_FIRST_TEXTURE up to FORWARD_BINDING_FROXEL_INTEGRATED).
#define FORWARD_BINDING_MATERIALS 2
#define FORWARD_BINDING_FIRST_TEXTURE 3
// The integrated froxel grid, its shape at its head (common/froxel_lookup.glsl;
// passes/volumetrics).
#define FORWARD_BINDING_FROXEL_INTEGRATED 29
// Textured rects and sky occlusion: compiled in (lit inputs the hair and wires leave out).
#define AREA_LIGHT_TEXTURE_BINDING LIT_BINDING_AREA_LIGHT_TEXTURES
#define SKY_OCCLUSION_BINDING LIT_BINDING_SKY_OCCLUSION

// transparent_occupancy.frag (camera in its vertex stage, gbuffer.vert).
#define TRANSPARENT_OCCUPANCY_BINDING_DEPTH 1
#define TRANSPARENT_OCCUPANCY_BINDING_DEPTH_RANGE 2
#define TRANSPARENT_OCCUPANCY_BINDING_BOUNDS 3

// transparent_occupancy_merge.comp.
#define MERGE_BINDING_TILE_MASKS 0
#define MERGE_BINDING_CLUSTER_BOUNDS 1
#define MERGE_BINDING_TRANSPARENT_BOUNDS 2

// msaa_expand.frag (forward MSAA: the single-sample targets copied into the multisampled ones).
#define MSAA_EXPAND_BINDING_HDR 0
#define MSAA_EXPAND_BINDING_MOTION 1
#define MSAA_EXPAND_BINDING_DEPTH 2

#endif
