// Bindings of the transparency shaders (forward_transparent.frag, transparent_occupancy.frag,
// transparent_occupancy_merge.comp, msaa_expand.frag), shared by them and
// forward_transparent_pass.cpp (valid in C++ and GLSL). Camera and lights:
// common/shared_bindings.h.
#ifndef CANDELA_FORWARD_TRANSPARENT_BINDINGS_H
#define CANDELA_FORWARD_TRANSPARENT_BINDINGS_H

#include "common/shared_bindings.h"

// forward_transparent.frag. Materials: common/material.glsl, the array then one sampler per
// TextureSlot (FORWARD_BINDING_FIRST_TEXTURE up to FORWARD_BINDING_CLUSTER_RANGES).
#define FORWARD_BINDING_MATERIALS 2
#define FORWARD_BINDING_FIRST_TEXTURE 3
#define FORWARD_BINDING_CLUSTER_RANGES 16
#define FORWARD_BINDING_LIGHT_INDICES 17
#define FORWARD_BINDING_DEPTH_RANGE 18
#define FORWARD_BINDING_PREFILTERED 19
#define FORWARD_BINDING_BRDF_LUT 20
#define FORWARD_BINDING_IRRADIANCE_SH 21
// Shadows (common/shadows.glsl, passes/shadows/shadow_pass.h).
#define FORWARD_BINDING_SHADOW_ATLAS 22
#define FORWARD_BINDING_SHADOW_VIEWS 23
#define FORWARD_BINDING_SHADOW_LIGHTS 24
#define FORWARD_BINDING_SHADOW_ATLAS_COMPARE 25
// The area lights' LTC table (lights/ltc_table_texture.h, common/area_lights.glsl).
#define FORWARD_BINDING_LTC_MATRIX 26
#define FORWARD_BINDING_LTC_MAGNITUDE 27
#define AREA_LIGHT_LTC_MATRIX_BINDING FORWARD_BINDING_LTC_MATRIX
#define AREA_LIGHT_LTC_MAGNITUDE_BINDING FORWARD_BINDING_LTC_MAGNITUDE
// The sky occlusion atlas (common/sky_occlusion.glsl, passes/sky_occlusion). 28 was the froxel
// grid's shape, which now heads the integrated buffer: the pass is at lavapipe's 32.
#define FORWARD_BINDING_SKY_OCCLUSION 28
#define SKY_OCCLUSION_BINDING FORWARD_BINDING_SKY_OCCLUSION
// The integrated froxel grid, its shape at its head (common/froxel_lookup.glsl;
// passes/volumetrics).
#define FORWARD_BINDING_FROXEL_INTEGRATED 29
// Textured rect lights' image atlas (lights/area_light_textures.h); 30 is
// PREVIOUS_WORLDS_BINDING.
#define FORWARD_BINDING_AREA_LIGHT_TEXTURES 31
#define AREA_LIGHT_TEXTURE_BINDING FORWARD_BINDING_AREA_LIGHT_TEXTURES

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
